// Stability study (issue 5): stiff and extreme cases (friction, thin/thick sheets, anisotropy,
// hardening, rate sensitivity, rate cut-off, step fraction, solver settings, travel past the
// maximum load, unit scaling). Tabulates convergence statistics and physical checks and flags
// every run that returns an untrustworthy result without stopping.
//
//   build-exp/experiments/stability [--quick] [--out DIR]
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "common/stability_cases.h"
#include "common/table.h"

namespace {

using namespace vsx;

constexpr double kBudgetS = 30.0;

const StabilityRow* find_row(const std::vector<StabilityRow>& rows, const std::string& name) {
  for (const StabilityRow& r : rows) {
    if (r.c.name == name) return &r;
  }
  return nullptr;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "; ") + x;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const StudyArgs args =
      parse_args(argc, argv, std::string(VS_SOURCE_DIR) + "/experiments/03_stability/results");
  std::filesystem::create_directories(args.out_dir);
  std::cout << "Stability study; machine: " << machine_description() << "\n";
  std::vector<StabilityRow> rows;
  for (const StabilityCase& c : stability_cases(VS_SOURCE_DIR, args.quick)) {
    rows.push_back(evaluate_stability(VS_SOURCE_DIR, c, kBudgetS));
    const StabilityRow& r = rows.back();
    std::cout << fmt::format("  {:<45} {:>8} {:8.0f} ms  {}\n", c.name, r.verdict,
                             1e3 * r.run.wall_s, r.run.result.message);
  }

  Table t;
  t.header = {
      "group",      "case",         "verdict",   "reached / target mm", "steps",
      "iter/step",  "max iter",     "cut-backs", "zero-length steps",   "worst residual",
      "cond. est.", "volume drift", "min h/h0",  "equilibrium",         "peak load N (at mm)",
      "wall ms"};
  Table csv;
  csv.header = {"group",           "case",
                "scene",           "overrides",
                "verdict",         "reached_mm",
                "target_mm",       "steps",
                "iter_per_step",   "max_iter",
                "cutbacks",        "zero_steps",
                "worst_residual",  "condition_estimate",
                "volume_drift",    "min_h_over_h0",
                "equilibrium_err", "peak_N",
                "peak_travel_mm",  "wall_ms",
                "message",         "problems",
                "warnings"};
  for (const StabilityRow& r : rows) {
    t.add({r.c.group, r.c.name, r.verdict,
           fmt::format("{:.2f} / {:.4g}", r.reached_mm, r.target_travel_mm),
           std::to_string(r.steps), fmt::format("{:.1f}", r.iter_per_step),
           std::to_string(r.max_iter), std::to_string(r.cutbacks), std::to_string(r.zero_steps),
           fmt::format("{:.1e}", r.worst_residual), fmt::format("{:.1e}", r.condition),
           fmt::format("{:.1e} ({:.0e})", r.volume_drift, r.volume_drift_later),
           fmt::format("{:.3f}", r.min_thickness_ratio), pct(r.equilibrium),
           fmt::format("{:.4g} ({:.1f})", r.peak_N, r.peak_travel_mm), ms(r.run.wall_s)});
    csv.add({r.c.group,
             r.c.name,
             r.c.scene,
             describe(r.c.ov),
             r.verdict,
             g4(r.reached_mm),
             g4(r.target_travel_mm),
             std::to_string(r.steps),
             g4(r.iter_per_step),
             std::to_string(r.max_iter),
             std::to_string(r.cutbacks),
             std::to_string(r.zero_steps),
             g4(r.worst_residual),
             g4(r.condition),
             g4(r.volume_drift),
             g4(r.min_thickness_ratio),
             g4(r.equilibrium),
             g4(r.peak_N),
             g4(r.peak_travel_mm),
             ms(r.run.wall_s),
             r.run.result.message,
             join(r.problems),
             join(r.warnings)});
  }
  std::cout << "\n" << t.text();

  std::string md = fmt::format(
      "Base: `ex1_hemispherical_stretching.toml` (friction 0.04, 50 elements){}. Machine: {}. "
      "Equilibrium = max |F_vertical - F_punch,inside| / F_punch over circles in the free stretch "
      "carrying the largest vertical force (the unsupported wall between punch and die), at every "
      "output travel; F_punch,inside is the punch force on the nodes inside the circle (all of it "
      "unless a cup wall outside is ironed against the punch). Volume drift = max |V - V0| / V0. A "
      "case "
      "is `ok` when it completes and passes every check, `stopped` when the solver ends early "
      "with a message, `GARBAGE` when it returns without stopping but fails a check, `ok*` when "
      "it passes but the volume drifts above round-off (1e-9) or the solver raises a warning (e.g. "
      "elements shorter than the thickness). Cond. est. = the largest (max / min)^2 of the "
      "Cholesky pivots of the Newton matrices over the accepted solves, free dofs only "
      "(`RunResult::max_condition_estimate`): a lower bound of their 2-norm condition "
      "numbers.\n\n",
      args.quick ? ", travel 5 mm (quick)" : "", machine_description());
  md += t.markdown() + "\n";

  // Unit scaling: scaled runs against their unscaled twins.
  Table u;
  u.header = {"case", "compared with", "force / s^2 rel. L2", "eps_t max abs at r0 * s"};
  for (const StabilityRow& r : rows) {
    if (r.c.group != "units") continue;
    const bool rate = r.c.name.find("power") != std::string::npos;
    const double s = r.c.name.find("x 0.1") != std::string::npos ? 0.1 : 10.0;
    const StabilityRow* base = rows.front().c.group == "base" ? &rows.front() : nullptr;
    if (rate) base = find_row(rows, "power m = 0.1");
    if (!base || !base->run.result.completed() || !r.run.result.completed()) continue;
    const ScaleMismatch m = scale_mismatch(base->run.result, r.run.result, s);
    u.add({r.c.name, base->c.name, fmt::format("{:.2e}", m.force_rel_l2),
           fmt::format("{:.2e}", m.eps_t_max_abs)});
  }
  md +=
      "Unit scaling (the scene units are fixed to mm, N, s, MPa, so a metre-based run is the "
      "same problem with every length scaled; lengths x s and time x s at the same punch speed "
      "must give the same strains at r0 x s and forces x s^2):\n\n" +
      u.markdown() + "\n";

  std::string bad;
  for (const StabilityRow& r : rows) {
    if (r.verdict == "GARBAGE" || r.verdict == "aborted") {
      bad += fmt::format("- **{}** ({}): {}. Reproduce: `vshell run data/scenes/{}.toml{}`\n",
                         r.c.name, r.verdict, join(r.problems), r.c.scene, cli_args(r.c.ov));
    }
  }
  std::string stopped;
  for (const StabilityRow& r : rows) {
    if (r.verdict == "stopped") {
      stopped += fmt::format("- {}: {}\n", r.c.name, r.run.result.message);
    }
  }
  std::string warned;
  for (const StabilityRow& r : rows) {
    if (!r.warnings.empty()) warned += fmt::format("- {}: {}\n", r.c.name, join(r.warnings));
  }
  md += "Runs that returned without a trustworthy answer:\n\n" + (bad.empty() ? "- none\n" : bad);
  md += "\nRuns that stopped with a message:\n\n" + (stopped.empty() ? "- none\n" : stopped);
  md += "\nWarnings:\n\n" + (warned.empty() ? "- none\n" : warned);
  write_text(args.out_dir + "/stability.csv", csv.csv());
  write_text(args.out_dir + "/summary.md", md);
  std::cout << "\n" << md << "wrote " << args.out_dir << "\n";
  return 0;
}
