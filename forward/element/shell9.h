// The 9-node degenerated shell element of paper section 6 in the viscous analogy (velocities for
// displacements, strain rates for strains), with a choice of strain evaluation:
//   kSelective (paper, section 6.3): in-plane components (eps11, eps22, gam12) at 3x3 points,
//     transverse shear (gam13, gam23) at 2x2 points. Membrane-locks on thin curved shells and has
//     one spurious transverse mode in flat free meshes (numerics.md sections 1.4, 2.1).
//   kMitc9: all components at 3x3 points from the MITC9 assumed covariant strains (mitc9.h).
//   kFull / kReduced: everything at 3x3 / 2x2 (for comparison and zero-mode tests only).
// Through the thickness, any ThicknessRule (Gauss or Simpson; quadrature.h).
//
// Constitutive choices (Shell9Material):
//   elastic:  D1 = E/(1-nu^2) [[1,nu,0],[nu,1,0],[0,0,(1-nu)/2]], D2 = k G I, G = E/(2(1+nu)),
//             k = 5/6 (eq. 63 read as k G, READING-NOTES). nu = 1/2 gives G [[4,2,0],[2,4,0],
//             [0,0,1]] = the viscous D1 with mu = G (numerics.md 1.1).
//   viscous:  the Hill point law (hill_plane_stress.h) at every in-plane point and thickness
//             point ("flow point"); ViscousLaw::Constant(mu) is the constant-viscosity mode.
//             Transverse shear carries the penalty viscosity k * shear_viscosity, not the flow
//             rule (numerics.md 3.4; same choice as the axisymmetric element).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "element/shell9_kinematics.h"
#include "element/simpson.h"
#include "material/hill_plane_stress.h"
#include "material/normal_stress.h"
#include "material/planar_anisotropy.h"

namespace vs::shell3d {

enum class Shell9Rule { kSelective, kMitc9, kFull, kReduced };

inline constexpr double kShellShearCorrection = 5.0 / 6.0;

struct Shell9Material {
  bool viscous = false;
  double young = 0.0, poisson = 0.5;        // elastic
  const HillPlaneStressLaw* law = nullptr;  // viscous (not owned)
  // Planar anisotropy (not owned; null: the law's normal anisotropy). The yield function in
  // material axes replaces the law's A; the scalar flow law (hardening, rate, cut-off) stays the
  // law's. RD per flow point: Shell9Operators::FlowRow::rd_cos (needs material axes in the
  // geometry).
  const PlanarAnisotropy* planar = nullptr;
  double shear_viscosity = 0.0;  // viscous: transverse-shear penalty viscosity
  double shear_correction = kShellShearCorrection;
  // Artificial drilling stiffness at 6-dof nodes: drill_scale * G_ref * h_a * (element area) / 9
  // for each such node (G_ref = G or shear_viscosity).
  double drill_scale = 1e-3;

  static Shell9Material Elastic(double young, double poisson);
  static Shell9Material Viscous(const HillPlaneStressLaw& law, double shear_viscosity);
  double shear_reference() const;
};

// Primal-dual tangent (material/flow_direction.h, here with the 3-component Hill law): at every
// flow point the flow direction m = A d / (3 eh) is replaced in the rank-one part of the tangent
// by a dual unknown n,
//   D(n) = mu A + w 3 eh c sym(n (A d)^T),          c = tangent coefficient, w = tangent weight,
// (n = m: the consistent tangent; n = 0: the secant matrix of the direct iteration). n follows
// from the linearised dual equation 3 eh n - A d = 0 about an earlier evaluation ("anchor", with
// rate d_a, direction m_a, cut-off rate eh_a and dual n_a), with dd = d - d_a the rate change of
// the point (d is linear in the element velocities while the geometry is fixed):
//   n_full = m_a + (A dd / 3 - n_a (m_a . dd)) / eh_a,
// and n = n_full scaled back onto the ball |n|_* = sqrt(3 n^T A^-1 n) <= 1 (|m|_* = e / eh < 1).
// D(n) is positive semi-definite for |n|_*, |m|_* <= 1 (flow_direction.h). Without an anchor
// n = 0; the caller may also prescribe n (dual_given: a damped step of the duals).
// Yld2000-2d (no closed-form dual, M = 3 T^T H T per point from the local solve, a = M d = 3 e m,
// dual_potential.h): the proof of flow_direction.h holds in the metric of the point's own M, so
// n (given or linearised) is also scaled into the ellipsoid 3 n^T M^-1 n <= 1. In material axes
// (y = T x, n_m = T^-T n) and with c = -f / (9 eh^3) (the rate-independent part; the hardening
// part only adds (hv/3) M):
//   x^T D x = (f / eh) [y^T H y - w (e / eh) (y . n_m)(y . m)],
// and by Cauchy-Schwarz in the H metric |y . v| <= sqrt(y^T H y) sqrt(v^T H^-1 v), where
// H^-1 = K(m) = n(m) n(m)^T + sigma_bar d^2sigma_bar/ds^2 (m) (dual_potential.h) gives
// m^T K m = 1 and n_m^T K n_m = 3 n^T M^-1 n: D(n) >= 0 for w <= 1 inside the ellipsoid. The
// unit ball sigma_bar(n) <= 1 is not inside it for a non-quadratic criterion: sigma_bar^2 / 2
// curves less away from m than its Hessian K(m) at m, most at a sharply curved m (a = 8, the
// equibiaxial point: n^T K(m) n up to 5 on the unit ball), and there D(n) was indefinite (the
// r45 0.292, r90 0.724 cup of experiments/10_earing: points with 3 n^T M^-1 n = 3.1-3.3, an
// indefinite Newton matrix, an ascent step, and a first step that cycled for 100 iterations).
// The consistent dual n = (e / eh) m lies inside (3 n^T M^-1 n = (e / eh)^2), so Newton's
// tangent is unchanged; for Hill 1948 the ellipsoid is the ball itself.
struct Shell9FlowDirection {
  Vec3 d = Vec3::Zero();       // in-plane rate of the evaluation
  Vec3 m = Vec3::Zero();       // its flow direction A d / (3 eh) (0 for a constant viscosity)
  Vec3 n = Vec3::Zero();       // the dual its tangent used
  Vec3 n_full = Vec3::Zero();  // n before the scaling onto the ball
  double eh = 0.0;             // cut-off rate sqrt(e^2 + e_c^2)
};

// Per flow point state (viscous only), index = in-plane point * n_thickness + thickness point.
// Null pointers mean 0. With dual_record set, a kTangent evaluation uses the primal-dual tangent
// (n = dual_given if set, else from dual_anchor if set, else 0) and writes every flow point's
// record there.
struct Shell9State {
  const double* sigma_y = nullptr;
  const double* hardening_viscosity = nullptr;
  const Shell9FlowDirection* dual_anchor = nullptr;
  const Vec3* dual_given = nullptr;
  Shell9FlowDirection* dual_record = nullptr;
  // Through-thickness normal stress sigma_33 = -p(zeta) (material/normal_stress.h): the face
  // pressures at each in-plane point (lower face = t = -1, opposite to e3); null: plane stress.
  const FacePressure* face_pressure = nullptr;
  // Planar anisotropy without a closed-form dual (Yld2000-2d): per flow point the unit-surface
  // stress m (material axes) of the point's last evaluation, the warm start of its local solve,
  // overwritten with the new one (zero: no start yet). Null: every solve starts cold.
  PlaneVector* flow_guess = nullptr;
};

enum class Shell9Stiffness { kSecant, kTangent, kNone };

struct Shell9Resultant {
  // Sums over the thickness of the point stresses, each projected from its own frame (e1 along
  // g_r(t), which turns with t on a curved, twisted element) onto `frame`: tensors, independent
  // of the element's parametrisation.
  Vec3 N = Vec3::Zero();          // membrane forces (N11, N22, N12) [N/mm], local frame
  Vec3 M = Vec3::Zero();          // moments int s z dz [N], z along e3
  Mat3 frame = Mat3::Identity();  // local frame (columns e1, e2, e3) at the mid-surface
};

struct Shell9Output {
  Eigen::VectorXd force;           // internal nodal forces, element dofs
  Eigen::MatrixXd stiffness;       // secant or tangent
  double potential = 0.0;          // integral of the power potential (elastic: strain energy)
  std::vector<double> point_rate;  // effective rate at each flow point (viscous)
  std::vector<Shell9Resultant> resultant;  // at each in-plane (flow) point
};

// Number of in-plane points of the flow (membrane/bending) rule: 9, or 4 for kReduced.
int shell9_inplane_points(Shell9Rule rule);

// The velocity-independent part of an element evaluation in one configuration: the in-plane
// strain-rate operators of all flow points stacked as the rows of L (local frame, 3 rows per flow
// point; B(t) = B0 + t B1 + t^2 B2, MITC9 tying, basis), their volume and resultant weights, the
// transverse-shear Gram matrix and the drilling terms. A nonlinear solve evaluates one
// configuration many times: building this once per configuration (shell9_operators) and
// evaluating with it (about 45 KB per MITC9 element with 3 thickness points) leaves per
// evaluation only L q, the point laws, L^T (row forces), the shear Gram matrix times q and, for a
// matrix, L^T (D L).
//
// Transverse shear is linear with a viscosity Gs that is constant within a solve (the element's
// penalty viscosity, or k G), so its rows never need the point laws: with gamma = B_s q at a shear
// point of volume weight dV, the power sum_s Gs dV |gamma|^2 / 2 = Gs q^T S q / 2 with
// S = sum_s dV B_s^T B_s, its force Gs S q and its matrix Gs S. S replaces the shear rows (2 per
// shear point and thickness point, 40 % of L's rows for MITC9): the element's matrix product runs
// over the flow rows only.
struct Shell9Operators {
  struct FlowRow {  // a flow point (index in Shell9State arrays = position in `flow`)
    int row = 0;    // its 3 in-plane rows start here
    int point = 0;  // in-plane point (resultants)
    double dV = 0.0, dz = 0.0, arm = 0.0;  // volume weight; h/2 dt and z dz (resultants)
    double zeta = 0.0;                     // z / h = t / 2 of the thickness point
    // Planar anisotropy: RD at the angle a from the point's e1, (cos a, sin a) (RD along e1
    // without material axes).
    double rd_cos = 1.0, rd_sin = 0.0;
    // Resultants: the point's in-plane axes (e1, e2) in the mid-surface frame (E1, E2) of its
    // in-plane point, P = [[E1.e1, E1.e2], [E2.e1, E2.e2]] row by row: the stress S of the point
    // enters the sums as P S P^T (the projection of the tensor onto the mid-surface frame).
    bool turned = false;  // P != I
    std::array<double, 4> to_mid{1.0, 0.0, 0.0, 1.0};
  };
  struct DrillNode {
    int offset = 0;  // the node's rotation dofs
    Vec3 director = Vec3::UnitZ();
    double thickness_area = 0.0;  // h_a (element area) / 9
  };
  int ndof = 0, inplane_points = 0;
  Eigen::MatrixXd L;           // 3 rows per flow point
  Eigen::MatrixXd shear_gram;  // S = sum_s dV B_s^T B_s (ndof x ndof, symmetric, both halves)
  std::vector<FlowRow> flow;
  std::vector<Mat3> frame;  // local frame on the mid-surface (t = 0) at each in-plane point
  std::vector<std::array<double, 9>> shape;  // shape functions N_a at each in-plane point
  std::vector<DrillNode> drill;
};

void shell9_operators(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                      Shell9Operators* ops);

// Substitutes u = u' - C r for the velocity columns u (3, from `velocity`) of a node in terms of
// new unknowns u' and its rotation columns r (2, from `rotation`): the operators of the element
// in the unknowns (u', r), L T and T^T S T with T = I except the block -C at (velocity, rotation).
// (FormingModel's face coupling: a node's velocity unknowns are its touching face's.)
void shell9_substitute_velocity(int velocity, int rotation, const Eigen::Matrix<double, 3, 2>& C,
                                Shell9Operators* ops);

// Evaluates the element at element velocities q (size ops.ndof).
//
// `next`, if given, is the operators of the element the caller evaluates next: the loop over the
// flow points asks the memory system for its L and S a slice at a time, so that its first L q
// finds them in cache. A residual evaluation of a large mesh streams every element's operators
// from memory (about 45 KB for MITC9 with 3 thickness points, 35 MB at 768 elements); without the
// hint the first L q of an element waits on it, 3.7 us against 0.9 us with it (16-division
// quarter disc, one thread, measured with L alone). It changes no result.
void shell9_evaluate(const Shell9Operators& ops, const Shell9Material& mat,
                     const Shell9State& state, const Eigen::VectorXd& q, Shell9Stiffness kind,
                     Shell9Output* out, double tangent_weight = 1.0,
                     const Shell9Operators* next = nullptr);

// The same, building the operators of g first.
void shell9_evaluate(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                     const Shell9Material& mat, const Shell9State& state, const Eigen::VectorXd& q,
                     Shell9Stiffness kind, Shell9Output* out, double tangent_weight = 1.0);

// Squared dual norm of a flow direction n at flow point fr (the ball |n|_* <= 1 of the
// primal-dual tangent): 3 n^T A^-1 n with the point's A (Hill 1948), or sigma_bar(n)^2 in the
// material axes of the point (Yld2000-2d).
double shell9_dual_norm_squared(const Shell9Material& mat, const Shell9Operators::FlowRow& fr,
                                const Vec3& n);

// Mid-surface area of the element (3x3 Gauss).
double shell9_area(const Shell9Geometry& g);

// Membrane initial-stress (geometric) stiffness for an implicit geometry update, per pair of
// nodes (the same for each of the 3 velocity components, global frame):
//   k(a, b) = sum_p dA_p (grad N_a)^T N+_p (grad N_b),
// over the in-plane points p of `rule` on the mid-surface (the order of Shell9Output::resultant),
// grad in the local frame e1 = g_r / |g_r|, e2 = e3 x e1 of the point, N+_p the tensile part of
// the membrane force tensor [[N11, N12], [N12, N22]] of `membrane` (N/mm, one Vec3 per point).
// Dropping the compressive part keeps k positive semi-definite (see axisym2_stress_stiffness).
Eigen::Matrix<double, 9, 9> shell9_stress_stiffness(const Shell9Geometry& g, Shell9Rule rule,
                                                    const std::vector<Vec3>& membrane);
// The same with the membrane force tensors in global axes (3x3, N/mm, one per point), projected
// onto the point's tangent plane, N_ab = e_a . N e_b: independent of the element's parametrisation
// and of the configuration the tensors come from (the local components of another configuration
// are relative to its frame e1 = g_r / |g_r|, which turns with the r-line of the element, not with
// the s-line: mirror-image elements would see different tensors).
Eigen::Matrix<double, 9, 9> shell9_stress_stiffness(const Shell9Geometry& g, Shell9Rule rule,
                                                    const std::vector<Mat3>& membrane);

}  // namespace vs::shell3d
