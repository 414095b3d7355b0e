// Calibration error against calibration time, as a function of the forward discretisation used
// inside the fit (issue 5).
//
// Twin experiment on ex1 (hemispherical stretching, 20 mm): "measured" data (load at 1..20 mm,
// thickness strain at 10 and 20 mm, no noise) come from a FINE forward model (96 elements, travel
// step 0.0125 element lengths). Four parameters (punch friction, Swift K and n, R) are then
// identified from a start 20 % off with COARSER forward models. The error of the identified
// parameters is the discretisation bias the coarse model puts into the calibration; the time is
// the whole fit (forward runs in 2 threads). The twin itself (data, fit) is
// experiments/common/calibration_cost.h, shared with the quick CTest variant.
//
//   build/experiments/calibration_cost [--quick] [--out DIR]
// (default DIR: experiments/07_calibration_cost/results/ of the source tree)
#include "common/calibration_cost.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/harness.h"
#include "common/table.h"

namespace {

struct Setting {
  std::string label;
  vsx::Overrides ov;  // forward discretisation (on top of the common edits)
};

}  // namespace

int main(int argc, char** argv) {
  const std::string src = VS_SOURCE_DIR;
  const vsx::StudyArgs args =
      vsx::parse_args(argc, argv, src + "/experiments/07_calibration_cost/results");
  const bool quick = args.quick;
  const std::string& out_dir = args.out_dir;
  std::filesystem::create_directories(out_dir);

  vsx::TwinSetup setup;
  setup.scene_path = vsx::scene_path(src, "ex1_hemispherical_stretching");
  // Data from the fine model with the true parameters.
  const vsx::TwinData data =
      vsx::twin_data(setup, {{"blank.elements", quick ? "48" : "96"},
                             {"numerics.max_travel_increment_per_length", "0.0125"}});
  if (!data.ok) {
    fmt::print(stderr, "reference run failed: {}\n", data.message);
    return 1;
  }
  fmt::print("reference: {} ({:.1f} s)\n", vsx::describe(data.fine), data.wall_s);

  std::vector<Setting> settings = {{"12 elements", {{"blank.elements", "12"}}},
                                   {"24 elements", {{"blank.elements", "24"}}}};
  if (!quick) {
    settings.push_back({"48 elements", {{"blank.elements", "48"}}});
    settings.push_back(
        {"24 elements, step 0.1 l (unstable)",
         {{"blank.elements", "24"}, {"numerics.max_travel_increment_per_length", "0.1"}}});
  }
  std::string md = fmt::format(
      "Reference data: `{}` ({:.1f} s). Start: every parameter x0.8. Forward tolerance 1e-8, "
      "central differences with relative step 0.05, 2 threads.\n\n"
      "| forward model in the fit | friction err | K err | n err | R err | max err | forward "
      "runs | wall s | CPU s per forward run |\n|---|---|---|---|---|---|---|---|---|\n",
      vsx::describe(data.fine), data.wall_s);
  std::ofstream csv(out_dir + "/calibration_cost.csv");
  csv << "setting,friction_err_rel,K_err_rel,n_err_rel,R_err_rel,max_err_rel,forward_runs,wall_s,"
         "cpu_s_per_run\n";
  for (const Setting& s : settings) {
    const vsx::TwinFit fit = vsx::twin_fit(setup, data, s.ov);
    const std::vector<double>& err = fit.error;
    // CPU per forward run from one timed run of the coarse model at the truth.
    vsx::Overrides one = vsx::twin_common_edits(setup);
    for (const vsx::Override& o : s.ov) one.push_back(o);
    const double cpu_run = vsx::run_once(vsx::make_scene(setup.scene_path, one), 600.0).cpu_s;
    md += fmt::format(
        "| {} | {:+.2f}% | {:+.2f}% | {:+.2f}% | {:+.2f}% | {:.2f}% | {} | {:.1f} | {:.2f} |\n",
        s.label, 100 * err[0], 100 * err[1], 100 * err[2], 100 * err[3], 100 * fit.max_error,
        fit.forward_runs, fit.wall_s, cpu_run);
    csv << fmt::format("\"{}\",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.4g},{:.4g}\n", s.label,
                       err[0], err[1], err[2], err[3], fit.max_error, fit.forward_runs, fit.wall_s,
                       cpu_run);
    fmt::print("{}: max error {:.2f}%, {} forward runs, {:.1f} s ({})\n", s.label,
               100 * fit.max_error, fit.forward_runs, fit.wall_s, fit.message);
  }
  std::ofstream(out_dir + "/summary.md") << md;
  fmt::print("\n{}", md);
  return 0;
}
