// Barlat Yld2000-2d (Barlat et al. 2003, Int J Plasticity 19:1297, "Plane stress yield function
// for aluminum alloy sheets - part 1: theory"), in material axes (plane_stress_axes.h).
//
// Two linear transformations of the in-plane stress s = (s11, s22, s12):
//   X' = L' s,  X'' = L'' s,   X = (Xxx, Xyy, Xxy), principal values X1 >= X2,
//   L'  = [[2a1/3, -a1/3, 0], [-a2/3, 2a2/3, 0], [0, 0, a7]],
//   L'' = 1/9 [[-2a3 + 2a4 + 8a5 - 2a6,  a3 - 4a4 - 4a5 + 4a6, 0],
//              [ 4a3 - 4a4 - 4a5 +  a6, -2a3 + 8a4 + 2a5 - 2a6, 0],
//              [ 0, 0, 9a8]],
// and
//   Phi = phi' + phi'' = |X'1 - X'2|^a + |2X''2 + X''1|^a + |2X''1 + X''2|^a = 2 sigma_bar^a.
// All alpha = 1 gives the deviator for both X and Hosford's isotropic function, which is von Mises
// for a = 2 and 4 (exponent a: 8 for FCC / aluminium, 6 for BCC / steel). The yield function is
// convex for a >= 1 (Barlat 2003, section 4); the derivatives below need a >= 2.
//
// Smooth forms without principal axes. With T = (Xxx + Xyy)/2 and q = ((Xxx - Xyy)/2)^2 + Xxy^2
// (X1,2 = T +- sqrt(q)):
//   phi'  = (4 q')^(a/2),
//   phi'' = u(x, q'') = |x - sqrt(q)|^a + |x + sqrt(q)|^a,  x = 3 T''.
// u is even in sqrt(q), hence a smooth function of q; for sqrt(q) < |x| / 10 it is evaluated by its
// binomial series u = 2 sum_k C(a, 2k) |x|^(a - 2k) q^k (finite and exact for even integer a),
// which avoids the cancellation of the closed form's q-derivatives at q -> 0 (X'' with equal
// principal values). With grad q = ((Xxx - Xyy)/2, -(Xxx - Xyy)/2, 2 Xxy), Q = d^2q/dX^2 =
// [[1/2, -1/2, 0], [-1/2, 1/2, 0], [0, 0, 2]], grad x = (3/2, 3/2, 0):
//   dphi'/dX   = phi'_q grad q,   d^2phi'/dX^2 = phi'_q Q + phi'_qq grad q grad q^T,
//   dphi''/dX  = u_x grad x + u_q grad q,
//   d^2phi''/dX^2 = u_xx gx gx^T + u_xq (gx gq^T + gq gx^T) + u_qq gq gq^T + u_q Q,
//   dPhi/ds = L'^T dphi'/dX' + L''^T dphi''/dX'',  d^2Phi/ds^2 = L'^T (.) L' + L''^T (.) L'',
// and for sigma_bar = (Phi/2)^(1/a):
//   dsigma_bar/ds = sigma_bar / (a Phi) dPhi/ds,
//   d^2sigma_bar/ds^2 = sigma_bar / (a Phi) [d^2Phi/ds^2 + (1/a - 1) / Phi dPhi/ds dPhi/ds^T].
// The evaluation scales s by its largest component first (sigma_bar has degree one, its gradient
// degree zero, its Hessian degree -1), so Phi ~ |s|^a cannot overflow.
//
// The dual (viscous) form has no closed form: dual() is the local Newton solve of
// dual_potential.h.
#pragma once

#include <array>

#include "material/plane_stress_yield.h"

namespace vs {

struct Yld2000Coefficients {
  std::array<double, 8> alpha{1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  double exponent = 8.0;  // a
};

class Yld2000 final : public PlaneStressYield {
 public:
  // Throws InputError for an exponent below 2 or non-finite coefficients.
  explicit Yld2000(const Yld2000Coefficients& c);

  double effective_stress(const PlaneVector& s) const override;
  YieldPoint evaluate(const PlaneVector& s) const override;
  DualPoint dual(const PlaneVector& d, const PlaneVector* guess = nullptr) const override;

  const Yld2000Coefficients& coefficients() const { return c_; }
  const PlaneMatrix& L1() const { return L1_; }  // L'
  const PlaneMatrix& L2() const { return L2_; }  // L''

 private:
  Yld2000Coefficients c_;
  PlaneMatrix L1_;
  PlaneMatrix L2_;
};

}  // namespace vs
