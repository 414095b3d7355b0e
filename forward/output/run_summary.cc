#include "output/run_summary.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "output/fld.h"
#include "output/forming_limit.h"
#include "output/suspect_results.h"

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
  s.final_thinnest_x0_mm = kNaN;
  s.final_thinnest_y0_mm = kNaN;
  s.final_thinning_percent = kNaN;
  s.shell3d = result.geometry == Geometry::kShell3d;
  s.flc_min_margin = s.flc_min_x0_mm = s.flc_min_y0_mm = s.flc_min_r0_mm = kNaN;
  s.flc_min_eps_major = s.flc_min_eps_minor = kNaN;
  s.warnings = result.warnings;
  if (result.steps.empty()) return s;
  const StepRecord& last = result.steps.back();
  s.final_punch_travel_mm = last.punch_travel_mm;
  s.final_min_thickness_mm = last.min_thickness_mm;
  s.final_thinnest_r0_mm = last.thinnest_r0_mm;
  if (!s.shell3d) {
    s.final_thinnest_x0_mm = last.thinnest_r0_mm;
    s.final_thinnest_y0_mm = 0.0;
  } else if (result.shell && !result.shell->stages.empty()) {
    // The thinnest node of the final stage (the state of the last step record: the first of
    // equal minima, as the record takes it).
    const ShellStage& st = result.shell->stages.back();
    std::size_t thinnest = 0;
    for (std::size_t i = 1; i < st.thickness_mm.size(); ++i) {
      if (st.thickness_mm[i] < st.thickness_mm[thinnest]) thinnest = i;
    }
    if (thinnest < result.shell->mesh.nodes.size()) {
      s.final_thinnest_x0_mm = result.shell->mesh.nodes[thinnest].x();
      s.final_thinnest_y0_mm = result.shell->mesh.nodes[thinnest].y();
    }
  }
  // First occurrence of the maximum, so a force plateau reports where it was first reached.
  for (const StepRecord& r : result.steps) {
    if (std::isnan(s.peak_punch_force_N) || r.punch_force_N > s.peak_punch_force_N) {
      s.peak_punch_force_N = r.punch_force_N;
      s.punch_travel_at_peak_mm = r.punch_travel_mm;
    }
  }
  return s;
}

RunSummary summarize_run(const Scene& scene, const RunResult& result) {
  RunSummary s = summarize_run(result);
  s.final_thinning_percent = 100.0 * (1.0 - s.final_min_thickness_mm / scene.blank.thickness_mm);
  const FormingLimitCurve flc = forming_limit_curve(scene);
  s.flc_description = flc.description();
  for (const std::string& w : flc.warnings) s.warnings.push_back(w);
  for (const std::string& w : suspect_result_warnings(result)) s.warnings.push_back(w);
  std::vector<FldPoint> points = fld_points(result);
  apply_forming_limit(flc, &points);
  for (const FldPoint& p : points) {
    if (p.zone == FormingZone::kUnknown) continue;
    ++s.flc_elements;
    s.flc_failed_elements += p.zone == FormingZone::kFailed ? 1 : 0;
    s.flc_marginal_elements += p.zone == FormingZone::kMarginal ? 1 : 0;
  }
  if (const FldPoint* p = least_margin_point(points)) {
    s.flc_min_margin = p->flc_margin;
    s.flc_min_zone = forming_zone_name(p->zone);
    s.flc_min_element = static_cast<int>(p->element);
    s.flc_min_x0_mm = p->x0_mm;
    s.flc_min_y0_mm = p->y0_mm;
    s.flc_min_r0_mm = p->r0_mm;
    s.flc_min_eps_major = p->eps_major;
    s.flc_min_eps_minor = p->eps_minor;
  }
  s.cup_profile = cup_profile_report(scene, result);
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
    const std::string thinning =
        std::isnan(s.final_thinning_percent)
            ? std::string()
            : fmt::format(" (thinning {:.1f} %)", s.final_thinning_percent);
    const std::string where =
        s.shell3d ? fmt::format("x0 {:.3f} mm, y0 {:.3f} mm (r0 {:.3f} mm)", s.final_thinnest_x0_mm,
                                s.final_thinnest_y0_mm, s.final_thinnest_r0_mm)
                  : fmt::format("r0 {:.3f} mm", s.final_thinnest_r0_mm);
    out += fmt::format("\nmin thickness     {:.4f} mm{} at {}", s.final_min_thickness_mm, thinning,
                       where);
  }
  if (s.flc_description != "none") {
    if (std::isnan(s.flc_min_margin)) {
      out += "\nFLC margin        no element strains";
    } else {
      const std::string at =
          s.shell3d ? fmt::format("x0 {:.3f} mm, y0 {:.3f} mm", s.flc_min_x0_mm, s.flc_min_y0_mm)
                    : fmt::format("r0 {:.3f} mm", s.flc_min_r0_mm);
      out += fmt::format(
          "\nFLC margin        {:.4f} ({}) at element {}, {} (major {:.4f}, minor {:.4f}); "
          "{} failed, {} marginal of {} elements",
          s.flc_min_margin, s.flc_min_zone, s.flc_min_element, at, s.flc_min_eps_major,
          s.flc_min_eps_minor, s.flc_failed_elements, s.flc_marginal_elements, s.flc_elements);
    }
    out += fmt::format("\nFLC               {}", s.flc_description);
  }
  const std::string cup = cup_profile_report_text(s.cup_profile);
  if (!cup.empty()) out += "\n" + cup;
  out += fmt::format("\nsolver time       {:.2f} s", s.total_time_s);
  return out;
}

}  // namespace vs
