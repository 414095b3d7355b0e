// The paper's 2-node straight axisymmetric shell element (sections 4.2-4.3, after Zienkiewicz,
// Bauer, Morgan & Onate 1977), in the viscous analogy: velocities for displacements, strain rates
// for strains. Everything is evaluated at the element midpoint (one-point rule; the paper notes
// this is accurate, and it is what avoids shear locking), with Simpson integration through the
// thickness.
//
// Nodal unknowns in the global frame: radial velocity u, axial velocity w, rotation rate beta of
// the normal. With the tangent t = (c, s) = (dr/ds, dz/ds) and normal n = (-s, c), a point at
// distance zeta along n moves with v + zeta * dn/dt where dn/dt = -beta t, so
//   eps_s = d(v.t)/ds,  eps_t = u / r,  kappa_s = -d beta/ds,  kappa_t = -beta c / r,
//   gamma = d(v.n)/ds - beta                      (paper eq. 33 with R = infinity).
// Rates at zeta: eps_s + zeta kappa_s, eps_t + zeta kappa_t. Transverse shear carries a penalty
// viscosity (kappa_shear mu_shear h), not the flow rule (numerics.md section 3.4).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "element/simpson.h"
#include "material/normal_stress.h"
#include "material/viscous_law.h"

namespace vs {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat56 = Eigen::Matrix<double, 5, 6>;
using Vec5 = Eigen::Matrix<double, 5, 1>;

// Shear correction factor of the transverse shear penalty (Mindlin; numerics.md section 1.1).
inline constexpr double kShearCorrection = 5.0 / 6.0;

struct Axisym2Geometry {
  double ra, za, rb, zb;  // node coordinates [mm]
  double length() const;
  double mid_radius() const { return 0.5 * (ra + rb); }
};

// B: generalised strain rates (eps_s, eps_t, kappa_s, kappa_t, gamma) = B * (ua wa ba ub wb bb).
Mat56 axisym2_B(const Axisym2Geometry& g);
// B d, written out.
Vec5 axisym2_strain_rates(const Axisym2Geometry& g, const Vec6& d);

struct Axisym2Section {
  double thickness_mm = 1.0;
  const std::vector<double>* sigma_y = nullptr;  // flow stress at each thickness point [MPa]
  // Hardening seen by the step at each point, theta H dt [MPa s] (see ViscousLaw::evaluate);
  // null = none.
  const std::vector<double>* hardening_viscosity = nullptr;
  double shear_viscosity = 1.0;  // penalty viscosity for transverse shear
  // kTangent, optional: a flow direction n per point (2 each) that the rank-one part of the
  // tangent uses instead of the current one (primal-dual Newton, material/flow_direction.h);
  // null: the current one (the consistent tangent).
  const double* flow_direction = nullptr;
  // Through-thickness normal stress sigma_33 = -p(zeta) (material/normal_stress.h): the contact
  // pressures on the faces, lower = zeta -h/2 (the side the element normal n = (-s, c) points
  // away from). Zero (the default): plane stress.
  FacePressure face_pressure = {};
};

enum class StiffnessKind { kSecant, kTangent, kNone };

struct Axisym2Output {
  Vec6 force = Vec6::Zero();      // internal nodal forces (full 360 degrees) [N]
  Mat6 stiffness = Mat6::Zero();  // secant or tangent [N s/mm]
  // kTangent with split only: the tangent's rank-one part T, stiffness = secant + weight * T.
  Mat6 tangent_part = Mat6::Zero();
  double potential = 0.0;  // integral of phi over the volume [N mm/s]; with kNone and kTangent
  Vec5 strain_rate = Vec5::Zero();       // generalised strain rates
  Vec5 stress_resultant = Vec5::Zero();  // N_s, N_t [N/mm]; M_s, M_t [N]; Q [N/mm]
  std::vector<double> point_rate;        // kNone: effective strain rate at each thickness point
  // kTangent: flow direction m = A d / (3 eh) (2 per point) and cut-off rate eh at each point.
  std::vector<double> point_direction;
  std::vector<double> point_cutoff_rate;
};

// Evaluates the element at nodal velocities d. `rule` and `section.sigma_y` have equal size.
// With kTangent, `tangent_weight` in [0, 1] blends secant (0) and consistent tangent (1); the
// nonlinear solver adapts it like a trust region. `split`: also return the tangent's rank-one
// part separately (Axisym2Output::tangent_part, one more matrix product); without it only the
// blended stiffness.
void axisym2_evaluate(const Axisym2Geometry& g, const Axisym2Section& section,
                      const ThicknessRule& rule, const ViscousLaw& law, const Vec6& d,
                      StiffnessKind kind, Axisym2Output* out, double tangent_weight = 1.0,
                      bool split = true);

// Initial-stress (geometric) stiffness of the membrane forces for an implicit geometry update:
// moving the nodes by Delta changes the internal forces at fixed stress resultants by about
// K Delta, with the updated-Lagrangian form
//   K = 2 pi int_L [N_s (dDelta/ds).(ddelta/ds) + N_t (Delta_r / r)(delta_r / r)] r ds,
// one-point rule: 2 pi r_m N_s / L on [[I, -I], [-I, I]] for (u, w) and 2 pi L N_t / r_m on the
// midpoint radial velocity. Compressive resultants are dropped (the matrix stays positive
// semi-definite: a compressed membrane's negative stiffness is the wrinkling instability, which
// the velocity solve does not resolve). Rotation rates get nothing. N_s, N_t in N/mm; K in N/mm.
Mat6 axisym2_stress_stiffness(const Axisym2Geometry& g, double N_s, double N_t);

}  // namespace vs
