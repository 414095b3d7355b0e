#include "element/shell9.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cassert>
#include <cmath>
#include <vector>

#include "element/quadrature.h"

namespace vs::shell3d {

Shell9Material Shell9Material::Elastic(double young, double poisson) {
  Shell9Material m;
  m.young = young;
  m.poisson = poisson;
  return m;
}

Shell9Material Shell9Material::Viscous(const HillPlaneStressLaw& law, double shear_viscosity) {
  Shell9Material m;
  m.viscous = true;
  m.law = &law;
  m.shear_viscosity = shear_viscosity;
  return m;
}

double Shell9Material::shear_reference() const {
  return viscous ? shear_viscosity : young / (2.0 * (1.0 + poisson));
}

int shell9_inplane_points(Shell9Rule rule) { return rule == Shell9Rule::kReduced ? 4 : 9; }

namespace {

// Gauss-Legendre rules of 2 and 3 points, built once (gauss_legendre allocates).
struct Gauss {
  std::array<double, 3> x{}, w{};
  int n = 0;
};
Gauss make_gauss(int n) {
  const Rule1D r = gauss_legendre(n);
  Gauss g;
  g.n = n;
  for (int i = 0; i < n; ++i) g.x[i] = r.x[i], g.w[i] = r.w[i];
  return g;
}
const Gauss& gauss(int n) {
  static const Gauss g2 = make_gauss(2), g3 = make_gauss(3);
  return n == 2 ? g2 : g3;
}

// shell9_stress_stiffness with the membrane tensor of in-plane point ip in the point's local frame
// (e1, e2) from local(ip, e1, e2).
template <class Local>
Eigen::Matrix<double, 9, 9> stress_stiffness(const Shell9Geometry& g, Shell9Rule rule,
                                             std::size_t points, const Local& local) {
  Eigen::Matrix<double, 9, 9> k = Eigen::Matrix<double, 9, 9>::Zero();
  const Gauss& q = gauss(rule == Shell9Rule::kReduced ? 2 : 3);
  assert(static_cast<int>(points) == q.n * q.n);
  static_cast<void>(points);
  int ip = 0;
  for (int j = 0; j < q.n; ++j) {
    for (int i = 0; i < q.n; ++i, ++ip) {
      const Shape9 sh = lagrange9(q.x[i], q.x[j]);
      Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
      for (int a = 0; a < 9; ++a) {
        gr += sh.dr(a) * g.x[a];
        gs += sh.ds(a) * g.x[a];
      }
      const Vec3 n = gr.cross(gs);
      const double area = n.norm();
      const Vec3 e1 = gr.normalized();
      const Vec3 e2 = (n / area).cross(e1);
      const Eigen::Matrix2d N = local(static_cast<std::size_t>(ip), e1, e2);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(N);
      const Eigen::Vector2d lam = eig.eigenvalues().cwiseMax(0.0);
      if (lam.maxCoeff() <= 0.0) continue;
      const Eigen::Matrix2d Np =
          eig.eigenvectors() * lam.asDiagonal() * eig.eigenvectors().transpose();
      Eigen::Matrix2d J;  // d(x1, x2)/d(r, s)
      J << gr.dot(e1), gs.dot(e1), gr.dot(e2), gs.dot(e2);
      Eigen::Matrix<double, 2, 9> G;  // rows: d/dr, d/ds
      G.row(0) = sh.dr.transpose();
      G.row(1) = sh.ds.transpose();
      G = J.transpose().inverse() * G;  // rows: d/dx1, d/dx2
      k += (area * q.w[i] * q.w[j]) * G.transpose() * Np * G;
    }
  }
  return k;
}

}  // namespace

Eigen::Matrix<double, 9, 9> shell9_stress_stiffness(const Shell9Geometry& g, Shell9Rule rule,
                                                    const std::vector<Vec3>& membrane) {
  return stress_stiffness(g, rule, membrane.size(), [&](std::size_t ip, const Vec3&, const Vec3&) {
    const Vec3& m = membrane[ip];
    Eigen::Matrix2d N;
    N << m(0), m(2), m(2), m(1);
    return N;
  });
}

Eigen::Matrix<double, 9, 9> shell9_stress_stiffness(const Shell9Geometry& g, Shell9Rule rule,
                                                    const std::vector<Mat3>& membrane) {
  return stress_stiffness(g, rule, membrane.size(),
                          [&](std::size_t ip, const Vec3& e1, const Vec3& e2) {
                            const Mat3& m = membrane[ip];
                            Eigen::Matrix2d N;
                            N << e1.dot(m * e1), e1.dot(m * e2), e2.dot(m * e1), e2.dot(m * e2);
                            return Eigen::Matrix2d(0.5 * (N + N.transpose()));
                          });
}

double shell9_area(const Shell9Geometry& g) {
  const Gauss& q = gauss(3);
  double area = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Shape9 sh = lagrange9(q.x[i], q.x[j]);
      Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
      for (int a = 0; a < 9; ++a) {
        gr += sh.dr(a) * g.x[a];
        gs += sh.ds(a) * g.x[a];
      }
      area += q.w[i] * q.w[j] * gr.cross(gs).norm();
    }
  return area;
}

namespace {

// ---- Covariant strain-rate operator as a polynomial in the thickness coordinate ----
//
// With c_a = h_a / 2 the point x(r, s, t) = sum N_a (x_a + t c_a V3_a) has
//   g_r(t) = gr0 + t gr1,  gr0 = sum N_a,r x_a,  gr1 = sum N_a,r c_a V3_a   (g_s alike),
//   g_t    = sum N_a c_a V3_a                                               (independent of t),
// and the velocity u = sum N_a (v_a + t c_a dV3_a). The rows of covariant_B
// (shell9_kinematics.h), [e_rr, e_ss, 2e_rs, 2e_rt, 2e_st], are products of these vectors with
// N_a, N_a,r, N_a,s and (director columns) one more factor t c_a, so B(t) = B0 + t B1 + t^2 B2:
//   velocity columns of node a (times the nodal velocity frame Q_a, if any):
//     B0: Nr gr0, Ns gs0, Ns gr0 + Nr gs0, Nr gt, Ns gt      B1: Nr gr1, Ns gs1, Ns gr1 + Nr gs1,
//     0, 0                                                    B2: 0
//   director-rate columns (times P_a):
//     B0: 0, 0, 0, c N gr0, c N gs0
//     B1: c Nr gr0, c Ns gs0, c (Ns gr0 + Nr gs0), c (N gr1 + Nr gt), c (N gs1 + Ns gt)
//     B2: c Nr gr1, c Ns gs1, c (Ns gr1 + Nr gs1), 0, 0
// (rows of the 5 x 3 blocks written as row vectors). The MITC9 assumed strains interpolate the
// tying values in (r, s) with weights independent of t, so they are quadratic in t as well: the
// tying points are evaluated once per element, not once per thickness point.
constexpr int kMaxDof = 54;
using BMat = Eigen::Matrix<double, 5, Eigen::Dynamic, Eigen::ColMajor, 5, kMaxDof>;
using VecD = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxDof, 1>;

struct SurfacePoint {
  Vec3 gr0, gr1, gs0, gs1, gt;
  double h = 0.0;
};

struct CovPoly {
  BMat B[3];
};

SurfacePoint surface_point(const Shell9Geometry& g, const Shape9& sh) {
  SurfacePoint p;
  p.gr0 = p.gr1 = p.gs0 = p.gs1 = p.gt = Vec3::Zero();
  for (int a = 0; a < 9; ++a) {
    const double c = 0.5 * g.thickness[a];
    const Vec3 cv = c * g.director[a];
    p.gr0 += sh.dr(a) * g.x[a];
    p.gs0 += sh.ds(a) * g.x[a];
    p.gr1 += sh.dr(a) * cv;
    p.gs1 += sh.ds(a) * cv;
    p.gt += sh.N(a) * cv;
    p.h += sh.N(a) * g.thickness[a];
  }
  return p;
}

void covariant_poly(const Shell9Geometry& g, const Shape9& sh, const SurfacePoint& p, int n,
                    CovPoly* out) {
  for (BMat& B : out->B) B.setZero(5, n);
  int off = 0;
  for (int a = 0; a < 9; ++a) {
    const double c = 0.5 * g.thickness[a];
    const double Nr = sh.dr(a), Ns = sh.ds(a), N = sh.N(a);
    // Velocity columns: g^T Q_a = (Q_a^T g)^T.
    Vec3 r0 = p.gr0, r1 = p.gr1, s0 = p.gs0, s1 = p.gs1, tt = p.gt;
    if (g.has_vel_frame) {
      const Mat3 Qt = g.vel_frame[a].transpose();
      r0 = Qt * p.gr0;
      r1 = Qt * p.gr1;
      s0 = Qt * p.gs0;
      s1 = Qt * p.gs1;
      tt = Qt * p.gt;
    }
    for (int k = 0; k < 3; ++k) {
      const int col = off + k;
      out->B[0](0, col) = Nr * r0(k);
      out->B[0](1, col) = Ns * s0(k);
      out->B[0](2, col) = Ns * r0(k) + Nr * s0(k);
      out->B[0](3, col) = Nr * tt(k);
      out->B[0](4, col) = Ns * tt(k);
      out->B[1](0, col) = Nr * r1(k);
      out->B[1](1, col) = Ns * s1(k);
      out->B[1](2, col) = Ns * r1(k) + Nr * s1(k);
    }
    // Director-rate columns: g^T P_a = (P_a^T g)^T.
    const int nr = g.n_rot[a];
    const Mat3& P = g.rot_map[a];
    for (int k = 0; k < nr; ++k) {
      const Vec3 pk = P.col(k);
      const double R0 = pk.dot(p.gr0), R1 = pk.dot(p.gr1), S0 = pk.dot(p.gs0), S1 = pk.dot(p.gs1),
                   Tt = pk.dot(p.gt);
      const int col = off + 3 + k;
      out->B[0](3, col) = c * N * R0;
      out->B[0](4, col) = c * N * S0;
      out->B[1](0, col) = c * Nr * R0;
      out->B[1](1, col) = c * Ns * S0;
      out->B[1](2, col) = c * (Ns * R0 + Nr * S0);
      out->B[1](3, col) = c * (N * R1 + Nr * Tt);
      out->B[1](4, col) = c * (N * S1 + Ns * Tt);
      out->B[2](0, col) = c * Nr * R1;
      out->B[2](1, col) = c * Ns * S1;
      out->B[2](2, col) = c * (Ns * R1 + Nr * S1);
    }
    off += 3 + nr;
  }
}

// MITC9 tying (mitc9.h): a = 1/sqrt(3), b = sqrt(3/5); linear basis through -a, a, quadratic
// through -b, 0, b.
struct Mitc9Points {
  double a = 1.0 / std::sqrt(3.0), b = std::sqrt(0.6);
  std::array<double, 2> lin(double x) const { return {0.5 * (1.0 - x / a), 0.5 * (1.0 + x / a)}; }
  std::array<double, 3> quad(double x) const {
    const double b2 = b * b;
    return {0.5 * x * (x - b) / b2, 1.0 - x * x / b2, 0.5 * x * (x + b) / b2};
  }
  double r_coord(int k) const { return (k / 3 == 0) ? -a : a; }
  double s_coord(int k) const { return (k % 3 - 1) * b; }
};

// The tying values the interpolation needs, per power of t: rows e_rr and 2e_rt of the 6 points
// (r_k, s_k) of their family, e_ss and 2e_st of the 6 points (s_k, r_k), 2e_rs of the 4 points
// (+-a, +-a); one sample per row of these matrices (column-major: a column holds one dof's
// samples, so each interpolated row is a product with the weight vector).
using Samples6 = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, kMaxDof>;
using Samples4 = Eigen::Matrix<double, 4, Eigen::Dynamic, Eigen::ColMajor, 4, kMaxDof>;
struct Mitc9Tying {
  Samples6 rr[3], rt[3], ss[3], st[3];
  Samples4 rs[3];
};

void mitc9_tying_poly(const Shell9Geometry& g, int n, CovPoly* scratch, Mitc9Tying* ty) {
  const Mitc9Points m;
  auto at = [&](double r, double s) {
    const Shape9 sh = lagrange9(r, s);
    covariant_poly(g, sh, surface_point(g, sh), n, scratch);
  };
  for (int p = 0; p < 3; ++p) {
    ty->rr[p].resize(6, n);
    ty->rt[p].resize(6, n);
    ty->ss[p].resize(6, n);
    ty->st[p].resize(6, n);
    ty->rs[p].resize(4, n);
  }
  for (int k = 0; k < 6; ++k) {
    at(m.r_coord(k), m.s_coord(k));
    for (int p = 0; p < 3; ++p) {
      ty->rr[p].row(k) = scratch->B[p].row(0);
      ty->rt[p].row(k) = scratch->B[p].row(3);
    }
    at(m.s_coord(k), m.r_coord(k));  // r and s exchanged
    for (int p = 0; p < 3; ++p) {
      ty->ss[p].row(k) = scratch->B[p].row(1);
      ty->st[p].row(k) = scratch->B[p].row(4);
    }
  }
  for (int k = 0; k < 4; ++k) {
    at((k % 2 == 0) ? -m.a : m.a, (k / 2 == 0) ? -m.a : m.a);
    for (int p = 0; p < 3; ++p) ty->rs[p].row(k) = scratch->B[p].row(2);
  }
}

void mitc9_assumed_poly(const Mitc9Tying& ty, double r, double s, int n, CovPoly* out) {
  const Mitc9Points m;
  const auto lr = m.lin(r), ls = m.lin(s);
  const auto qr = m.quad(r), qs = m.quad(s);
  Eigen::Matrix<double, 6, 1> wr, ws;
  Eigen::Vector4d wrs;
  for (int k = 0; k < 6; ++k) {
    wr(k) = lr[k / 3] * qs[k % 3];  // e_rr, 2e_rt family
    ws(k) = ls[k / 3] * qr[k % 3];  // e_ss, 2e_st family
  }
  for (int k = 0; k < 4; ++k) wrs(k) = lr[k % 2] * ls[k / 2];
  for (int p = 0; p < 3; ++p) {
    BMat& B = out->B[p];
    B.resize(5, n);
    B.row(0).noalias() = wr.transpose() * ty.rr[p];
    B.row(1).noalias() = ws.transpose() * ty.ss[p];
    B.row(2).noalias() = wrs.transpose() * ty.rs[p];
    B.row(3).noalias() = wr.transpose() * ty.rt[p];
    B.row(4).noalias() = ws.transpose() * ty.st[p];
  }
}

// Components (s11, s22, s12) of P S P^T for the plane tensor S = [[v0, v2], [v2, v1]] and the 2x2
// matrix P (row by row).
Vec3 projected(const Vec3& v, const std::array<double, 4>& P) {
  Eigen::Matrix2d p, s;
  p << P[0], P[1], P[2], P[3];
  s << v(0), v(2), v(2), v(1);
  const Eigen::Matrix2d m = p * s * p.transpose();
  return Vec3(m(0, 0), m(1, 1), 0.5 * (m(0, 1) + m(1, 0)));
}

// Point basis at thickness coordinate t of a surface point (as point_basis()).
struct Basis {
  double detJ;
  Mat3 frame;
  Mat5 T;  // local_transform(J^-1 frame)
};

Basis basis_at(const SurfacePoint& p, double t) {
  Basis b;
  Mat3 J;
  const Vec3 gr = p.gr0 + t * p.gr1, gs = p.gs0 + t * p.gs1;
  J.col(0) = gr;
  J.col(1) = gs;
  J.col(2) = p.gt;
  b.detJ = J.determinant();
  const Vec3 e3 = gr.cross(gs).normalized();
  const Vec3 e1 = gr.normalized();
  b.frame.col(0) = e1;
  b.frame.col(1) = e3.cross(e1);
  b.frame.col(2) = e3;
  b.T = local_transform(J.inverse() * b.frame);
  return b;
}

// Natural-coordinate increments (dr, ds) of a unit step along the initial RD at a point of the
// initial mid-surface: dX = G_r dr + G_s ds = RD0 in the least-squares sense (exact for RD0 in
// the tangent plane): (G^T G) c = G^T RD0 with G = [G_r, G_s].
Eigen::Vector2d rd_natural(const Shell9Geometry& g, const Shape9& sh) {
  Vec3 Gr = Vec3::Zero(), Gs = Vec3::Zero();
  for (int a = 0; a < 9; ++a) {
    Gr += sh.dr(a) * g.x_initial[static_cast<std::size_t>(a)];
    Gs += sh.ds(a) * g.x_initial[static_cast<std::size_t>(a)];
  }
  Eigen::Matrix2d M;
  M << Gr.dot(Gr), Gr.dot(Gs), Gr.dot(Gs), Gs.dot(Gs);
  return M.inverse() * Eigen::Vector2d(Gr.dot(g.rd_initial), Gs.dot(g.rd_initial));
}

// The quadratic form of the point law at a flow point, in the form of hill_plane_stress.h:
// e^2 = d . a / 3 with a = 3 g (g = d(e^2/2)/dd), stress mu a, secant mu M with M = 3 dg/dd.
// Normal anisotropy: a = A d, M = A. Planar Hill 1948: the same with the rotated A
// (planar_anisotropy.h). Yld2000-2d: g = T^T e m(T d), M = 3 T^T H T from the local solve
// (dual_potential.h), T the point's rate rotation (plane_stress_axes.h).
struct PointForm {
  Vec3 a;
  Mat3 M;
  double e_squared;
};

PointForm point_form(const Shell9Material& mat, const Shell9State& st,
                     const Shell9Operators::FlowRow& fr, int flow_index, const Vec3& d) {
  PointForm f;
  if (mat.planar == nullptr) {
    f.M = mat.law->A();
  } else {
    const MaterialAxes axes(fr.rd_cos, fr.rd_sin);
    const PlaneMatrix& T = axes.rate_rotation();
    if (mat.planar->quadratic) {
      f.M = T.transpose() * mat.planar->A * T;
    } else {
      PlaneVector* guess = st.flow_guess ? st.flow_guess + flow_index : nullptr;
      const bool warm = guess != nullptr && !guess->isZero();
      const DualPoint dual = mat.planar->yield->dual(T * d, warm ? guess : nullptr);
      if (guess != nullptr && dual.rate > 0.0) *guess = dual.direction;
      f.a = T.transpose() * ((3.0 * dual.rate) * dual.direction);
      f.M = 3.0 * (T.transpose() * dual.hessian * T);
      f.e_squared = dual.rate * dual.rate;
      return f;
    }
  }
  f.a = f.M * d;
  f.e_squared = std::max(d.dot(f.a) / 3.0, 0.0);
  return f;
}

}  // namespace

double shell9_dual_norm_squared(const Shell9Material& mat, const Shell9Operators::FlowRow& fr,
                                const Vec3& n) {
  if (mat.planar == nullptr) return mat.law->dual_norm_squared(n);
  const MaterialAxes axes(fr.rd_cos, fr.rd_sin);
  const PlaneVector nm = axes.stress_to_material(n);
  if (mat.planar->quadratic) return nm.dot(mat.planar->P * nm);
  const double sb = mat.planar->yield->effective_stress(nm);
  return sb * sb;
}

namespace {

struct PointLaw {
  Vec3 stress;
  Mat3 D;
  double potential;
  double rate;
};

PointLaw evaluate_point(const Shell9Material& mat, const Shell9State& st,
                        const Shell9Operators::FlowRow& fr, int flow_index, const Vec3& d,
                        Shell9Stiffness kind, double tangent_weight) {
  PointLaw p;
  if (!mat.viscous) {
    const double nu = mat.poisson, f = mat.young / (1.0 - nu * nu);
    p.D << f, f * nu, 0.0, f * nu, f, 0.0, 0.0, 0.0, 0.5 * f * (1.0 - nu);
    p.stress = p.D * d;
    p.potential = 0.5 * d.dot(p.stress);
    p.rate = 0.0;
    return p;
  }
  const double sy = st.sigma_y ? st.sigma_y[flow_index] : 0.0;
  const double hv = st.hardening_viscosity ? st.hardening_viscosity[flow_index] : 0.0;
  const HillPlaneStressLaw& law = *mat.law;
  // A and Ad of the normal-anisotropy law, or their per-point forms (point_form).
  const PointForm form = point_form(mat, st, fr, flow_index, d);
  const Mat3& A = form.M;
  const Vec3& Ad = form.a;
  const InPlanePoint ip = law.evaluate_scaled(sy, hv, Ad, form.e_squared);
  p.stress = ip.stress;
  p.potential = ip.potential;
  p.rate = ip.rate;
  if (kind == Shell9Stiffness::kNone) return p;
  p.D = ip.mu * A;
  if (kind != Shell9Stiffness::kTangent) return p;
  if (st.dual_record) {
    // Primal-dual tangent (shell9.h, Shell9FlowDirection).
    Shell9FlowDirection& rec = st.dual_record[flow_index];
    rec.d = d;
    rec.eh = ip.cutoff_rate;
    rec.m = ip.cutoff_rate > 0.0 ? Vec3(Ad / (3.0 * ip.cutoff_rate)) : Vec3::Zero();
    Vec3 n = Vec3::Zero(), n_full = Vec3::Zero();
    if (st.dual_given) {
      n = n_full = st.dual_given[flow_index];
    } else if (st.dual_anchor && st.dual_anchor[flow_index].eh > 0.0) {
      const Shell9FlowDirection& a = st.dual_anchor[flow_index];
      const Vec3 dd = d - a.d;
      n = n_full = a.m + (A * dd / 3.0 - a.n * a.m.dot(dd)) / a.eh;
      const double norm2 = shell9_dual_norm_squared(mat, fr, n);
      if (norm2 > 1.0) n /= std::sqrt(norm2);
    }
    if (mat.planar != nullptr && !mat.planar->quadratic) {
      // Yld2000-2d: D(n) is positive semi-definite for n in the ellipsoid 3 n^T M^-1 n <= 1 of
      // the point's own M, not for the whole unit ball sigma_bar(n) <= 1 (shell9.h).
      const double ellipsoid2 = 3.0 * n.dot(A.llt().solve(n));
      if (ellipsoid2 > 1.0) n /= std::sqrt(ellipsoid2);
    }
    rec.n = n;
    rec.n_full = n_full;
    if (ip.tangent_coef != 0.0) {
      const Vec3 nAd = (1.5 * tangent_weight * ip.tangent_coef * ip.cutoff_rate) * n;
      p.D += nAd * Ad.transpose() + Ad * nAd.transpose();
    }
    return p;
  }
  if (ip.tangent_coef != 0.0) p.D += (tangent_weight * ip.tangent_coef) * Ad * Ad.transpose();
  return p;
}

// Per-thread scratch: the kernels allocate nothing after the first element of a given size.
struct Workspace {
  Mitc9Tying tying;
  CovPoly assumed;
  Eigen::MatrixXd DL;         // (dV D_p) B_p, one row per row of L
  Eigen::VectorXd rate, gen;  // L q and the row forces (dV times stresses)
  Eigen::VectorXd Sq;         // the shear Gram matrix times q
  Eigen::MatrixXd shear;      // sqrt(dV) B_s, 2 rows per shear point (shell9_operators)
  Shell9Operators ops;        // shell9_evaluate(g, ...)
};

Workspace& workspace() {
  thread_local Workspace ws;
  return ws;
}

}  // namespace

void shell9_operators(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                      Shell9Operators* ops) {
  Workspace& ws = workspace();
  const int n = g.ndof();
  assert(n <= kMaxDof);
  const Gauss& mr = gauss(rule == Shell9Rule::kReduced ? 2 : 3);
  const bool separate_shear = rule == Shell9Rule::kSelective;
  const bool mitc = rule == Shell9Rule::kMitc9;
  const int nt = static_cast<int>(thick.zeta.size());
  const int nip = mr.n * mr.n;
  const Gauss& sr = gauss(separate_shear ? 2 : mr.n);
  ops->ndof = n;
  ops->inplane_points = nip;
  // L: 3 in-plane rows per flow point. The shear rows (2 per shear point and thickness point)
  // are scaled by sqrt(dV) into ws.shear and summed into S = sum dV B_s^T B_s at the end.
  ops->L.resize(3 * nip * nt, n);
  ws.shear.resize(2 * sr.n * sr.n * nt, n);
  ops->flow.clear();
  ops->frame.assign(static_cast<std::size_t>(nip), Mat3::Identity());
  ops->shape.resize(static_cast<std::size_t>(nip));
  int rows = 0, shear_rows = 0;
  auto add_shear = [&](const auto& Bs, double dV) {
    assert(dV > 0.0);
    ws.shear.middleRows(shear_rows, 2) = std::sqrt(dV) * Bs;
    shear_rows += 2;
  };
  if (mitc) mitc9_tying_poly(g, n, &ws.assumed, &ws.tying);
  int ip = 0;
  for (int j = 0; j < mr.n; ++j) {
    for (int i = 0; i < mr.n; ++i, ++ip) {
      const double r = mr.x[i], s = mr.x[j];
      const Shape9 sh = lagrange9(r, s);
      for (int a = 0; a < 9; ++a)
        ops->shape[static_cast<std::size_t>(ip)][static_cast<std::size_t>(a)] = sh.N(a);
      const SurfacePoint sp = surface_point(g, sh);
      const Eigen::Vector2d rd_nat =
          g.has_material_axes ? rd_natural(g, sh) : Eigen::Vector2d::UnitX();
      if (mitc) {
        mitc9_assumed_poly(ws.tying, r, s, n, &ws.assumed);
      } else {
        covariant_poly(g, sh, sp, n, &ws.assumed);
      }
      const CovPoly& A = ws.assumed;
      const Mat3 mid = basis_at(sp, 0.0).frame;  // of the resultants
      ops->frame[static_cast<std::size_t>(ip)] = mid;
      for (int k = 0; k < nt; ++k) {
        const double t = 2.0 * thick.zeta[static_cast<std::size_t>(k)];
        const double wt = 2.0 * thick.weight[static_cast<std::size_t>(k)];
        const Basis b = basis_at(sp, t);
        const BMat Bcov = A.B[0] + t * A.B[1] + (t * t) * A.B[2];
        const BMat Bl = b.T * Bcov;
        const double dV = b.detJ * mr.w[i] * mr.w[j] * wt;
        // Resultants per unit length: dz = h/2 dt, z = t h/2 (weights of [-1, 1] halved).
        const double dz = 0.5 * sp.h * wt;
        ops->L.middleRows(rows, 3) = Bl.topRows<3>();
        ops->flow.push_back({rows, ip, dV, dz, dz * 0.5 * t * sp.h, 0.5 * t});
        if (g.has_material_axes) {
          // The convected RD at this point (Shell9Geometry::rd_initial) in its local frame.
          const Vec3 rd = rd_nat(0) * (sp.gr0 + t * sp.gr1) + rd_nat(1) * (sp.gs0 + t * sp.gs1);
          const double c = rd.dot(b.frame.col(0)), sn = rd.dot(b.frame.col(1));
          const double len = std::hypot(c, sn);
          ops->flow.back().rd_cos = c / len;
          ops->flow.back().rd_sin = sn / len;
        }
        if (t != 0.0) {
          Shell9Operators::FlowRow& f = ops->flow.back();
          f.turned = true;
          for (int u = 0; u < 2; ++u)
            for (int w = 0; w < 2; ++w)
              f.to_mid[static_cast<std::size_t>(2 * u + w)] = mid.col(u).dot(b.frame.col(w));
        }
        rows += 3;
        if (!separate_shear) add_shear(Bl.bottomRows<2>(), dV);
      }
    }
  }
  if (separate_shear) {
    for (int j = 0; j < sr.n; ++j) {
      for (int i = 0; i < sr.n; ++i) {
        const Shape9 sh = lagrange9(sr.x[i], sr.x[j]);
        const SurfacePoint sp = surface_point(g, sh);
        covariant_poly(g, sh, sp, n, &ws.assumed);
        const CovPoly& A = ws.assumed;
        for (int k = 0; k < nt; ++k) {
          const double t = 2.0 * thick.zeta[static_cast<std::size_t>(k)];
          const double wt = 2.0 * thick.weight[static_cast<std::size_t>(k)];
          const Basis b = basis_at(sp, t);
          const BMat Bcov = A.B[0] + t * A.B[1] + (t * t) * A.B[2];
          const Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxDof> Bs =
              b.T.bottomRows<2>() * Bcov;
          add_shear(Bs, b.detJ * sr.w[i] * sr.w[j] * wt);
        }
      }
    }
  }
  assert(rows == ops->L.rows() && shear_rows == ws.shear.rows());
  ops->shear_gram.setZero(n, n);
  ops->shear_gram.selfadjointView<Eigen::Lower>().rankUpdate(ws.shear.transpose());
  ops->shear_gram.triangularView<Eigen::StrictlyUpper>() = ops->shear_gram.transpose();
  // Drilling: 1/2 k (V3 . omega)^2 at 6-dof nodes (section 6.3: a small artificial in-plane
  // rotational stiffness); numerics.md 4.2 suggests 1e-3..1e-4 mu h A_e.
  ops->drill.clear();
  bool any_drill = false;
  for (int a = 0; a < 9; ++a) any_drill = any_drill || g.n_rot[a] == 3;
  if (any_drill) {
    const double area = shell9_area(g);
    for (int a = 0; a < 9; ++a) {
      if (g.n_rot[a] != 3) continue;
      ops->drill.push_back({g.offset(a) + 3, g.director[a], g.thickness[a] * area / 9.0});
    }
  }
}

void shell9_substitute_velocity(int velocity, int rotation, const Eigen::Matrix<double, 3, 2>& C,
                                Shell9Operators* ops) {
  ops->L.middleCols<2>(rotation) -= ops->L.middleCols<3>(velocity) * C;
  Eigen::MatrixXd& S = ops->shear_gram;  // T^T S T: the columns, then the rows
  S.middleCols<2>(rotation) -= S.middleCols<3>(velocity) * C;
  S.middleRows<2>(rotation) -= C.transpose() * S.middleRows<3>(velocity);
}

void shell9_evaluate(const Shell9Operators& ops, const Shell9Material& mat,
                     const Shell9State& state, const Eigen::VectorXd& q, Shell9Stiffness kind,
                     Shell9Output* out, double tangent_weight, const Shell9Operators* next) {
  Workspace& ws = workspace();
  const int n = ops.ndof;
  assert(q.size() == n);
  const bool want_k = kind != Shell9Stiffness::kNone;
  const auto R = ops.L.rows();
  out->point_rate.assign(ops.flow.size(), 0.0);
  out->resultant.assign(static_cast<std::size_t>(ops.inplane_points), Shell9Resultant{});
  out->potential = 0.0;
  ws.rate.noalias() = ops.L * q;
  ws.gen.resize(R);
  if (want_k) ws.DL.resize(R, n);
  // The next element's L and S, one slice of cache lines per flow point (shell9.h).
  const Eigen::MatrixXd* ahead[2] = {next != nullptr ? &next->L : nullptr,
                                     next != nullptr ? &next->shear_gram : nullptr};
  std::size_t lines[2] = {0, 0};
  for (int m = 0; m < 2; ++m)
    if (ahead[m] != nullptr)
      lines[m] = (static_cast<std::size_t>(ahead[m]->size()) * sizeof(double) + 63) / 64;
  const std::size_t total_lines = lines[0] + lines[1];
  const std::size_t per_point =
      ops.flow.empty() ? 0 : (total_lines + ops.flow.size() - 1) / ops.flow.size();
  std::size_t line = 0;
  for (std::size_t f = 0; f < ops.flow.size(); ++f) {
    for (std::size_t k = 0; k < per_point && line < total_lines; ++k, ++line) {
      const int m = line < lines[0] ? 0 : 1;
      const std::size_t l = m == 0 ? line : line - lines[0];
      __builtin_prefetch(reinterpret_cast<const char*>(ahead[m]->data()) + 64 * l, 0, 2);
    }
    const Shell9Operators::FlowRow& fr = ops.flow[f];
    const Vec3 d = ws.rate.segment<3>(fr.row);
    PointLaw p = evaluate_point(mat, state, fr, static_cast<int>(f), d, kind, tangent_weight);
    if (state.face_pressure) {  // sigma_33 = -p(zeta): the normal stresses shift (normal_stress.h)
      const NormalStressTerm t =
          normal_stress_term(state.face_pressure[fr.point].at(fr.zeta), d(0), d(1));
      p.stress(0) += t.stress_shift_MPa;
      p.stress(1) += t.stress_shift_MPa;
      p.potential += t.potential;
    }
    out->point_rate[f] = p.rate;
    ws.gen.segment<3>(fr.row) = fr.dV * p.stress;
    if (want_k) ws.DL.middleRows(fr.row, 3).noalias() = (fr.dV * p.D) * ops.L.middleRows(fr.row, 3);
    out->potential += p.potential * fr.dV;
    Shell9Resultant& res = out->resultant[static_cast<std::size_t>(fr.point)];
    const Vec3 sm = fr.turned ? projected(p.stress, fr.to_mid) : p.stress;
    res.N += fr.dz * sm;
    res.M += fr.arm * sm;
  }
  for (int ip = 0; ip < ops.inplane_points; ++ip) {
    out->resultant[static_cast<std::size_t>(ip)].frame = ops.frame[static_cast<std::size_t>(ip)];
  }
  // Transverse shear (Shell9Operators): force Gs S q, power Gs q^T S q / 2, matrix Gs S, with Gs
  // the penalty viscosity (elastic: k G).
  const double Gs = mat.shear_correction * mat.shear_reference();
  out->force.noalias() = ops.L.transpose() * ws.gen;
  ws.Sq.noalias() = ops.shear_gram * q;
  out->force += Gs * ws.Sq;
  out->potential += 0.5 * Gs * q.dot(ws.Sq);
  if (want_k) {
    // K = Gs S + sum_p B_p^T (dV D_p) B_p over the rows of all flow points, as one product of
    // the stacked operators: the lower triangle by one triangular product (Eigen's blocked
    // kernel), then mirrored.
    out->stiffness.noalias() = Gs * ops.shear_gram;
    out->stiffness.triangularView<Eigen::Lower>() += ops.L.transpose() * ws.DL;
    out->stiffness.triangularView<Eigen::StrictlyUpper>() = out->stiffness.transpose();
  }
  for (const Shell9Operators::DrillNode& dn : ops.drill) {
    const double kd = mat.drill_scale * mat.shear_reference() * dn.thickness_area;
    const double w = dn.director.dot(q.segment<3>(dn.offset));
    out->force.segment<3>(dn.offset) += kd * w * dn.director;
    if (want_k)
      out->stiffness.block<3, 3>(dn.offset, dn.offset) +=
          kd * dn.director * dn.director.transpose();
    out->potential += 0.5 * kd * w * w;
  }
}

void shell9_evaluate(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                     const Shell9Material& mat, const Shell9State& state, const Eigen::VectorXd& q,
                     Shell9Stiffness kind, Shell9Output* out, double tangent_weight) {
  Shell9Operators& ops = workspace().ops;
  shell9_operators(g, rule, thick, &ops);
  shell9_evaluate(ops, mat, state, q, kind, out, tangent_weight);
}

}  // namespace vs::shell3d
