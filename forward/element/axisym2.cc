#include "element/axisym2.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace vs {

double Axisym2Geometry::length() const { return std::hypot(rb - ra, zb - za); }

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

void axisym2_evaluate(const Axisym2Geometry& g, const Axisym2Section& section,
                      const ThicknessRule& rule, const ViscousLaw& law, const Vec6& d,
                      StiffnessKind kind, Axisym2Output* out, double tangent_weight) {
  assert(section.sigma_y != nullptr && section.sigma_y->size() == rule.zeta.size());
  const bool want_potential = kind == StiffnessKind::kNone;
  const Mat56 B = axisym2_B(g);
  const Vec5 e = B * d;
  const double h = section.thickness_mm;
  const Eigen::Matrix2d& A = law.A();

  Eigen::Matrix2d Dmm = Eigen::Matrix2d::Zero(), Dmb = Eigen::Matrix2d::Zero(),
                  Dbb = Eigen::Matrix2d::Zero();
  Eigen::Vector2d N = Eigen::Vector2d::Zero(), M = Eigen::Vector2d::Zero();
  double phi = 0.0;
  const std::size_t np = rule.zeta.size();
  out->point_rate.resize(np);
  for (std::size_t k = 0; k < np; ++k) {
    const double z = rule.zeta[k] * h;
    const double w = rule.weight[k] * h;
    const Eigen::Vector2d dk(e(0) + z * e(2), e(1) + z * e(3));
    const double hv = section.hardening_viscosity ? (*section.hardening_viscosity)[k] : 0.0;
    const ViscousLaw::Point p = law.evaluate((*section.sigma_y)[k], hv, dk, want_potential);
    out->point_rate[k] = p.rate;
    N += w * p.stress;
    M += (w * z) * p.stress;
    phi += w * p.potential;
    if (kind != StiffnessKind::kNone) {
      Eigen::Matrix2d Dk = p.mu * A;
      if (kind == StiffnessKind::kTangent && p.tangent_coef != 0.0) {
        const Eigen::Vector2d Ad = A * dk;
        Dk += (tangent_weight * p.tangent_coef) * Ad * Ad.transpose();
      }
      Dmm += w * Dk;
      Dmb += (w * z) * Dk;
      Dbb += (w * z * z) * Dk;
    }
  }
  const double Gs = kShearCorrection * section.shear_viscosity * h;
  const double Q = Gs * e(4);
  phi += 0.5 * Gs * e(4) * e(4);

  const double W = 2.0 * std::numbers::pi * g.mid_radius() * g.length();
  Vec5 S;
  S << N(0), N(1), M(0), M(1), Q;
  out->strain_rate = e;
  out->stress_resultant = S;
  out->force = W * (B.transpose() * S);
  out->potential = W * phi;
  if (kind != StiffnessKind::kNone) {
    Eigen::Matrix<double, 5, 5> D = Eigen::Matrix<double, 5, 5>::Zero();
    D.block<2, 2>(0, 0) = Dmm;
    D.block<2, 2>(0, 2) = Dmb;
    D.block<2, 2>(2, 0) = Dmb.transpose();
    D.block<2, 2>(2, 2) = Dbb;
    D(4, 4) = Gs;
    out->stiffness = W * (B.transpose() * D * B);
  }
}

}  // namespace vs
