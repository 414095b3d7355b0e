#include "shell3d/shell9.h"

#include <Eigen/Geometry>
#include <cassert>
#include <optional>

#include "shell3d/mitc9.h"
#include "shell3d/quadrature.h"

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

double shell9_area(const Shell9Geometry& g) {
  const Rule1D q = gauss_legendre(3);
  double area = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
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

struct PointLaw {
  Vec3 stress;
  Mat3 D;
  double potential;
  double rate;
};

PointLaw evaluate_point(const Shell9Material& mat, const Shell9State& st, int flow_index,
                        const Vec3& d, Shell9Stiffness kind, double tangent_weight) {
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
  const InPlanePoint ip = mat.law->evaluate(sy, hv, d);
  p.stress = ip.stress;
  p.potential = ip.potential;
  p.rate = ip.rate;
  p.D = ip.mu * mat.law->A();
  if (kind == Shell9Stiffness::kTangent && ip.tangent_coef != 0.0) {
    const Vec3 Ad = mat.law->A() * d;
    p.D += (tangent_weight * ip.tangent_coef) * Ad * Ad.transpose();
  }
  return p;
}

// Local engineering strain-rate operator [eps11, eps22, gam12, gam13, gam23] at (r, s, t).
Eigen::Matrix<double, 5, Eigen::Dynamic> local_B(const Shell9Geometry& g, double r, double s,
                                                 double t, const Mitc9TyingB* tying,
                                                 PointBasis* pb) {
  const Shape9 sh = lagrange9(r, s);
  *pb = point_basis(g, sh, t);
  const Mat5X Bcov = tying ? mitc9_assumed_B(*tying, r, s) : covariant_B(g, sh, *pb, t);
  return local_transform(pb->C) * Bcov;
}

}  // namespace

void shell9_evaluate(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                     const Shell9Material& mat, const Shell9State& state, const Eigen::VectorXd& q,
                     Shell9Stiffness kind, Shell9Output* out, double tangent_weight) {
  const int n = g.ndof();
  assert(q.size() == n);
  const bool want_k = kind != Shell9Stiffness::kNone;
  out->force = Eigen::VectorXd::Zero(n);
  if (want_k) out->stiffness = Eigen::MatrixXd::Zero(n, n);
  out->potential = 0.0;

  const Rule1D mr = gauss_legendre(rule == Shell9Rule::kReduced ? 2 : 3);
  const bool separate_shear = rule == Shell9Rule::kSelective;
  const int nt = static_cast<int>(thick.zeta.size());
  const int nip = static_cast<int>(mr.x.size() * mr.x.size());
  out->point_rate.assign(static_cast<std::size_t>(nip * nt), 0.0);
  out->resultant.assign(static_cast<std::size_t>(nip), Shell9Resultant{});
  const Rule1D sr = gauss_legendre(separate_shear ? 2 : static_cast<int>(mr.x.size()));
  out->shear_force.assign(sr.x.size() * sr.x.size(), Eigen::Vector2d::Zero());
  const double Gs = mat.shear_correction * mat.shear_reference();

  // Transverse shear at one point: Q = Gs gamma (penalty viscosity / elastic k G).
  auto add_shear = [&](const Eigen::Matrix<double, 2, Eigen::Dynamic>& Bs, double dV,
                       double h_weight, int sp) {
    const Eigen::Vector2d gam = Bs * q;
    out->force.noalias() += (Gs * dV) * (Bs.transpose() * gam);
    // The matrix is symmetric: only its lower triangle is accumulated (lazyProduct evaluates just
    // those coefficients; the blocked GEMM kernel costs more than it saves for thin factors), the
    // upper one is copied at the end.
    if (want_k) {
      out->stiffness.triangularView<Eigen::Lower>() += Bs.transpose().lazyProduct((Gs * dV) * Bs);
    }
    out->potential += 0.5 * Gs * gam.squaredNorm() * dV;
    out->shear_force[static_cast<std::size_t>(sp)] += (Gs * h_weight) * gam;
  };

  for (int k = 0; k < nt; ++k) {
    const double t = 2.0 * thick.zeta[static_cast<std::size_t>(k)];
    const double wt = 2.0 * thick.weight[static_cast<std::size_t>(k)];
    std::optional<Mitc9TyingB> tying;
    if (rule == Shell9Rule::kMitc9) tying = mitc9_tying(g, t);
    int ip = 0;
    for (std::size_t j = 0; j < mr.x.size(); ++j) {
      for (std::size_t i = 0; i < mr.x.size(); ++i, ++ip) {
        PointBasis pb;
        const auto Bl = local_B(g, mr.x[i], mr.x[j], t, tying ? &*tying : nullptr, &pb);
        const double dV = pb.detJ * mr.w[i] * mr.w[j] * wt;
        const Eigen::Matrix<double, 3, Eigen::Dynamic> Bm = Bl.topRows<3>();
        const Vec3 d = Bm * q;
        const int flow = ip * nt + k;
        const PointLaw p = evaluate_point(mat, state, flow, d, kind, tangent_weight);
        out->point_rate[static_cast<std::size_t>(flow)] = p.rate;
        out->force.noalias() += dV * (Bm.transpose() * p.stress);
        if (want_k) {
          const Eigen::Matrix<double, 3, Eigen::Dynamic> DB = (dV * p.D) * Bm;
          out->stiffness.triangularView<Eigen::Lower>() += Bm.transpose().lazyProduct(DB);
        }
        out->potential += p.potential * dV;
        // Resultants per unit length: dz = h/2 dt, z = t h/2 (weights of [-1, 1] halved).
        Shell9Resultant& R = out->resultant[static_cast<std::size_t>(ip)];
        const double dz = 0.5 * pb.h * wt;
        R.N += dz * p.stress;
        R.M += (dz * 0.5 * t * pb.h) * p.stress;
        if (k == nt / 2) R.frame = pb.frame;  // the middle thickness point (or nearest above)
        if (!separate_shear) add_shear(Bl.bottomRows<2>(), dV, 0.5 * pb.h * wt, ip);
      }
    }
    if (separate_shear) {
      int sp = 0;
      for (std::size_t j = 0; j < sr.x.size(); ++j) {
        for (std::size_t i = 0; i < sr.x.size(); ++i, ++sp) {
          PointBasis pb;
          const auto Bl = local_B(g, sr.x[i], sr.x[j], t, nullptr, &pb);
          add_shear(Bl.bottomRows<2>(), pb.detJ * sr.w[i] * sr.w[j] * wt, 0.5 * pb.h * wt, sp);
        }
      }
    }
  }

  if (want_k) {
    out->stiffness.triangularView<Eigen::StrictlyUpper>() = out->stiffness.transpose();
  }

  // Drilling: 1/2 k (V3 . omega)^2 at 6-dof nodes (section 6.3: a small artificial in-plane
  // rotational stiffness); numerics.md 4.2 suggests 1e-3..1e-4 mu h A_e.
  bool any_drill = false;
  for (int a = 0; a < 9; ++a) any_drill = any_drill || g.n_rot[a] == 3;
  if (any_drill) {
    const double area = shell9_area(g);
    for (int a = 0; a < 9; ++a) {
      if (g.n_rot[a] != 3) continue;
      const double kd = mat.drill_scale * mat.shear_reference() * g.thickness[a] * area / 9.0;
      const int o = g.offset(a) + 3;
      const Vec3& v3 = g.director[a];
      const double w = v3.dot(q.segment<3>(o));
      out->force.segment<3>(o) += kd * w * v3;
      if (want_k) out->stiffness.block<3, 3>(o, o) += kd * v3 * v3.transpose();
      out->potential += 0.5 * kd * w * w;
    }
  }
}

}  // namespace vs::shell3d
