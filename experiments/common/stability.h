// Stability checks of one forward run: convergence statistics and physical checks (volume,
// thickness > 0, punch force against the vertical force through circles of the free region) and
// a verdict: converged and sane, stopped with a message, or suspicious (garbage). Header-only.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness.h"
#include "metrics.h"
#include "output/suspect_results.h"

namespace vsx {

struct StabilityCase {
  std::string group;
  std::string name;
  std::string scene;  // bundled scene name
  Overrides ov;
};

struct StabilityRow {
  StabilityCase c;
  TimedRun run;
  double target_travel_mm = 0.0;
  double reached_mm = 0.0;
  double tolerance = 0.0;
  int steps = 0;
  double iter_per_step = kNaN;
  int max_iter = 0;
  int cutbacks = 0;
  int zero_steps = 0;           // accepted steps that did not advance the punch
  double worst_residual = 0.0;  // largest final relative residual of an accepted step
  double condition = kNaN;    // largest conditioning estimate (lower bound) of the Newton matrices
  double volume_drift = 0.0;  // max |V - V0| / V0
  double volume_drift_later = 0.0;    // the same from the first advanced step on
  double min_thickness_ratio = kNaN;  // min h / h0 over the run
  double equilibrium = kNaN;  // vs::free_wall_equilibrium_error, the largest over the outputs
  double peak_N = kNaN;
  double peak_travel_mm = kNaN;
  bool finite = true;
  std::vector<std::string> problems;  // why the result is not trustworthy (empty = fine)
  std::vector<std::string> warnings;  // harmless-looking departures from exactness
  std::string verdict;                // "ok", "ok*" (warnings), "stopped", "aborted", "GARBAGE"
};

inline StabilityRow evaluate_stability(const std::string& source_dir, const StabilityCase& c,
                                       double budget_s) {
  StabilityRow row;
  row.c = c;
  const vs::Scene scene = make_scene(scene_path(source_dir, c.scene), c.ov);
  row.target_travel_mm = scene.process.punch_travel_mm;
  row.tolerance = scene.numerics.tolerance;
  row.run = run_once(scene, budget_s);
  const vs::RunResult& r = row.run.result;
  row.steps = static_cast<int>(r.steps.size());
  row.reached_mm = final_travel(r);
  row.cutbacks = r.total_cutbacks;
  row.condition = r.max_condition_estimate;
  const Peak pk = peak_load(r);
  row.peak_N = pk.force_N;
  row.peak_travel_mm = pk.travel_mm;
  const double h0 = scene.blank.thickness_mm;
  double v0 = kNaN, v1 = kNaN, hmin = std::numeric_limits<double>::infinity();
  int iters = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const vs::StepRecord& s = r.steps[i];
    if (i == 0) v0 = s.volume_mm3;
    iters += s.iterations;
    row.max_iter = std::max(row.max_iter, s.iterations);
    row.worst_residual = std::max(row.worst_residual, s.residual_norm);
    row.volume_drift = std::max(row.volume_drift, std::abs(s.volume_mm3 - v0) / v0);
    if (i == 1) v1 = s.volume_mm3;
    if (i >= 1)
      row.volume_drift_later = std::max(row.volume_drift_later, std::abs(s.volume_mm3 - v1) / v1);
    hmin = std::min(hmin, s.min_thickness_mm);
    if (i > 0 && s.punch_travel_mm <= r.steps[i - 1].punch_travel_mm) ++row.zero_steps;
    for (double v : {s.punch_force_N, s.min_thickness_mm, s.volume_mm3, s.residual_norm}) {
      if (!std::isfinite(v)) row.finite = false;
    }
  }
  if (row.steps > 0) {
    row.iter_per_step = static_cast<double>(iters) / row.steps;
    row.min_thickness_ratio = hmin / h0;
  }
  row.equilibrium = vs::free_wall_equilibrium(r).error;

  // Verdict: a completed run must pass every check; a stopped run must say why.
  if (!row.finite) row.problems.push_back("non-finite values in the step records");
  if (row.steps > 0 && !(row.min_thickness_ratio > 0.0)) row.problems.push_back("thickness <= 0");
  // Thickness follows from the constant element volume, so the volume is exact up to round-off;
  // a drift above 1e-9 is a bookkeeping bug (a warning), above 1e-3 a wrong answer.
  if (row.volume_drift > 1e-3) {
    row.problems.push_back(fmt::format("volume drift {:.2g}", row.volume_drift));
  } else if (row.volume_drift > 1e-9) {
    row.warnings.push_back(fmt::format("volume drift {:.2g} > 1e-9", row.volume_drift));
  }
  // The solver's own trust caveats (e.g. elements shorter than the thickness).
  for (const std::string& w : r.warnings) row.warnings.push_back("solver: " + w);
  // Picard (the paper's direct iteration) stops on the velocity change only: its residual is
  // reported but judged against a loose 1e-3. Newton accepts a step whose update has vanished to
  // round-off with a residual up to 100 x tolerance (ill-conditioned cases, e.g. a rate cut-off
  // of 1e-8): judged against that same limit.
  const double residual_limit =
      scene.numerics.solver == vs::SolverKind::kPicard ? 1e-3 : 100.0 * row.tolerance;
  if (row.worst_residual > residual_limit) {
    row.problems.push_back(
        fmt::format("accepted residual {:.2g} > {:.2g}", row.worst_residual, residual_limit));
  }
  if (row.equilibrium > vs::kFreeWallEquilibriumWarning) {
    row.problems.push_back(fmt::format("equilibrium off by {:.2g}", row.equilibrium));
  }
  for (std::size_t i = 1; i < r.steps.size(); ++i) {
    if (r.steps[i].punch_force_N < 0.0) {
      row.problems.push_back("negative punch force");
      break;
    }
  }
  if (row.run.aborted) {
    row.verdict = "aborted";
    row.problems.push_back(
        fmt::format("still running after the {:.0f} s budget: {} steps, travel {:.3g} of {:.3g} mm",
                    budget_s, row.steps, row.reached_mm, row.target_travel_mm));
  } else if (!r.completed()) {
    row.verdict = r.message.empty() ? "GARBAGE" : "stopped";
    if (r.message.empty()) row.problems.push_back("stopped without a message");
  } else {
    row.verdict = !row.problems.empty() ? "GARBAGE" : row.warnings.empty() ? "ok" : "ok*";
  }
  return row;
}

// Overrides that scale every length of example 1 (`base`, as loaded) by `s`; time scales with it
// at the same punch speed: strains must be unchanged at r0 * s and forces scale with s^2.
inline Overrides ex1_scaled(const vs::Scene& base, double s) {
  auto v = [s](double x) { return fmt::format("{}", x * s); };
  Overrides ov{{"blank.radius_mm", v(base.blank.radius_mm)},
               {"blank.thickness_mm", v(base.blank.thickness_mm)},
               {"process.punch_travel_mm", v(base.process.punch_travel_mm)},
               {"numerics.max_travel_increment_mm", v(base.numerics.max_travel_increment_mm)}};
  std::string outs;
  for (double t : base.process.output_travels_mm) outs += (outs.empty() ? "" : ", ") + v(t);
  ov.push_back({"process.output_travels_mm", "[" + outs + "]"});
  for (const vs::ToolSpec& t : base.tools) {
    ov.push_back({"tool." + t.name + ".radius_mm", v(t.radius_mm)});
    if (t.kind == vs::ToolKind::kDie || t.kind == vs::ToolKind::kFlatPunch) {
      ov.push_back({"tool." + t.name + ".profile_radius_mm", v(t.profile_radius_mm)});
    }
  }
  return ov;
}

// Largest mismatch between a scaled run and the unscaled one: force / s^2 on the load curve
// (relative L2) and thickness strain at r0 * s (max abs over the outputs).
struct ScaleMismatch {
  double force_rel_l2 = kNaN;
  double eps_t_max_abs = kNaN;
};

inline ScaleMismatch scale_mismatch(const vs::RunResult& base, const vs::RunResult& scaled,
                                    double s) {
  ScaleMismatch m;
  vs::RunResult back = scaled;  // scaled back to the base units
  for (vs::StepRecord& st : back.steps) {
    st.punch_travel_mm /= s;
    st.punch_force_N /= s * s;
  }
  for (vs::Profile& p : back.profiles) {
    p.punch_travel_mm /= s;
    for (double& r0 : p.r0_mm) r0 /= s;
  }
  const double reach = std::min(final_travel(base), final_travel(back));
  m.force_rel_l2 = load_curve_rel_l2(back, base, reach);
  m.eps_t_max_abs = 0.0;
  for (const vs::Profile& p : base.profiles) {
    if (const vs::Profile* q = profile_at(back, p.punch_travel_mm)) {
      m.eps_t_max_abs = std::max(m.eps_t_max_abs, thickness_strain_max_abs(*q, p));
    }
  }
  return m;
}

}  // namespace vsx
