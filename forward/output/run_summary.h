// The handful of numbers a person wants after a run (peak force, final thinning...), computed
// once for the CLI summary and the run manifest.
#pragma once

#include <string>

#include "run/run_result.h"

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
  double final_thinnest_r0_mm = 0.0;
  double total_time_s = 0.0;  // RunTimings::total_s
};

const char* termination_name(Termination termination);

RunSummary summarize_run(const RunResult& result);

// Multi-line, human-readable report for the terminal (no trailing newline), e.g.
//   termination       completed
//   steps             120 (480 iterations, 0 cut-backs)
//   peak punch force  41.2 kN at 18.4 mm travel
std::string summary_report(const RunSummary& summary);

}  // namespace vs
