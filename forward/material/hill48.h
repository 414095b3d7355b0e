// Hill 1948 with planar anisotropy, plane stress, in material axes (plane_stress_axes.h):
//   sigma_bar^2 = s^T P s = (G+H) s11^2 - 2H s11 s22 + (F+H) s22^2 + 2N s12^2,
//   P = [[G+H, -H, 0], [-H, F+H, 0], [0, 0, 2N]]
// (Hill's quadratic 2f = F(s22-s33)^2 + G(s33-s11)^2 + H(s11-s22)^2 + 2N s12^2 at s33 = 0).
// Normalised to the uniaxial yield stress in RD: G + H = 1, so sigma_bar(u(0)) = 1.
//
// Identification (uniaxial stress u(theta), flow d ~ P u, r = d_ww / d33, d33 = -(d11 + d22)):
//   theta = 0:  d = (G+H, -H, 0)    -> r0  = H / G
//   theta = 90: d = (-H, F+H, 0)    -> r90 = H / F
//   theta = 45: d = (G, F, 2N) / 2  -> r45 = N / (F+G) - 1/2
//   sigma_bar^2(u(theta)) = 1 / sigma_theta^2 (stresses in units of sigma_0):
//   theta = 0: G + H = 1,  theta = 90: F + H = 1/sigma90^2,  theta = 45: (F + G + 2N)/4 =
//   1/sigma45^2, equibiaxial s = (1, 1, 0): F + G = 1/sigma_b^2.
// From r-values (with G + H = 1): G = 1/(1+r0), H = r0/(1+r0), F = H/r90, N = (r45 + 1/2)(F + G).
// From stresses: sigma0 = 1, sigma45, sigma90 give three equations for four coefficients, so a
// fourth datum is needed: the equibiaxial yield stress sigma_b (all-stress identification), or r0.
// r0 = r45 = r90 = R gives F = G = 1/(1+R), H = R/(1+R), 2N = 2(1+2R)/(1+R): the normal-anisotropy
// law of viscous_law.h and shell3d/hill_plane_stress.h (A = 3 P^-1 there).
//
// Dual (viscous) form, plane_stress_yield.h: e^2 = d^T P^-1 d and the unit-surface stress is
// m = P^-1 d / e. Derivation: normality d = lambda dsigma_bar/ds = lambda P s / sigma_bar; the
// work identity s . d = lambda s^T P s / sigma_bar = lambda sigma_bar defines e = lambda, so
// s = (sigma_bar / e) P^-1 d and d^T P^-1 d = (e / sigma_bar)^2 s^T P s = e^2.
#pragma once

#include "material/plane_stress_yield.h"

namespace vs {

struct Hill48Coefficients {
  double F = 0.5;
  double G = 0.5;
  double H = 0.5;
  double N = 1.5;  // the von Mises values
};

// Identifications of the header comment. Stresses are ratios to the RD yield stress sigma_0;
// r-values > 0. Bad data (non-positive values, a non-convex result) throw InputError.
Hill48Coefficients hill48_from_r_values(double r0, double r45, double r90);
Hill48Coefficients hill48_from_stresses(double sigma45, double sigma90, double sigma_b);
Hill48Coefficients hill48_from_stresses_and_r0(double sigma45, double sigma90, double r0);

class Hill48 final : public PlaneStressYield {
 public:
  // Throws InputError unless P is positive definite (a convex, bounded yield surface).
  explicit Hill48(const Hill48Coefficients& c);
  // r0 = r45 = r90 = R.
  static Hill48 NormalAnisotropy(double r_value);

  double effective_stress(const PlaneVector& s) const override;
  YieldPoint evaluate(const PlaneVector& s) const override;
  DualPoint dual(const PlaneVector& d, const PlaneVector* guess = nullptr) const override;

  const Hill48Coefficients& coefficients() const { return c_; }
  const PlaneMatrix& P() const { return P_; }
  const PlaneMatrix& P_inverse() const { return Pinv_; }

 private:
  Hill48Coefficients c_;
  PlaneMatrix P_;
  PlaneMatrix Pinv_;
};

}  // namespace vs
