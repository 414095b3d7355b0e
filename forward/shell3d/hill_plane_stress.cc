#include "shell3d/hill_plane_stress.h"

#include <algorithm>
#include <cmath>

namespace vs::shell3d {

Mat3 anisotropy_matrix3(double r_value) {
  const double R = r_value;
  const double f = 3.0 * (1.0 + R) / (1.0 + 2.0 * R);
  Mat3 A;
  A << f * (1.0 + R), f * R, 0.0, f * R, f * (1.0 + R), 0.0, 0.0, 0.0, 0.5 * f;
  return A;
}

double r_value_of(const ViscousLaw& law) {
  const double a = law.A()(0, 1) / law.A()(0, 0);
  return a / (1.0 - a);
}

HillPlaneStressLaw::HillPlaneStressLaw(const ViscousLaw& law)
    : law_(&law), A_(anisotropy_matrix3(r_value_of(law))), a11_(law.A()(0, 0)) {}

double HillPlaneStressLaw::effective_rate(const Vec3& d) const {
  return std::sqrt(std::max(d.dot(A_ * d) / 3.0, 0.0));
}

InPlanePoint HillPlaneStressLaw::evaluate(double sigma_y, double hardening_viscosity,
                                          const Vec3& d) const {
  const Vec3 Ad = A_ * d;
  const double e = std::sqrt(std::max(d.dot(Ad) / 3.0, 0.0));
  // The 2-vector (t, 0) has effective rate sqrt(A11 t^2 / 3) = e under the 2x2 law.
  const Eigen::Vector2d d2(e * std::sqrt(3.0 / a11_), 0.0);
  const ViscousLaw::Point p2 = law_->evaluate(sigma_y, hardening_viscosity, d2);
  InPlanePoint p;
  p.rate = e;
  p.mu = p2.mu;
  p.tangent_coef = p2.tangent_coef;
  p.potential = p2.potential;
  p.stress = p.mu * Ad;
  return p;
}

}  // namespace vs::shell3d
