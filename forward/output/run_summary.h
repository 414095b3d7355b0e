// The handful of numbers a person wants after a run (peak force, final thinning...), computed
// once for the CLI summary and the run manifest.
#pragma once

#include <string>
#include <vector>

#include "output/cup_profile_output.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct RunSummary {
  bool completed = false;
  std::string termination;  // "completed" | "failed"
  std::string message;
  int steps = 0;
  int total_iterations = 0;
  int total_cutbacks = 0;
  int friction_fallbacks = 0;
  // NaN when the run has no step.
  double final_punch_travel_mm = 0.0;
  double peak_punch_force_N = 0.0;
  double punch_travel_at_peak_mm = 0.0;
  double final_min_thickness_mm = 0.0;
  double final_thinning_percent = 0.0;  // 100 (1 - final_min_thickness_mm / h0), with a scene
  // Initial position of the finally thinnest point: r0 (both geometries), x0 and y0 (3D: the
  // thinnest node of the final stage; axisymmetric x0 = r0, y0 = 0).
  double final_thinnest_r0_mm = 0.0;
  double final_thinnest_x0_mm = 0.0;
  double final_thinnest_y0_mm = 0.0;
  double total_time_s = 0.0;  // RunTimings::total_s
  bool shell3d = false;
  // Forming-limit check of the final state (with a scene; flc_description "none" without a
  // curve, and the point fields NaN when no element has a margin).
  std::string flc_description = "none";
  double flc_min_margin = 0.0;  // smallest FLC margin (major true strain; < 0 beyond the FLC)
  std::string flc_min_zone = "none";
  int flc_min_element = -1;
  double flc_min_x0_mm = 0.0, flc_min_y0_mm = 0.0, flc_min_r0_mm = 0.0;
  double flc_min_eps_major = 0.0, flc_min_eps_minor = 0.0;
  int flc_failed_elements = 0, flc_marginal_elements = 0, flc_elements = 0;
  // Every warning of the run: RunResult::warnings, then those of the forming-limit curve and of
  // the load curve (suspect_results.h), with a scene.
  std::vector<std::string> warnings;
  // Cup-height (earing) profile of a 3D run with a free blank edge (with a scene).
  CupProfileReport cup_profile;
};

const char* termination_name(Termination termination);

RunSummary summarize_run(const RunResult& result);
// With the scene: also thinning, the forming-limit check and every warning.
RunSummary summarize_run(const Scene& scene, const RunResult& result);

// Multi-line, human-readable report for the terminal (no trailing newline), e.g.
//   termination       completed
//   steps             120 (480 iterations, 0 cut-backs)
//   peak punch force  41.2 kN at 18.4 mm travel
std::string summary_report(const RunSummary& summary);

}  // namespace vs
