#include "material/hill_plane_stress.h"

#include <Eigen/LU>
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
    : law_(&law), A_(anisotropy_matrix3(r_value_of(law))), Ainv3_(3.0 * A_.inverse()) {}

double HillPlaneStressLaw::effective_rate(const Vec3& d) const {
  return std::sqrt(std::max(d.dot(A_ * d) / 3.0, 0.0));
}

InPlanePoint HillPlaneStressLaw::evaluate(double sigma_y, double hardening_viscosity,
                                          const Vec3& d) const {
  const Vec3 Ad = A_ * d;
  return evaluate_scaled(sigma_y, hardening_viscosity, Ad, std::max(d.dot(Ad) / 3.0, 0.0));
}

InPlanePoint HillPlaneStressLaw::evaluate_scaled(double sigma_y, double hardening_viscosity,
                                                 const Vec3& Ad, double e_squared) const {
  // The scalar part depends on e only (the 2x2 law at any 2-vector of the same effective rate).
  const ViscousLaw::Scalars q = law_->scalars(sigma_y, hardening_viscosity, e_squared, true);
  InPlanePoint p;
  p.rate = std::sqrt(e_squared);
  p.mu = q.mu;
  p.tangent_coef = q.tangent_coef;
  p.potential = q.potential;
  p.cutoff_rate = q.cutoff_rate;
  p.stress = p.mu * Ad;
  return p;
}

}  // namespace vs::shell3d
