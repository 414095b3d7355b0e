// In-plane viscous point law of the 3D shell: rate d = (d11, d22, gamma12 = 2 d12) in the local
// orthonormal frame of the shell, stress s = (s11, s22, s12). Transverse shear is not part of the
// flow rule (it carries a penalty viscosity in the element; numerics.md section 3.4).
//
// Derivation (Hill 1948 with planar isotropy, Lankford value R, normalised to the in-plane
// uniaxial flow stress). The effective stress is the quadratic form
//   sigma_bar^2 = s^T P s = s11^2 + s22^2 - 2R/(1+R) s11 s22 + 2(1+2R)/(1+R) s12^2,
// (R = 1: s11^2 + s22^2 - s11 s22 + 3 s12^2, von Mises plane stress). Associated flow with the
// plastic work identity s . d = sigma_bar * e (engineering shear makes s . d the work rate) gives
// d = (e / sigma_bar) P s, hence s = (sigma_bar / e) P^-1 d and e^2 = d^T P^-1 d. Writing
// A = 3 P^-1:   e^2 = d^T A d / 3,   s = mu A d,   mu = sigma_bar(e) / (3 e),  with
//   A = 3(1+R)/(1+2R) [[1+R, R, 0], [R, 1+R, 0], [0, 0, 1/2]]
// (the 2x2 block inverts [[1, -a], [-a, 1]], a = R/(1+R), with 1 - a^2 = (1+2R)/(1+R)^2; the
// shear entry is 3 / (2(1+2R)/(1+R))). R = 1 gives A = [[4,2,0],[2,4,0],[0,0,1]]: the paper's
// D1 / mu for nu = 1/2 (READING-NOTES, eq. 76 corrected). The 2x2 block equals the axisymmetric
// anisotropy_matrix(R), and mu, the tangent coefficient and the potential depend on e only, so the
// scalar part is delegated to the axisymmetric ViscousLaw (same flow law, cut-off, rate law).
#pragma once

#include <Eigen/Core>

#include "material/viscous_law.h"

namespace vs::shell3d {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// A(R) of the header comment.
Mat3 anisotropy_matrix3(double r_value);

// R recovered from a ViscousLaw's 2x2 A(R): A12 / A11 = R / (1 + R).
double r_value_of(const ViscousLaw& law);

struct InPlanePoint {
  double rate = 0.0;           // effective strain rate e [1/s]
  double mu = 0.0;             // secant viscosity [MPa s]
  double tangent_coef = 0.0;   // D_tan = mu A + tangent_coef (A d)(A d)^T
  double potential = 0.0;      // phi(e) [MPa/s]
  double cutoff_rate = 0.0;    // eh = sqrt(e^2 + e_c^2) (0 for a constant viscosity)
  Vec3 stress = Vec3::Zero();  // (s11, s22, s12) [MPa]
};

// The 3-component law sharing the scalar flow law of `law` (not owned; must outlive this).
class HillPlaneStressLaw {
 public:
  explicit HillPlaneStressLaw(const ViscousLaw& law);

  InPlanePoint evaluate(double sigma_y, double hardening_viscosity, const Vec3& d) const;
  // The same with the rate d = A^-1 (A d) given through Ad = A d and e^2 = d . Ad / 3.
  InPlanePoint evaluate_scaled(double sigma_y, double hardening_viscosity, const Vec3& Ad,
                               double e_squared) const;
  double effective_rate(const Vec3& d) const;
  const Mat3& A() const { return A_; }
  // Squared dual norm 3 n^T A^-1 n of a flow direction n (the primal-dual tangent, shell9.h).
  double dual_norm_squared(const Vec3& n) const { return n.dot(Ainv3_ * n); }
  const ViscousLaw& scalar_law() const { return *law_; }

 private:
  const ViscousLaw* law_;
  Mat3 A_;
  Mat3 Ainv3_;  // 3 A^-1
};

}  // namespace vs::shell3d
