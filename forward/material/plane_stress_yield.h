// A plane-stress yield function in material axes and its dual norm: the interface between the
// anisotropic yield criteria (hill48.h, yld2000.h) and the viscous point law
// (anisotropic_viscous_law.h). Vectors follow plane_stress_axes.h: d = (d11, d22, 2 d12),
// s = (s11, s22, s12), s . d the work rate.
//
// sigma_bar(s) is an effective stress, convex, even and homogeneous of degree one, normalised so
// that sigma_bar equals the uniaxial yield stress in RD: sigma_bar(u(0)) = 1 for unit stress.
// (It is a norm on stress space.) Its dual norm
//   e(d) = max { s . d : sigma_bar(s) <= 1 }
// is the effective strain rate: for s on the yield surface sigma_bar(s) = sigma_y the plastic work
// identity s . d = sigma_y e holds exactly when d is normal to the surface at s (associated flow),
// and the maximiser m(d) = de/dd (sigma_bar(m) = 1) is the unit-surface stress whose normal is
// parallel to d. E(d) = e^2/2 and Sigma(s) = sigma_bar^2/2 are Legendre conjugates, so
//   g(d) = dE/dd = e m   solves   dSigma/ds (g) = sigma_bar(g) dsigma_bar/ds (g) = d,
//   H(d) = d^2E/dd^2 = [d^2Sigma/ds^2 (g)]^-1,  d^2Sigma/ds^2 = n n^T + sigma_bar
//   d^2sigma_bar/ds^2,
// n = dsigma_bar/ds (derivation and solver in dual_potential.h). For a quadratic criterion
// sigma_bar^2 = s^T P s both are closed forms: g = P^-1 d, H = P^-1, e^2 = d^T P^-1 d.
#pragma once

#include "material/plane_stress_axes.h"

namespace vs {

// sigma_bar and its first two derivatives at one stress.
struct YieldPoint {
  double value = 0.0;                          // sigma_bar(s)
  PlaneVector gradient = PlaneVector::Zero();  // n = d sigma_bar / ds (the flow direction)
  PlaneMatrix hessian = PlaneMatrix::Zero();   // d^2 sigma_bar / ds^2 (singular along s)
};

// The dual norm at a rate d (material axes), header comment.
struct DualPoint {
  double rate = 0.0;                            // e(d)
  PlaneVector direction = PlaneVector::Zero();  // m(d), sigma_bar(m) = 1 (zero at d = 0)
  PlaneMatrix hessian = PlaneMatrix::Zero();    // H(d) = d^2 (e^2/2) / dd^2
  int iterations = 0;                           // local Newton iterations (0 for a closed form)
  bool converged = true;
};

class PlaneStressYield {
 public:
  virtual ~PlaneStressYield() = default;
  virtual double effective_stress(const PlaneVector& s) const = 0;
  // Value, gradient and Hessian. The origin (no direction) returns zeros.
  virtual YieldPoint evaluate(const PlaneVector& s) const = 0;
  // guess: optional flow direction m from a previous evaluation (warm start of a local solve).
  // At d = 0 the rate and direction are zero and H is the limit along guess's normal, or along
  // equibiaxial stretching without a guess (H is homogeneous of degree zero, so has no limit at 0).
  virtual DualPoint dual(const PlaneVector& d, const PlaneVector* guess = nullptr) const = 0;
};

// Uniaxial tension at theta to RD or equibiaxial tension: yield stress in units of the normalising
// stress (1 / sigma_bar(u)) and the strain-rate ratio of the normal: the Lankford ratio
// width / thickness rate (uniaxial), or r_b = d22 / d11 (equibiaxial).
struct DirectionalResponse {
  double stress = 0.0;
  double r_value = 0.0;
};
DirectionalResponse uniaxial_response(const PlaneStressYield& yield, double theta_rad);
DirectionalResponse equibiaxial_response(const PlaneStressYield& yield);

}  // namespace vs
