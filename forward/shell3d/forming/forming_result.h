// What a 3D forming run returns: per-step scalars (the axisymmetric StepRecord, so the existing
// load-travel stream and progress line apply), nodal snapshots at the output travels and at the
// end, termination and timings. Plain data; derived fields (strains, profiles) in
// forming_fields.h, files in forming_writer.h.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "shell3d/shell_mesh.h"

namespace vs::shell3d {

// The sheet at one instant.
struct ShellStage {
  double punch_travel_mm = 0.0;
  std::vector<Eigen::Vector3d> x;     // mid-surface nodes [mm]
  std::vector<double> thickness_mm;   // per node
  std::vector<int> contact_tool;      // per node: tool index, -1 free
  std::vector<double> eps_effective;  // per element: mean over its mid-thickness flow points
};

struct Shell3dTimings {
  double total_s = 0.0;
  double assembly_s = 0.0;       // element loops (matrix, residual, line-search potentials)
  double factorisation_s = 0.0;  // sparse Cholesky analysis, factorisations and solves
  double contact_s = 0.0;        // contact search, projection and the contact-event step
  int factorisations = 0;
};

struct Shell3dResult {
  ShellMesh mesh;  // initial mesh (the meshed part: quarter or full blank)
  std::vector<std::string> tool_names;
  std::vector<StepRecord> steps;
  std::vector<ShellStage> stages;  // at process.output_travels_mm reached, then the last state
  Termination termination = Termination::kCompleted;
  std::string message;
  std::vector<std::string> warnings;
  int total_iterations = 0;
  int total_cutbacks = 0;
  int dofs = 0;
  Shell3dTimings timings;
  bool completed() const { return termination == Termination::kCompleted; }
};

}  // namespace vs::shell3d
