// Scene: plain data describing one simulation. Built only by load_scene() (scene/load_scene.h),
// which applies the declared defaults, checks types and ranges and rejects unknown keys.
// Every key is documented in docs/scene-reference.md. Units: mm, N, s, MPa.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace vs {

enum class Geometry {
  kAxisymmetric,  // meridian of a circular blank, 2-node conical shell elements (vs::simulate)
  kShell3d,       // general 3D viscous shell, 9-node elements (vs::shell3d::simulate_shell3d)
};

// Outline of a 3D blank (geometry = shell3d).
enum class BlankShape {
  kCircle,  // circle of radius blank.radius_mm
  kSquare,  // square of half side blank.radius_mm, centred on the punch axis
};

// Part of the blank a 3D model meshes (geometry = shell3d).
enum class BlankSymmetry {
  kQuarter,  // x >= 0, y >= 0 with symmetry planes x = 0 and y = 0; forces reported x 4
  kFull,     // the whole blank, no symmetry planes
};

// Boundary condition at the outer rim of the blank.
enum class EdgeCondition {
  kPinned,   // radial and axial velocity zero, rotation free (paper example 1)
  kClamped,  // radial, axial velocity and rotation zero
  kFree,     // nothing prescribed: the rim may draw in over the die (paper examples 2, 3)
};

struct BlankSpec {
  double radius_mm = 50.0;    // initial outer radius
  double thickness_mm = 1.0;  // initial thickness
  int elements = 50;          // number of 2-node elements along the meridian
  double grading = 1.0;       // length ratio last/first element (geometric grading), > 0
  EdgeCondition edge = EdgeCondition::kPinned;
  // geometry = shell3d only:
  BlankShape shape = BlankShape::kCircle;
  BlankSymmetry symmetry = BlankSymmetry::kQuarter;
  int divisions = 8;  // 9-node elements along each edge of each structured block
  // Circle: 9-node elements across the ring from the central square to the rim (the curved
  // blocks' radial count); 0 (not set): divisions. Read it through ring_divisions().
  int radial_divisions = 0;
  int ring_divisions() const { return radial_divisions > 0 ? radial_divisions : divisions; }
};

enum class HardeningLaw {
  kSwift,     // sigma = K (eps0 + eps)^n
  kHollomon,  // sigma = max(sigma0, K eps^n): Hollomon with an initial yield plateau
  kVoce,      // sigma = sigma0 + Q (1 - exp(-b eps))
  kTable,     // piecewise linear (eps, sigma) times scale; last slope extrapolated
};

struct HardeningSpec {
  HardeningLaw law = HardeningLaw::kSwift;
  double K_MPa = 500.0;                  // Swift, Hollomon strength coefficient
  double eps0 = 0.01;                    // Swift pre-strain
  double n = 0.2;                        // Swift, Hollomon hardening exponent
  double sigma0_MPa = 200.0;             // Hollomon initial yield, Voce initial yield
  double Q_MPa = 100.0;                  // Voce saturation increment
  double b = 10.0;                       // Voce rate
  std::vector<double> table_strain;      // kTable: effective plastic strain, strictly increasing
  std::vector<double> table_stress_MPa;  // kTable: flow stress, > 0
  double table_scale = 1.0;              // kTable: multiplies every stress (calibration handle)
};

enum class RateLaw {
  kNone,     // rate independent: sigma_bar = sigma_y(eps_bar)
  kPerzyna,  // paper eq. (7): sigma_bar = sigma_y + (eps_dot / gamma)^(1/exponent)
  kPower,    // sigma_bar = sigma_y (eps_dot / reference_rate)^m
};

struct RateSpec {
  RateLaw law = RateLaw::kNone;
  double gamma_per_s = 1.0;           // Perzyna fluidity
  double exponent = 1.0;              // Perzyna exponent (not the hardening n)
  double m = 0.01;                    // power-law rate sensitivity
  double reference_rate_per_s = 1.0;  // power-law reference strain rate
};

// Planar anisotropy ([material.anisotropy], shell3d only). The yield function is normalised to
// the uniaxial yield stress along RD, so the hardening curve is the RD tensile curve; stresses
// are ratios to it (material/planar_anisotropy.h).
enum class AnisotropyModel {
  kNormal,        // Hill 1948 with planar isotropy: material.r_value (no planar anisotropy)
  kHill48R,       // Hill 1948 from r0, r45, r90
  kHill48Stress,  // Hill 1948 from sigma45, sigma90, sigma_b (ratios to sigma0)
  kYld2000,       // Barlat Yld2000-2d from the eight data and the exponent
};

struct AnisotropySpec {
  AnisotropyModel model = AnisotropyModel::kNormal;
  double rolling_direction_deg = 0.0;  // angle of RD from the x axis, counter-clockwise
  double r0 = 1.0, r45 = 1.0, r90 = 1.0;
  double sigma45_ratio = 1.0, sigma90_ratio = 1.0, sigma_b_ratio = 1.0;
  double r_b = 1.0;       // Yld2000-2d: d22 / d11 in equibiaxial tension
  double exponent = 8.0;  // Yld2000-2d: 8 for aluminium (FCC), 6 for steel (BCC)
  bool planar() const { return model != AnisotropyModel::kNormal; }
};

// Isotropic elasticity ([material.elastic], both geometries): a first-order correction of the
// rigid-plastic flow formulation, not an elastic-plastic solver (material/elastic_start.h).
enum class ElasticLaw {
  kNone,       // rigid-(visco)plastic: no elasticity (the default)
  kIsotropic,  // Hooke's law with E_MPa and nu
};

struct ElasticSpec {
  ElasticLaw law = ElasticLaw::kNone;
  double E_MPa = 210000.0;  // Young's modulus (required with kIsotropic)
  double nu = 0.3;          // Poisson's ratio, in (-1, 0.5) (required with kIsotropic)
  // The flow stress at accumulated strain e is the elastic-plastic secant curve
  // min(E e, sigma_y(e - sigma / E)) instead of sigma_y(e).
  bool start = true;
  // The reported thickness strains include the elastic part from the current stress.
  bool strains = true;
  bool on() const { return law != ElasticLaw::kNone; }
  bool start_on() const { return on() && start; }
  bool strains_on() const { return on() && strains; }
};

struct MaterialSpec {
  HardeningSpec hardening;
  RateSpec rate;
  AnisotropySpec anisotropy;
  ElasticSpec elastic;
  // Normal anisotropy (Lankford) R = width / thickness strain rate in uniaxial tension.
  // Hill 1948 with planar isotropy, normalised so that sigma_bar equals the in-plane uniaxial
  // flow stress: the hardening curve is the in-plane tensile curve for every R.
  double r_value = 1.0;
};

enum class ToolKind {
  kHemisphericalPunch,  // sphere of radius radius_mm, moves +z (into the sheet from below)
  kFlatPunch,           // flat face, nose radius profile_radius_mm, outer radius radius_mm
  kDie,                 // fixed, above the sheet: opening radius_mm, shoulder profile_radius_mm
  kBlankHolder,         // presses the flange against the die face with force_N
};

struct ToolSpec {
  std::string name;  // unique label used in outputs and calibration addresses
  ToolKind kind = ToolKind::kHemisphericalPunch;
  double radius_mm = 50.0;         // punch radius / die opening radius
  double profile_radius_mm = 5.0;  // flat-punch nose radius / die shoulder radius
  // Coulomb coefficient between this tool and the sheet; +infinity means sticking.
  double friction = 0.0;
  double force_N = 0.0;  // blank holder: total (360 degree) holding force, or
  double gap_mm = 0.0;   // blank holder: fixed gap to the die face (exactly one > 0)
  bool sticking() const { return friction == std::numeric_limits<double>::infinity(); }
};

struct ProcessSpec {
  double punch_travel_mm = 10.0;          // total punch travel
  double punch_speed_mm_per_s = 1.0;      // matters only for rate-sensitive materials
  std::vector<double> output_travels_mm;  // travels at which strain distributions are written
};

enum class SolverKind {
  kNewton,  // a few direct iterations, then Newton with a line search on the flow potential
  kPicard,  // the paper's direct (secant) iteration only
};

enum class TimeIntegration {
  kHeun,   // explicit trapezoidal predictor-corrector: two velocity solves per step, O(dt^2)
  kEuler,  // the paper's forward update with the start-of-step velocity: O(dt)
  // backward Euler in the geometry: the velocity solved in the end-of-step configuration, with
  // the configuration's dependence on the velocity in the solve (stable at any step)
  kImplicit,
};

// Through-thickness normal stress sigma_33 (experiments/08_continuum_reference, section 8).
enum class NormalStress {
  kNone,     // plane stress (sigma_33 = 0), the paper's shell
  kContact,  // sigma_33 = -p(zeta), linear from the contact pressure on each face to the other
};

// Where a tool's tangential contact (sticking, Coulomb friction) acts on the sheet (issue 15;
// docs/contact_face.md): the paper's shell holds the mid-surface, a continuum the face that
// touches the tool.
enum class FrictionSurface {
  kMid,   // the mid-surface velocity (the paper's shell)
  kFace,  // the touching face's velocity v + z dV3/dt (z = -/+ h/2), with the friction's moment
};

// Implicit update with two or more solves: in which solve a node that reaches a tool during the
// step first touches it (stepping/step_driver.h, take_implicit_step).
enum class ContactEntry {
  kFirstSolve,  // in the first solve's configuration (moved with the start velocity)
  kLastSolve,   // in the last solve's: free in the velocities that place the end configuration
};

// Strain evaluation of the 9-node shell (geometry = shell3d; forward/shell3d/shell9.h).
enum class ShellElementRule {
  kMitc9,           // MITC9 assumed covariant strains (Bucalem-Bathe): no membrane locking
  kPaperSelective,  // the paper's rule: in-plane 3x3, transverse shear 2x2
};

// The implicit update's default step cap in element lengths (a cap for accuracy: smooth and
// within 0.2 % in force on ex1; experiments/06_step_stability).
inline constexpr double kImplicitTravelIncrementPerLength = 0.25;
// The default start refinement of a shell3d scene with the implicit update (NumericsSpec).
inline constexpr int kShell3dImplicitStartRefinement = 3;
// NumericsSpec::implicit_solves of a shell3d scene that leaves the count to the model's size
// (not a value a scene file can give; stepping/step_driver.h, implicit_solves_for).
inline constexpr int kImplicitSolvesBySize = 0;

struct NumericsSpec {
  int thickness_points = 5;  // Simpson points through the thickness: 3, 5, 7 or 9
  SolverKind solver = SolverKind::kNewton;
  // A scene file without the key gets the implicit update (load_scene.cc,
  // apply_geometry_defaults). The struct's own default is the one for scenes built in code.
  TimeIntegration time_integration = TimeIntegration::kHeun;
  // Weight of the end-of-step velocity in the implicit update x_{n+1} = x_n + dt ((1 - theta)
  // v_n + theta v_{n+1}): 1/2 trapezoidal (second order), 1 backward Euler (first order, damps
  // the stiffest modes completely).
  double implicit_theta = 0.5;
  // Implicit update: velocity solves per step, each in the configuration moved with the previous
  // solve's velocity (the first: with the start velocity). 2: the trapezoidal update of
  // implicit_theta, second order; 1: the configuration moved with the start velocity and the one
  // solve's velocity carried into the next step (first order in the geometry, a stiff mode damped
  // only by |z|^2 = theta a / (1 + theta a), a = its rate times the step; step_driver.h).
  // kImplicitSolvesBySize: chosen by the model's size when the run builds it (a shell3d scene
  // file without the key; implicit_solves_for in stepping/step_driver.h).
  int implicit_solves = 2;
  // Implicit update with two or more solves: the solve in which new contacts enter (not those of
  // sticking tools, which always enter in the first; step_driver.h).
  ContactEntry contact_entry = ContactEntry::kFirstSolve;
  // Implicit update: end steps at contact events, as the explicit update must (false: a node that
  // reaches a tool within a step touches it within the step, in the solve of contact_entry).
  bool contact_events = true;
  double tolerance = 1e-6;                // relative velocity change and relative residual
  int max_iterations = 100;               // per step, before the step is cut back
  double step_fraction = 1.0;             // fraction of the contact-event step taken when far
  double max_travel_increment_mm = 0.25;  // cap on punch travel per step
  // Second cap on the travel per step, relative to the shortest initial element length. The
  // explicit (Heun) update needs it: above it the deformation mechanism of nearly rigid free
  // regions switches from step to step and outputs jitter by up to 1 %; the implicit update is
  // stable at any step, where this cap is for accuracy only (0.25 is smooth and within 0.2 % in
  // force on ex1; experiments/06_step_stability). A scene file without the key gets 0.25 with
  // the implicit update (kImplicitTravelIncrementPerLength), 0.025 with heun or euler (this
  // default; load_scene.cc, apply_geometry_defaults).
  double max_travel_increment_per_length = 0.025;
  // Levels of refinement of the start of the step grid: the first L grid increments are split
  // into 2^L, 2^(L-1), ..., 2 steps (travel_grid.h). A scene file without the key gets 3 for a
  // shell3d scene with the implicit update (its first contact events on a coarse grid), else 0
  // (load_scene.cc, apply_geometry_defaults).
  int start_refinement = 0;
  double max_strain_increment = 0.02;     // cap on effective strain increment per step
  double strain_rate_cutoff = 1e-4;       // cut-off rate, relative to punch_speed / blank radius
  double friction_regularisation = 1e-4;  // Coulomb arctan velocity, relative to punch speed
  int max_cutbacks = 8;                   // step halvings before the run stops
  // Factor on the transverse-shear penalty viscosity (the section's mid point at the nominal rate;
  // AxisymModel / FormingModel::freeze_material). A numerical choice, not a material constant:
  // experiments/08_continuum_reference, section 14.
  double transverse_shear_scale = 1.0;
  ShellElementRule element_rule = ShellElementRule::kMitc9;  // geometry = shell3d only
  NormalStress normal_stress = NormalStress::kNone;
  FrictionSurface friction_surface = FrictionSurface::kMid;
};

// Forming-limit curve (FLC) of the forming-limit diagram: outputs only (fld.svg, the margin per
// element in fld_points.csv and the 3D stages, run.json); the solver never reads it. Strains are
// true (logarithmic) strains, as in the FLD (output/forming_limit.h).
enum class FormingLimitModel {
  kKeelerBrazier,  // from the hardening exponent n and the thickness
  kTable,          // the user's points
  kNone,           // no curve
};

struct FormingLimitSpec {
  FormingLimitModel model = FormingLimitModel::kKeelerBrazier;
  std::vector<double> table_minor;  // kTable: minor true strain, strictly increasing
  std::vector<double> table_major;  // kTable: major true strain on the curve, > 0
  double safety_margin = 0.1;       // major true strain below the FLC counted as marginal
};

struct OutputSpec {
  std::string directory = "out";  // relative to the current working directory
  bool plots = true;              // write SVG plots
  bool history = true;            // keep per-step element strains (FLD paths, deformed stages)
  // geometry = shell3d: measured cup-height profile shown beside the computed one
  // (cup_profile.svg, run.json): the file (given relative to the scene file, stored resolved),
  // "" = none, and its points, read when the scene is loaded (scene/cup_profile_file.h).
  std::string measured_cup_profile;
  std::vector<double> measured_cup_angle_deg;  // angle from the rolling direction
  std::vector<double> measured_cup_height_mm;
};

struct Scene {
  std::string source;  // file the scene came from (for messages)
  std::string title;
  Geometry geometry = Geometry::kAxisymmetric;
  BlankSpec blank;
  MaterialSpec material;
  std::vector<ToolSpec> tools;
  ProcessSpec process;
  NumericsSpec numerics;
  FormingLimitSpec forming_limit;
  OutputSpec output;
};

}  // namespace vs
