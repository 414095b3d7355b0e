// The planar-anisotropic yield function of a scene ([material.anisotropy]) as the 3D shell uses
// it: built once per run from the scene data (hill48.h, yld2000.h, yld2000_fit.h), with what the
// element needs per flow point (shell9.cc, evaluate_point):
//   - Hill 1948 (quadratic): P in material axes; in the local frame of a point whose RD makes the
//     angle a with e1 (plane_stress_axes.h, d' = T d, s' = T_s s, T_s = T^-T) the viscous law is
//     that of hill_plane_stress.h with
//       A(a) = 3 T^T P^-1 T,   3 A(a)^-1 = T_s^T P T_s
//     (e^2 = d'^T P^-1 d' = d^T (T^T P^-1 T) d; the stress s = T^T s' = T^T (f/e) P^-1 T d), so
//     the normal-anisotropy code path runs unchanged with a per-point A;
//   - Yld2000-2d: the local solve of the dual norm (dual_potential.h) per point, rotated.
// Both are normalised to the uniaxial yield stress along RD: the hardening curve of the scene is
// the RD tensile curve.
#pragma once

#include <memory>
#include <string>

#include "material/plane_stress_yield.h"
#include "scene/scene.h"

namespace vs {

struct PlanarAnisotropy {
  std::unique_ptr<PlaneStressYield> yield;  // material axes
  bool quadratic = false;                   // Hill 1948: P below is the criterion
  PlaneMatrix P = PlaneMatrix::Identity();  // sigma_bar^2 = s'^T P s' (quadratic only)
  PlaneMatrix A = PlaneMatrix::Identity();  // 3 P^-1 (quadratic only), material axes
  double rd_angle_rad = 0.0;                // RD from the global x axis in the initial blank
  std::string description;                  // one line for the run's "built" list
};

// The scene's planar anisotropy, or null for model = normal. Data that give no convex yield
// function (or a Yld2000-2d identification that does not converge) throw InputError naming
// `source` and the section.
std::unique_ptr<PlanarAnisotropy> make_planar_anisotropy(const AnisotropySpec& spec,
                                                         const std::string& source);

}  // namespace vs
