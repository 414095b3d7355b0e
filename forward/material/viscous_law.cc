#include "material/viscous_law.h"

#include <algorithm>
#include <cmath>

namespace vs {

Eigen::Matrix2d anisotropy_matrix(double r_value) {
  const double R = r_value;
  const double f = 3.0 * (1.0 + R) / (1.0 + 2.0 * R);
  Eigen::Matrix2d A;
  A << f * (1.0 + R), f * R, f * R, f * (1.0 + R);
  return A;
}

ViscousLaw::ViscousLaw(const RateSpec& rate, double cutoff_rate, double r_value)
    : rate_(rate), cutoff_(cutoff_rate), A_(anisotropy_matrix(r_value)) {}

ViscousLaw ViscousLaw::Constant(double mu, double r_value) {
  ViscousLaw law;
  law.constant_mu_ = mu;
  law.A_ = anisotropy_matrix(r_value);
  return law;
}

double ViscousLaw::effective_rate(const Eigen::Vector2d& d) const {
  return std::sqrt(std::max(d.dot(A_ * d) / 3.0, 0.0));
}

double ViscousLaw::effective_stress(double sigma_y, double e, double hardening_viscosity) const {
  if (is_constant()) return 3.0 * constant_mu_ * e;
  const double eh = std::sqrt(e * e + cutoff_ * cutoff_);
  return flow(sigma_y, hardening_viscosity, eh) * e / eh;
}

ViscousLaw::Point ViscousLaw::evaluate(double sigma_y, double hardening_viscosity,
                                       const Eigen::Vector2d& d, bool want_potential) const {
  Point p;
  const Eigen::Vector2d Ad = A_ * d;
  const double e2 = std::max(d.dot(Ad) / 3.0, 0.0);
  const double e = std::sqrt(e2);
  const Scalars q = scalars(sigma_y, hardening_viscosity, e2, want_potential);
  p.rate = e;
  p.mu = q.mu;
  p.tangent_coef = q.tangent_coef;
  p.potential = q.potential;
  p.stress = p.mu * Ad;
  return p;
}

}  // namespace vs
