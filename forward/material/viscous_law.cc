#include "material/viscous_law.h"

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

double ViscousLaw::flow(double sigma_y, double hv, double e) const {
  double s = sigma_y;
  switch (rate_.law) {
    case RateLaw::kNone:
      break;
    case RateLaw::kPerzyna:
      // Paper eq. (7) solved for the stress: e = gamma (sigma_bar - sigma_y)^exponent.
      s += std::pow(e / rate_.gamma_per_s, 1.0 / rate_.exponent);
      break;
    case RateLaw::kPower:
      s *= std::pow(e / rate_.reference_rate_per_s, rate_.m);
      break;
  }
  return s + hv * e;
}

double ViscousLaw::flow_slope(double sigma_y, double hv, double e) const {
  double d = hv;
  switch (rate_.law) {
    case RateLaw::kNone:
      break;
    case RateLaw::kPerzyna:
      d += std::pow(e / rate_.gamma_per_s, 1.0 / rate_.exponent) / (rate_.exponent * e);
      break;
    case RateLaw::kPower:
      d += rate_.m * sigma_y * std::pow(e / rate_.reference_rate_per_s, rate_.m) / e;
      break;
  }
  return d;
}

double ViscousLaw::antiderivative(double sigma_y, double hv, double e) const {
  double F = 0.5 * hv * e * e;
  switch (rate_.law) {
    case RateLaw::kNone:
      F += sigma_y * e;
      break;
    case RateLaw::kPerzyna: {
      const double q = 1.0 / rate_.exponent + 1.0;
      F += sigma_y * e + rate_.gamma_per_s * std::pow(e / rate_.gamma_per_s, q) / q;
      break;
    }
    case RateLaw::kPower: {
      const double q = rate_.m + 1.0;
      F += sigma_y * rate_.reference_rate_per_s * std::pow(e / rate_.reference_rate_per_s, q) / q;
      break;
    }
  }
  return F;
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
  const double e = std::sqrt(std::max(d.dot(Ad) / 3.0, 0.0));
  p.rate = e;
  if (is_constant()) {
    p.mu = constant_mu_;
    if (want_potential) p.potential = 1.5 * constant_mu_ * e * e;
  } else {
    // Smooth cut-off: the flow law is evaluated at eh = sqrt(e^2 + e_c^2) and scaled by e/eh,
    // so mu = f(eh) / (3 eh), the potential is F(eh) - F(e_c) (F' = f) and the tangent
    // coefficient (f'(eh) eh - f(eh)) / (9 eh^3) is smooth through e = 0.
    const double hv = hardening_viscosity;
    const double eh = std::sqrt(e * e + cutoff_ * cutoff_);
    const double f = flow(sigma_y, hv, eh);
    p.mu = f / (3.0 * eh);
    p.tangent_coef = (flow_slope(sigma_y, hv, eh) * eh - f) / (9.0 * eh * eh * eh);
    if (want_potential) {
      p.potential = antiderivative(sigma_y, hv, eh) - antiderivative(sigma_y, hv, cutoff_);
    }
  }
  p.stress = p.mu * Ad;
  return p;
}

}  // namespace vs
