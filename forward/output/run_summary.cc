#include "output/run_summary.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace vs {

const char* termination_name(Termination termination) {
  switch (termination) {
    case Termination::kCompleted:
      return "completed";
    case Termination::kFailed:
      return "failed";
  }
  return "unknown";
}

RunSummary summarize_run(const RunResult& result) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  RunSummary s;
  s.completed = result.completed();
  s.termination = termination_name(result.termination);
  s.message = result.message;
  s.steps = static_cast<int>(result.steps.size());
  s.total_iterations = result.total_iterations;
  s.total_cutbacks = result.total_cutbacks;
  s.friction_fallbacks = result.friction_fallbacks;
  s.total_time_s = result.timings.total_s;
  s.final_punch_travel_mm = kNaN;
  s.peak_punch_force_N = kNaN;
  s.punch_travel_at_peak_mm = kNaN;
  s.final_min_thickness_mm = kNaN;
  s.final_thinnest_r0_mm = kNaN;
  if (result.steps.empty()) return s;
  const StepRecord& last = result.steps.back();
  s.final_punch_travel_mm = last.punch_travel_mm;
  s.final_min_thickness_mm = last.min_thickness_mm;
  s.final_thinnest_r0_mm = last.thinnest_r0_mm;
  // First occurrence of the maximum, so a force plateau reports where it was first reached.
  for (const StepRecord& r : result.steps) {
    if (std::isnan(s.peak_punch_force_N) || r.punch_force_N > s.peak_punch_force_N) {
      s.peak_punch_force_N = r.punch_force_N;
      s.punch_travel_at_peak_mm = r.punch_travel_mm;
    }
  }
  return s;
}

std::string summary_report(const RunSummary& s) {
  std::string out = fmt::format("termination       {}", s.termination);
  if (!s.message.empty()) out += fmt::format("\nmessage           {}", s.message);
  out += fmt::format("\nsteps             {} ({} iterations, {} cut-backs)", s.steps,
                     s.total_iterations, s.total_cutbacks);
  if (s.friction_fallbacks > 0) {
    out += fmt::format("\nfriction re-solves {} (solves redone with lagged normal reactions)",
                       s.friction_fallbacks);
  }
  if (s.steps > 0) {
    out += fmt::format("\nfinal travel      {:.3f} mm", s.final_punch_travel_mm);
    out += fmt::format("\npeak punch force  {:.4g} kN at {:.3f} mm travel",
                       s.peak_punch_force_N / 1000.0, s.punch_travel_at_peak_mm);
    out += fmt::format("\nmin thickness     {:.4f} mm at r0 {:.3f} mm", s.final_min_thickness_mm,
                       s.final_thinnest_r0_mm);
  }
  out += fmt::format("\nsolver time       {:.2f} s", s.total_time_s);
  return out;
}

}  // namespace vs
