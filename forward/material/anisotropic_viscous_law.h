// The viscous-shell point law (viscous_law.h) for a planar-anisotropic yield function: in-plane
// stress from in-plane strain rate through the dual (dissipation) potential, with the consistent
// tangent. Vectors and frames: plane_stress_axes.h (d = (d11, d22, 2 d12) in the local frame of
// the point, RD at angle a to e1); yield function and dual norm: plane_stress_yield.h.
//
// Derivation (material axes). Associated flow from the yield surface sigma_bar(s) = f (f the flow
// stress): d = lambda dsigma_bar/ds (normality), with the plastic work identity s . d = f e, which
// by Euler's identity for the degree-one sigma_bar gives lambda = e, the dual norm of d. The
// thickness rate follows from incompressibility, d33 = -(d11 + d22), and never enters the
// in-plane work (s33 = 0). The stress is the unit-surface point m(d) scaled by f, s = f m(d) =
// f de/dd: the gradient of the dissipation potential D(d) = F(e(d)), F' = f. In the notation of
// viscous_law.h, g = e m = d(e^2/2)/dd and H = dg/dd:
//   s = (f / e) g = 3 mu g,   mu = f / (3 e).
// Hill 1948: g = P^-1 d = A d / 3 with A = 3 P^-1, which is viscous_law.h's s = mu A d.
//
// Cut-off and rate law: exactly those of the scalar ViscousLaw passed in (its R is not used). The
// flow law is evaluated at eh = sqrt(e^2 + e_c^2) and scaled by e / eh (ViscousLaw::scalars):
//   s = 3 mu g,   mu = f(eh) / (3 eh),
//   ds/dd = 3 mu H + 9 c g g^T,   c = (f'(eh) eh - f(eh)) / (9 eh^3)   (tangent_coef),
// from d(f(eh)/eh)/dd = (f' eh - f) / eh^3 g; potential F(eh) - F(e_c), whose gradient is s.
// Work conjugacy s . d = (f(eh) e / eh) e = sigma_bar(e) e with ViscousLaw::effective_stress.
// In the local frame (plane_stress_axes.h): s = T^T s'(T d), ds/dd = T^T (ds'/dd') T.
//
// The flow direction m is returned (local frame) so that a Newton loop can carry it per point, as
// the primal-dual method of flow_direction.h carries n = (e / eh) m (its dual-norm ball
// |n|_* <= 1 is sigma_bar(n) <= 1 here), and hand it back as the warm start of the local solve.
#pragma once

#include "material/plane_stress_yield.h"
#include "material/viscous_law.h"

namespace vs {

class AnisotropicViscousLaw {
 public:
  // yield and scalar_law are not owned and must outlive this. rd_angle_rad: RD relative to e1.
  AnisotropicViscousLaw(const PlaneStressYield& yield, const ViscousLaw& scalar_law,
                        double rd_angle_rad = 0.0);

  struct Point {
    double rate = 0.0;                                 // effective strain rate e [1/s]
    double mu = 0.0;                                   // secant viscosity [MPa s]
    double tangent_coef = 0.0;                         // c of the header comment
    double potential = 0.0;                            // F(eh) - F(e_c) [MPa/s]
    double cutoff_rate = 0.0;                          // eh (0 for a constant viscosity)
    PlaneVector stress = PlaneVector::Zero();          // (s11, s22, s12) [MPa], local frame
    PlaneMatrix tangent = PlaneMatrix::Zero();         // ds/dd [MPa s], local frame
    PlaneVector flow_direction = PlaneVector::Zero();  // m, local frame (0 at d = 0)
    int iterations = 0;                                // local solve (0 for Hill 1948)
    bool converged = true;                             // local solve converged
  };
  // sigma_y, hardening_viscosity: as ViscousLaw::evaluate. flow_guess: m of a previous evaluation
  // of this point (local frame), or null.
  Point evaluate(double sigma_y, double hardening_viscosity, const PlaneVector& d,
                 const PlaneVector* flow_guess = nullptr, bool want_potential = true) const;

  double effective_rate(const PlaneVector& d) const;
  const MaterialAxes& axes() const { return axes_; }
  const PlaneStressYield& yield() const { return *yield_; }
  const ViscousLaw& scalar_law() const { return *law_; }

 private:
  const PlaneStressYield* yield_;
  const ViscousLaw* law_;
  MaterialAxes axes_;
};

}  // namespace vs
