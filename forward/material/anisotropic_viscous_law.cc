#include "material/anisotropic_viscous_law.h"

namespace vs {

AnisotropicViscousLaw::AnisotropicViscousLaw(const PlaneStressYield& yield,
                                             const ViscousLaw& scalar_law, double rd_angle_rad)
    : yield_(&yield), law_(&scalar_law), axes_(rd_angle_rad) {}

double AnisotropicViscousLaw::effective_rate(const PlaneVector& d) const {
  return yield_->dual(axes_.rate_to_material(d)).rate;
}

AnisotropicViscousLaw::Point AnisotropicViscousLaw::evaluate(double sigma_y,
                                                             double hardening_viscosity,
                                                             const PlaneVector& d,
                                                             const PlaneVector* flow_guess,
                                                             bool want_potential) const {
  const PlaneVector dm = axes_.rate_to_material(d);
  PlaneVector guess_m;
  if (flow_guess != nullptr) guess_m = axes_.stress_to_material(*flow_guess);
  const DualPoint dual = yield_->dual(dm, flow_guess != nullptr ? &guess_m : nullptr);
  const double e = dual.rate;
  const ViscousLaw::Scalars q = law_->scalars(sigma_y, hardening_viscosity, e * e, want_potential);

  Point p;
  p.rate = e;
  p.mu = q.mu;
  p.tangent_coef = q.tangent_coef;
  p.potential = q.potential;
  p.cutoff_rate = q.cutoff_rate;
  p.iterations = dual.iterations;
  p.converged = dual.converged;
  const PlaneVector g = e * dual.direction;  // d(e^2/2)/dd, material axes
  p.stress = axes_.stress_to_local(3.0 * q.mu * g);
  p.tangent =
      axes_.tangent_to_local(3.0 * q.mu * dual.hessian + 9.0 * q.tangent_coef * g * g.transpose());
  p.flow_direction = axes_.stress_to_local(dual.direction);
  return p;
}

}  // namespace vs
