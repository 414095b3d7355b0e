// What a forward run returns, for both geometries: per-step scalars, strain profiles at the
// requested travels, optional full history (axisymmetric), the nodal fields of the 3D sheet at
// the output travels, termination, what was built, and timings. Plain data; writers live in
// output/.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "mesh/shell_mesh.h"
#include "scene/scene.h"

namespace vs {

// One converged step.
struct StepRecord {
  int step = 0;
  double time_s = 0.0;
  double punch_travel_mm = 0.0;
  double punch_force_N = 0.0;     // full 360-degree force the punch exerts on the sheet (+z)
  int iterations = 0;             // nonlinear iterations of the accepted solve
  double residual_norm = 0.0;     // final relative residual
  double update_norm = 0.0;       // final relative velocity change (paper eq. 12)
  int contact_nodes = 0;          // nodes in contact with any tool
  int cutbacks = 0;               // step halvings before this step converged
  double min_thickness_mm = 0.0;  // thinnest element
  double thinnest_r0_mm = 0.0;    // its initial radius (element midpoint)
  double thinnest_r_mm = 0.0;     // its current radius
  double volume_mm3 = 0.0;        // sheet volume (constant up to round-off)
  double rim_draw_in_mm = 0.0;    // initial minus current rim radius
};

// Fields along one line of the sheet at one instant: the meridian of an axisymmetric run
// (element midpoints), or a line through the centre of a 3D blank (nodes; the forces are empty
// there).
struct Profile {
  double punch_travel_mm = 0.0;
  // "meridian" (axisymmetric); 3D: "x" (along the x axis, y = 0), "y" (x = 0), "diagonal"
  // (x = y), and for a full blank also "x_neg", "y_neg", "diagonal_neg" (the other halves).
  std::string line = "meridian";
  std::vector<double> r0_mm;  // initial radius of the element midpoint
  std::vector<double> r_mm;   // current radius
  std::vector<double> z_mm;   // current height
  std::vector<double> thickness_mm;
  std::vector<double> eps_meridional;       // ln(l / l0)
  std::vector<double> eps_circumferential;  // ln(r / r0)
  std::vector<double> eps_thickness;        // ln(h / h0)
  std::vector<double> eps_effective;        // accumulated effective plastic strain (mid-surface)
  std::vector<int> contact;                 // 0 free, 1 touching a tool at either node
  std::vector<double> meridional_force_N_per_mm;       // N_s = integral of sigma_s over h
  std::vector<double> circumferential_force_N_per_mm;  // N_t
  // Axial force carried through the circle at the element midpoint, -2 pi r (N_s t_z + Q n_z):
  // in the unsupported region it equals the punch force (exact equilibrium check).
  std::vector<double> vertical_force_N;
  // Axial force of the punch on each node (their sum is the punch force; empty if unknown): the
  // force through a circle equals the punch force on the nodes inside it when no other tool
  // touches them, also once a cup wall outside the circle is ironed against the punch.
  std::vector<double> punch_force_node_N;
  std::vector<double> node_r_mm;  // deformed shape: nodes of the meridian
  std::vector<double> node_z_mm;
};

enum class Termination {
  kCompleted,  // reached the total punch travel
  kFailed,     // stopped early; message says why; everything up to the last step is kept
};

struct RunTimings {
  double total_s = 0.0;
  double assembly_s = 0.0;      // element loops: matrices, residuals, potentials
  double linear_solve_s = 0.0;  // factorisations and triangular solves (axisymmetric: the solves)
  double contact_s = 0.0;       // contact search, projection and the contact-event step
  int factorisations = 0;       // numeric factorisations (3D)
  int krylov_steps = 0;         // Newton steps solved by preconditioned CG (solver/newton.h)
  int krylov_iterations = 0;    // their CG iterations (and those of failed attempts)
  // Factorisations CHOLMOD refused as not positive definite, done by the LDL^T fallback (3D).
  int factorisation_fallbacks = 0;
};

// The 3D sheet at one instant (nodal fields of the meshed part).
struct ShellStage {
  double punch_travel_mm = 0.0;
  std::vector<Eigen::Vector3d> x;     // mid-surface nodes [mm]
  std::vector<double> thickness_mm;   // per node
  std::vector<int> contact_tool;      // per node: tool index, -1 free
  std::vector<double> eps_effective;  // per element: mean over its mid-thickness flow points
  // Per element, mean over its mid-thickness flow points of the effective (Hill) stress of the
  // viscous law at the point's accumulated strain and current effective rate [MPa]: the flow
  // stress where the sheet deforms, less in the nearly rigid regions (rate cut-off).
  std::vector<double> effective_stress_MPa;
};

// What only a 3D run has: its initial mesh, the sheet at zero travel and at the output travels
// and the end.
struct ShellFields {
  shell3d::ShellMesh mesh;  // the meshed part: quarter or full blank
  // The first converged state, at zero travel (the initial blank with its first flow; empty x
  // when the run failed before it).
  ShellStage initial;
  std::vector<ShellStage> stages;  // at the output travels reached, then the end
};

struct RunResult {
  Geometry geometry = Geometry::kAxisymmetric;
  // What the solver built for this scene, one line each (model, unknowns, linear solver,
  // contact and friction terms, blank holder, ...), for run.json.
  std::vector<std::string> built;
  int dofs = 0;
  std::vector<StepRecord> steps;
  // At process.output_travels_mm (in that order) and the end; 3D: one per line at each of
  // those travels, the lines in the order of Profile::line.
  std::vector<Profile> profiles;
  std::vector<Profile> history;  // every step, if output.history
  Termination termination = Termination::kCompleted;
  std::string message;
  std::vector<std::string> warnings;  // trust caveats (e.g. elements shorter than the thickness)
  int total_iterations = 0;
  // Implicit update: Newton iterations of the k-th velocity solve of a step (k = 0, 1, ..;
  // numerics.implicit_solves), summed over every step tried (the last contact round of
  // each solve). total_iterations counts only the last solve of each accepted step.
  std::vector<int> implicit_solve_iterations;
  // The velocity solves per implicit step as run (numerics.implicit_solves, resolved where the
  // scene leaves it to the model's size); 0 for a run that did not get to build its model.
  int implicit_solves = 0;
  int total_cutbacks = 0;
  // Solves whose Newton iteration with friction consistent with the current normal reactions did
  // not converge and that were redone with lagged reactions (see simulate.cc).
  int friction_fallbacks = 0;
  // Largest conditioning estimate of the Newton matrices of the accepted solves (a lower bound
  // of their 2-norm condition numbers: squared ratio of the Cholesky pivots).
  double max_condition_estimate = 1.0;
  RunTimings timings;
  std::shared_ptr<const ShellFields> shell;  // 3D runs only
  bool completed() const { return termination == Termination::kCompleted; }
};

}  // namespace vs
