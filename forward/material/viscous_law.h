// The viscous-shell analogy at one material point (paper sections 2, 4.1 and 4.5, corrected).
//
// In-plane strain rate d = (d_1, d_2) (meridional, circumferential; transverse shear is handled
// separately by the element as a penalty, see numerics.md section 3.4). Hill 1948 with planar
// isotropy and Lankford value R, normalised to the in-plane uniaxial flow stress:
//   sigma_bar^2 = s1^2 + s2^2 - 2R/(1+R) s1 s2.
// Associated flow with plastic work sigma_bar * e = s . d gives
//   e^2 = d^T A d / 3,  s = mu A d,  mu = sigma_bar(e) / (3 e),
//   A = 3(1+R)/(1+2R) [[1+R, R], [R, 1+R]]      (R = 1: A = [[4,2],[2,4]], eq. 21).
// Rigid zones need a large but finite viscosity (paper appendix). We cap it smoothly: the flow law
// is evaluated at eh = sqrt(e^2 + e_c^2), sigma_bar = f(eh) e / eh, so mu = f(eh) / (3 eh) never
// exceeds f(e_c) / (3 e_c), and for e >> e_c the stress is the flow stress to O((e_c/e)^2). A hard
// cut-off (mu constant below e_c) makes the Newton tangent jump at e = e_c and stalls Newton; the
// smooth cap keeps it C-infinity. The stress derives from the convex potential phi(e)
// (phi' = sigma_bar), which the nonlinear solver uses as merit function.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "scene/scene.h"

namespace vs {

// A(R) of the header comment.
Eigen::Matrix2d anisotropy_matrix(double r_value);

class ViscousLaw {
 public:
  // Flow law sigma_bar = f(sigma_y, e) of RateSpec with cut-off rate e_c > 0.
  ViscousLaw(const RateSpec& rate, double cutoff_rate, double r_value);
  // Linear viscous material of constant viscosity mu (the elastic-shell analogy: mu plays G).
  static ViscousLaw Constant(double mu, double r_value = 1.0);

  struct Point {
    double rate = 0.0;                                 // effective strain rate e [1/s]
    double mu = 0.0;                                   // secant viscosity [MPa s]
    double tangent_coef = 0.0;                         // D_tan = mu A + tangent_coef (A d)(A d)^T
    double potential = 0.0;                            // phi(e) [MPa/s]: power density potential
    Eigen::Vector2d stress = Eigen::Vector2d::Zero();  // s = mu A d [MPa]
  };
  // sigma_y: flow stress at the start of the step; hardening_viscosity = theta H dt [MPa s]: the
  // hardening of the step seen by the velocity solve, sigma_y(eps_n + theta e dt) linearised
  // (theta = 1/2, midpoint). It makes the instantaneous problem strictly convex along the flow
  // direction, which a rate-independent point is not, and removes the step-to-step switching
  // between nearly equal mechanisms that frozen (explicit) hardening produces.
  // The potential is computed only if asked for (line searches); it is 0 otherwise.
  Point evaluate(double sigma_y, double hardening_viscosity, const Eigen::Vector2d& d,
                 bool want_potential = true) const;

  // The scalar part of evaluate() at effective rate e = sqrt(e_squared): secant viscosity, tangent
  // coefficient and (if asked) potential. It needs e only squared (the cut-off rate is
  // sqrt(e^2 + e_c^2)), which keeps a square root off the critical path. Inline (defined below):
  // elements call it at every thickness point.
  struct Scalars {
    double mu = 0.0;
    double tangent_coef = 0.0;
    double potential = 0.0;
    double cutoff_rate = 0.0;  // eh = sqrt(e^2 + e_c^2) (0 for a constant viscosity)
  };
  Scalars scalars(double sigma_y, double hardening_viscosity, double e_squared,
                  bool want_potential) const;

  // Effective stress at effective rate e (>= 0), smooth cut-off applied.
  double effective_stress(double sigma_y, double e, double hardening_viscosity = 0.0) const;
  // Effective rate e of an in-plane rate vector.
  double effective_rate(const Eigen::Vector2d& d) const;

  const Eigen::Matrix2d& A() const { return A_; }
  double cutoff_rate() const { return cutoff_; }
  bool is_constant() const { return constant_mu_ > 0.0; }
  double constant_mu() const { return constant_mu_; }

 private:
  ViscousLaw() = default;
  // f(e) = sigma_bar(e) without cut-off, with the hardening term hv * e added; its slope and its
  // antiderivative int_0^e f.
  double flow(double sigma_y, double hv, double e) const;
  double flow_slope(double sigma_y, double hv, double e) const;
  double antiderivative(double sigma_y, double hv, double e) const;

  RateSpec rate_;
  double cutoff_ = 1e-6;
  double constant_mu_ = 0.0;
  Eigen::Matrix2d A_ = Eigen::Matrix2d::Zero();
};

// ---- inline definitions (hot path of every element evaluation) ----

inline double ViscousLaw::flow(double sigma_y, double hv, double e) const {
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

inline double ViscousLaw::flow_slope(double sigma_y, double hv, double e) const {
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

inline double ViscousLaw::antiderivative(double sigma_y, double hv, double e) const {
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

inline ViscousLaw::Scalars ViscousLaw::scalars(double sigma_y, double hardening_viscosity,
                                               double e_squared, bool want_potential) const {
  Scalars p;
  if (is_constant()) {
    p.mu = constant_mu_;
    if (want_potential) p.potential = 1.5 * constant_mu_ * e_squared;
    return p;
  }
  // Smooth cut-off: the flow law is evaluated at eh = sqrt(e^2 + e_c^2) and scaled by e/eh, so
  // mu = f(eh) / (3 eh), the potential is F(eh) - F(e_c) (F' = f) and the tangent coefficient
  // (f'(eh) eh - f(eh)) / (9 eh^3) is smooth through e = 0.
  const double hv = hardening_viscosity;
  const double eh = std::sqrt(e_squared + cutoff_ * cutoff_);
  const double inv = 1.0 / eh;  // one division for both coefficients
  p.cutoff_rate = eh;
  const double f = flow(sigma_y, hv, eh);
  p.mu = (1.0 / 3.0) * f * inv;
  p.tangent_coef = (1.0 / 9.0) * (flow_slope(sigma_y, hv, eh) * eh - f) * (inv * inv * inv);
  if (want_potential) {
    p.potential = antiderivative(sigma_y, hv, eh) - antiderivative(sigma_y, hv, cutoff_);
  }
  return p;
}

}  // namespace vs
