#include "element/axisym2.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace vs {

// Plain sqrt instead of hypot: coordinates are O(1-1000) mm, far from over- and underflow.
double Axisym2Geometry::length() const {
  const double dr = rb - ra, dz = zb - za;
  return std::sqrt(dr * dr + dz * dz);
}

Mat6 axisym2_stress_stiffness(const Axisym2Geometry& g, double N_s, double N_t) {
  Mat6 k = Mat6::Zero();
  const double L = g.length();
  const double r = g.mid_radius();
  const double ks = N_s > 0.0 ? 2.0 * std::numbers::pi * r * N_s / L : 0.0;
  for (int c = 0; c < 2; ++c) {  // u and w: the meridian gradient (v_b - v_a) / L
    k(c, c) += ks;
    k(3 + c, 3 + c) += ks;
    k(c, 3 + c) -= ks;
    k(3 + c, c) -= ks;
  }
  if (N_t > 0.0 && r > 0.0) {  // the midpoint radial velocity (u_a + u_b) / 2 over r
    const double kt = 0.25 * 2.0 * std::numbers::pi * L * N_t / r;
    k(0, 0) += kt;
    k(3, 3) += kt;
    k(0, 3) += kt;
    k(3, 0) += kt;
  }
  return k;
}

Mat56 axisym2_B(const Axisym2Geometry& g) {
  const double l = g.length();
  const double c = (g.rb - g.ra) / l;
  const double s = (g.zb - g.za) / l;
  const double r = g.mid_radius();
  Mat56 B;
  // clang-format off
  B << -c / l,      -s / l,       0.0,          c / l,       s / l,       0.0,
       0.5 / r,     0.0,          0.0,          0.5 / r,     0.0,         0.0,
       0.0,         0.0,          1.0 / l,      0.0,         0.0,        -1.0 / l,
       0.0,         0.0,         -0.5 * c / r,  0.0,         0.0,        -0.5 * c / r,
       s / l,      -c / l,       -0.5,         -s / l,       c / l,      -0.5;
  // clang-format on
  return B;
}

Vec5 axisym2_strain_rates(const Axisym2Geometry& g, const Vec6& d) {
  const double il = 1.0 / g.length(), hr = 0.5 / g.mid_radius();
  const double c = (g.rb - g.ra) * il;
  const double s = (g.zb - g.za) * il;
  const double du = d(3) - d(0), dw = d(4) - d(1), bsum = d(2) + d(5);
  Vec5 e;
  e << (c * du + s * dw) * il, (d(0) + d(3)) * hr, (d(2) - d(5)) * il, -c * bsum * hr,
      (c * dw - s * du) * il - 0.5 * bsum;
  return e;
}

namespace {

// Symmetric 2x2 matrix (xx, xy, yy) and the quadratic form helpers of the element loop.
struct Sym2 {
  double xx = 0.0, xy = 0.0, yy = 0.0;
  void add(double w, const Sym2& o) {
    xx += w * o.xx;
    xy += w * o.xy;
    yy += w * o.yy;
  }
  // (this) * (a, b).
  double row0(double a, double b) const { return xx * a + xy * b; }
  double row1(double a, double b) const { return xy * a + yy * b; }
};

// The columns of B (see axisym2_evaluate).
struct Columns {
  const double *ms, *mt, *bs, *bt, *sh;
};
constexpr bool kRotation[6] = {false, false, true, false, false, true};

// K = W B^T D B with D = [[Dmm, Dmb, 0], [Dmb, Dbb, 0], [0, 0, Gs]]. A translation column j has
// only membrane entries m_j and a rotation column only bending entries b_j (plus shear), so
//   K_ij = W (m_i^T Dmm m_j, m_i^T Dmb b_j or b_i^T Dbb b_j  +  sh_i Gs sh_j)
// (Dmb is symmetric: an integral of symmetric point matrices).
void element_matrix(const Columns& B, const Sym2& Dmm, const Sym2& Dmb, const Sym2& Dbb, double Gs,
                    double W, Mat6* K) {
  constexpr int kT[4] = {0, 1, 3, 4};  // translation dofs
  constexpr int kR[2] = {2, 5};        // rotation dofs
  // Local copies (no aliasing with K): entries of the columns, and D times them.
  double mx[4], my[4], bx[2], by[2], sh[6];
  for (int j = 0; j < 6; ++j) sh[j] = B.sh[j];
  for (int a = 0; a < 4; ++a) {
    mx[a] = B.ms[kT[a]];
    my[a] = B.mt[kT[a]];
  }
  for (int a = 0; a < 2; ++a) {
    bx[a] = B.bs[kR[a]];
    by[a] = B.bt[kR[a]];
  }
  double mm0[4], mm1[4], bm0[2], bm1[2], bb0[2], bb1[2];  // Dmm m_j, Dmb b_j, Dbb b_j
  for (int a = 0; a < 4; ++a) {
    mm0[a] = Dmm.row0(mx[a], my[a]);
    mm1[a] = Dmm.row1(mx[a], my[a]);
  }
  for (int a = 0; a < 2; ++a) {
    bm0[a] = Dmb.row0(bx[a], by[a]);
    bm1[a] = Dmb.row1(bx[a], by[a]);
    bb0[a] = Dbb.row0(bx[a], by[a]);
    bb1[a] = Dbb.row1(bx[a], by[a]);
  }
  double k[6][6];
  for (int a = 0; a < 4; ++a) {
    const int i = kT[a];
    for (int b = a; b < 4; ++b) {
      const int j = kT[b];
      k[i][j] = k[j][i] = W * (mx[a] * mm0[b] + my[a] * mm1[b] + sh[i] * Gs * sh[j]);
    }
    for (int b = 0; b < 2; ++b) {
      const int j = kR[b];
      k[i][j] = k[j][i] = W * (mx[a] * bm0[b] + my[a] * bm1[b] + sh[i] * Gs * sh[j]);
    }
  }
  for (int a = 0; a < 2; ++a) {
    const int i = kR[a];
    for (int b = a; b < 2; ++b) {
      const int j = kR[b];
      k[i][j] = k[j][i] = W * (bx[a] * bb0[b] + by[a] * bb1[b] + sh[i] * Gs * sh[j]);
    }
  }
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) (*K)(i, j) = k[i][j];
  }
}

}  // namespace

void axisym2_evaluate(const Axisym2Geometry& g, const Axisym2Section& section,
                      const ThicknessRule& rule, const ViscousLaw& law, const Vec6& d,
                      StiffnessKind kind, Axisym2Output* out, double tangent_weight, bool split) {
  assert(section.sigma_y != nullptr && section.sigma_y->size() == rule.zeta.size());
  // The line search needs the potential at the tangent's point and at trial points.
  const bool want_potential = kind != StiffnessKind::kSecant;
  const bool want_k = kind != StiffnessKind::kNone;
  const bool tangent = kind == StiffnessKind::kTangent;
  const double l = g.length();
  const double r = g.mid_radius();
  const double il = 1.0 / l, hr = 0.5 / r;  // two divisions instead of ten
  const double c = (g.rb - g.ra) * il;
  const double s = (g.zb - g.za) * il;

  // The rows of axisym2_B over the dofs (ua wa ba ub wb bb): ms = eps_s, mt = eps_t, bs = kappa_s,
  // bt = kappa_t, sh = gamma. Translation columns have only membrane entries (ms, mt) and shear,
  // rotation columns only bending entries (bs, bt) and shear.
  const double cl = c * il, sl = s * il, ct = -c * hr;
  const double ms[6] = {-cl, -sl, 0.0, cl, sl, 0.0};
  const double mt[6] = {hr, 0.0, 0.0, hr, 0.0, 0.0};
  const double bs[6] = {0.0, 0.0, il, 0.0, 0.0, -il};
  const double bt[6] = {0.0, 0.0, ct, 0.0, 0.0, ct};
  const double sh[6] = {sl, -cl, -0.5, -sl, cl, -0.5};

  // Generalised strain rates e = B d.
  Vec5 e = Vec5::Zero();
  for (int j = 0; j < 6; ++j) {
    e(0) += ms[j] * d(j);
    e(1) += mt[j] * d(j);
    e(2) += bs[j] * d(j);
    e(3) += bt[j] * d(j);
    e(4) += sh[j] * d(j);
  }
  const double h = section.thickness_mm;
  const Eigen::Matrix2d& A = law.A();
  const Sym2 As{A(0, 0), A(0, 1), A(1, 1)};

  // Section integrals Dmm = int D, Dmb = int z D, Dbb = int z^2 D of the point matrices
  // D = mu A + tw c (A d)(A d)^T (or the primal-dual form, Axisym2Section::flow_direction). The
  // mu A part integrates to (int mu) A: only three scalars and the rank-one parts R (times 1, z,
  // z^2) are accumulated.
  double mu0 = 0.0, mu1 = 0.0, mu2 = 0.0;
  Sym2 R0, R1, R2;
  double N0 = 0.0, N1 = 0.0, M0 = 0.0, M1 = 0.0;
  double phi = 0.0;
  const std::size_t np = rule.zeta.size();
  const bool pressed = section.face_pressure.active();
  if (!want_k) out->point_rate.resize(np);
  if (tangent) {
    out->point_direction.resize(2 * np);
    out->point_cutoff_rate.resize(np);
  }
  for (std::size_t k = 0; k < np; ++k) {
    const double z = rule.zeta[k] * h;
    const double w = rule.weight[k] * h;
    const double d0 = e(0) + z * e(2), d1 = e(1) + z * e(3);
    const double Ad0 = As.row0(d0, d1), Ad1 = As.row1(d0, d1);
    const double rate2 = std::max((1.0 / 3.0) * (d0 * Ad0 + d1 * Ad1), 0.0);
    const double hv = section.hardening_viscosity ? (*section.hardening_viscosity)[k] : 0.0;
    const ViscousLaw::Scalars p = law.scalars((*section.sigma_y)[k], hv, rate2, want_potential);
    if (!want_k) out->point_rate[k] = std::sqrt(rate2);
    const double wmu = w * p.mu;
    N0 += wmu * Ad0;
    N1 += wmu * Ad1;
    M0 += (wmu * z) * Ad0;
    M1 += (wmu * z) * Ad1;
    phi += w * p.potential;
    if (pressed) {  // sigma_33 = -p(zeta): both in-plane stresses shift (normal_stress.h)
      const NormalStressTerm t = normal_stress_term(section.face_pressure.at(rule.zeta[k]), d0, d1);
      const double ws = w * t.stress_shift_MPa;
      N0 += ws;
      N1 += ws;
      M0 += ws * z;
      M1 += ws * z;
      phi += w * t.potential;
    }
    if (want_k) {
      mu0 += wmu;
      mu1 += wmu * z;
      mu2 += wmu * z * z;
      if (tangent) {
        // Flow direction (0 for a constant viscosity, which has no rank-one part).
        const double m = p.cutoff_rate > 0.0 ? 1.0 / (3.0 * p.cutoff_rate) : 0.0;
        out->point_direction[2 * k] = m * Ad0;
        out->point_direction[2 * k + 1] = m * Ad1;
        out->point_cutoff_rate[k] = p.cutoff_rate;
      }
      if (tangent && p.tangent_coef != 0.0) {
        const double t = p.tangent_coef;
        Sym2 Rk{t * Ad0 * Ad0, t * Ad0 * Ad1, t * Ad1 * Ad1};
        if (section.flow_direction) {
          // c (A d)(A d)^T = 3 eh c m (A d)^T with m replaced by the given n, symmetrised.
          const double n0 = section.flow_direction[2 * k], n1 = section.flow_direction[2 * k + 1];
          const double t3 = 3.0 * t * p.cutoff_rate;
          Rk = Sym2{t3 * n0 * Ad0, 0.5 * t3 * (n0 * Ad1 + n1 * Ad0), t3 * n1 * Ad1};
        }
        R0.add(w, Rk);
        R1.add(w * z, Rk);
        R2.add(w * z * z, Rk);
      }
    }
  }
  const double Gs = kShearCorrection * section.shear_viscosity * h;
  const double Q = Gs * e(4);
  phi += 0.5 * Gs * e(4) * e(4);

  const double W = 2.0 * std::numbers::pi * r * l;
  out->strain_rate = e;
  out->stress_resultant << N0, N1, M0, M1, Q;
  // f = W B^T S.
  for (int j = 0; j < 6; ++j) {
    const double fj = kRotation[j] ? bs[j] * M0 + bt[j] * M1 : ms[j] * N0 + mt[j] * N1;
    out->force(j) = W * (fj + sh[j] * Q);
  }
  out->potential = want_potential ? W * phi : 0.0;
  if (!want_k) return;

  // Secant part mu A with the shear penalty, and the weighted rank-one part: in one product, or
  // (split) in two.
  Sym2 Dmm, Dmb, Dbb;
  Dmm.add(mu0, As);
  Dmb.add(mu1, As);
  Dbb.add(mu2, As);
  const Columns B{ms, mt, bs, bt, sh};
  if (tangent && !split) {
    Dmm.add(tangent_weight, R0);
    Dmb.add(tangent_weight, R1);
    Dbb.add(tangent_weight, R2);
  }
  element_matrix(B, Dmm, Dmb, Dbb, Gs, W, &out->stiffness);
  if (!tangent || !split) return;
  element_matrix(B, R0, R1, R2, 0.0, W, &out->tangent_part);
  out->stiffness += tangent_weight * out->tangent_part;
}

}  // namespace vs
