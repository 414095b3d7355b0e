// Plane-stress vectors and their rotation between the local frame of a shell point and the
// material (orthotropy) axes RD (rolling direction) and TD (transverse direction).
//
// Convention (the 3D shell's, shell3d/hill_plane_stress.h): rate d = (d11, d22, gamma12 = 2 d12),
// stress s = (s11, s22, s12). Then s . d = s11 d11 + s22 d22 + s12 gamma12 is the work rate per
// unit volume (the double contraction of the tensors), so stress and rate are work conjugate
// vectors and every potential below is differentiated with the plain dot product.
//
// Rotation. RD makes the angle a with the local axis e1 (counter-clockwise towards e2):
//   RD = c e1 + s e2,  TD = -s e1 + c e2,  c = cos a, s = sin a.
// Tensor components in the material axes are D'_ij = e'_i . D . e'_j, which for the rate vector
// (engineering shear) is d' = T d with
//   T = [[ c^2,    s^2,   c s      ],
//        [ s^2,    c^2,  -c s      ],
//        [-2 c s,  2 c s, c^2 - s^2]],
// and for the stress vector (tensor shear) s' = T_s s with T_s = T^-T. T_s^T T = I is the
// statement that the work rate does not depend on the frame: s' . d' = s . d. Hence a law
// written in material axes, s' = S(d'), reads in the local frame
//   s = T^T S(T d),   ds/dd = T^T (dS/dd') T.
// A uniaxial stress of unit magnitude at angle theta to RD has material components
// u(theta) = (cos^2, sin^2, cos sin); the width direction is w = (-sin, cos), whose rate is
// d_ww = d11 sin^2 + d22 cos^2 - gamma12 sin cos, and incompressibility gives the thickness rate
// d33 = -(d11 + d22). The Lankford ratio is r(theta) = d_ww / d33.
#pragma once

#include <Eigen/Core>

namespace vs {

using PlaneVector = Eigen::Vector3d;  // (11, 22, 12) components, see the header comment
using PlaneMatrix = Eigen::Matrix3d;

class MaterialAxes {
 public:
  // rd_angle_rad: angle from the local axis e1 to RD (counter-clockwise).
  explicit MaterialAxes(double rd_angle_rad = 0.0);
  // From c = cos a, s = sin a (c^2 + s^2 = 1).
  MaterialAxes(double c, double s);

  // Local -> material: rate d' = T d, stress s' = T^-T s.
  PlaneVector rate_to_material(const PlaneVector& d) const { return T_ * d; }
  PlaneVector stress_to_material(const PlaneVector& s) const { return Ts_ * s; }
  // Material -> local: stress s = T^T s', tangent T^T D' T.
  PlaneVector stress_to_local(const PlaneVector& s_material) const {
    return T_.transpose() * s_material;
  }
  PlaneMatrix tangent_to_local(const PlaneMatrix& D_material) const {
    return T_.transpose() * D_material * T_;
  }
  const PlaneMatrix& rate_rotation() const { return T_; }
  const PlaneMatrix& stress_rotation() const { return Ts_; }

 private:
  PlaneMatrix T_;
  PlaneMatrix Ts_;
};

// Unit uniaxial stress at angle theta to RD, material components (cos^2, sin^2, cos sin).
PlaneVector uniaxial_stress_direction(double theta_rad);

// Lankford ratio width rate / thickness rate of a rate d (material axes) for tension at theta.
double lankford_ratio(const PlaneVector& d, double theta_rad);

}  // namespace vs
