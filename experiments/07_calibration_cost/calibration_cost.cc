// Calibration error against calibration time, as a function of the forward discretisation used
// inside the fit (issue 5).
//
// Twin experiment on ex1 (hemispherical stretching, 20 mm): "measured" data (load at 1..20 mm,
// thickness strain at 10 and 20 mm, no noise) come from a FINE forward model (96 elements, travel
// step 0.0125 element lengths). Four parameters (punch friction, Swift K and n, R) are then
// identified from a start 20 % off with COARSER forward models. The error of the identified
// parameters is the discretisation bias the coarse model puts into the calibration; the time is
// the whole fit (forward runs in 2 threads).
//
//   build/experiments/calibration_cost [--quick] [--out DIR]
// (default DIR: experiments/07_calibration_cost/results/ of the source tree)
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "calibrate.h"
#include "common/harness.h"
#include "common/table.h"
#include "default_forward_model.h"
#include "synthetic.h"

namespace {

struct Truth {
  const char* address;
  double value;
  double lower, upper, scale;
};

const std::vector<Truth> kTruth = {{"tool.punch.friction", 0.1, 0.0, 0.5, 0.1},
                                   {"material.hardening.K_MPa", 589.0, 100.0, 2000.0, 500.0},
                                   {"material.hardening.n", 0.216, 0.05, 0.6, 0.2},
                                   {"material.r_value", 1.5, 0.3, 5.0, 1.0}};

struct Setting {
  std::string label;
  vsx::Overrides ov;  // forward discretisation (on top of the common edits)
};

vsx::Overrides common_edits() {
  return {{"process.punch_travel_mm", "20"},
          {"process.output_travels_mm", "[10.0, 20.0]"},
          {"numerics.tolerance", "1e-8"}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string src = VS_SOURCE_DIR;
  const vsx::StudyArgs args =
      vsx::parse_args(argc, argv, src + "/experiments/07_calibration_cost/results");
  const bool quick = args.quick;
  const std::string& out_dir = args.out_dir;
  std::filesystem::create_directories(out_dir);
  const std::string scene_path = vsx::scene_path(src, "ex1_hemispherical_stretching");

  // Data from the fine model with the true parameters.
  vsx::Overrides fine = common_edits();
  fine.push_back({"blank.elements", quick ? "48" : "96"});
  fine.push_back({"numerics.max_travel_increment_per_length", "0.0125"});
  for (const Truth& t : kTruth) fine.push_back({t.address, fmt::format("{}", t.value)});
  const vs::Scene truth_scene = vsx::make_scene(scene_path, fine);
  const vsx::TimedRun truth_run = vsx::run_once(truth_scene, 3600.0);
  if (!truth_run.result.completed()) {
    fmt::print(stderr, "reference run failed: {}\n", truth_run.result.message);
    return 1;
  }
  std::vector<double> travels, radii;
  for (int i = 1; i <= 20; ++i) travels.push_back(i);
  for (int i = 0; i <= 22; ++i) radii.push_back(2.5 * i);
  const auto data = vs::make_synthetic_measurements(
      truth_scene, truth_run.result,
      {{vs::MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0},
       {vs::MeasurementKind::kThicknessStrain, "thick_10mm", 10.0, radii, 0.0, 0.0},
       {vs::MeasurementKind::kThicknessStrain, "thick_20mm", 20.0, radii, 0.0, 0.0}},
      1);
  fmt::print("reference: {} ({:.1f} s)\n", vsx::describe(fine), truth_run.wall_s);

  std::vector<Setting> settings = {{"12 elements", {{"blank.elements", "12"}}},
                                   {"24 elements", {{"blank.elements", "24"}}}};
  if (!quick) {
    settings.push_back({"48 elements", {{"blank.elements", "48"}}});
    settings.push_back({"24 elements, step 0.1 l (unstable)",
                        {{"blank.elements", "24"},
                         {"numerics.max_travel_increment_per_length", "0.1"}}});
  }
  std::string md = fmt::format(
      "Reference data: `{}` ({:.1f} s). Start: every parameter x0.8. Forward tolerance 1e-8, "
      "central differences with relative step 0.05, 2 threads.\n\n"
      "| forward model in the fit | friction err | K err | n err | R err | max err | forward "
      "runs | wall s | CPU s per forward run |\n|---|---|---|---|---|---|---|---|---|\n",
      vsx::describe(fine), truth_run.wall_s);
  std::ofstream csv(out_dir + "/calibration_cost.csv");
  csv << "setting,friction_err_rel,K_err_rel,n_err_rel,R_err_rel,max_err_rel,forward_runs,wall_s,"
         "cpu_s_per_run\n";
  for (const Setting& s : settings) {
    vs::CalibrationConfig c;
    c.scenes = {{"scene", scene_path, "experiment"}};
    c.forward.tolerance = 1e-8;
    for (const vsx::Override& o : common_edits()) c.forward.overrides.push_back({o.address, o.value});
    for (const vsx::Override& o : s.ov) c.forward.overrides.push_back({o.address, o.value});
    for (const Truth& t : kTruth) {
      vs::ParameterSpec p;
      p.address = t.address;
      p.initial = 0.8 * t.value;
      p.lower = t.lower;
      p.upper = t.upper;
      p.scale = t.scale;
      p.where = "experiment";
      c.parameters.push_back(p);
    }
    const double sigma[] = {200.0, 0.002, 0.002};
    for (std::size_t k = 0; k < data.size(); ++k) {
      vs::DataSpec d;
      d.measurement = data[k];
      d.sigma = sigma[k];
      d.where = "experiment";
      c.data.push_back(d);
    }
    c.optimizer.threads = 2;
    c.optimizer.fd.relative_step = 0.05;
    vs::CalibrationOptions options;
    options.write_report = false;
    const double cpu0 = vsx::thread_cpu_s();
    (void)cpu0;
    const vs::CalibrationResult r = vs::calibrate(c, options, vs::make_default_forward_model());
    std::vector<double> err;
    double worst = 0.0;
    for (std::size_t i = 0; i < kTruth.size(); ++i) {
      err.push_back(r.parameters[i].value / kTruth[i].value - 1.0);
      worst = std::max(worst, std::abs(err.back()));
    }
    // CPU per forward run from one timed run of the coarse model at the truth.
    vsx::Overrides one = common_edits();
    for (const vsx::Override& o : s.ov) one.push_back(o);
    const double cpu_run = vsx::run_once(vsx::make_scene(scene_path, one), 600.0).cpu_s;
    md += fmt::format("| {} | {:+.2f}% | {:+.2f}% | {:+.2f}% | {:+.2f}% | {:.2f}% | {} | {:.1f} | {:.2f} |\n",
                      s.label, 100 * err[0], 100 * err[1], 100 * err[2], 100 * err[3], 100 * worst,
                      r.forward_runs, r.wall_time_s, cpu_run);
    csv << fmt::format("\"{}\",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.4g},{:.4g}\n", s.label,
                       err[0], err[1], err[2], err[3], worst, r.forward_runs, r.wall_time_s,
                       cpu_run);
    fmt::print("{}: max error {:.2f}%, {} forward runs, {:.1f} s ({})\n", s.label, 100 * worst,
               r.forward_runs, r.wall_time_s, r.message);
  }
  std::ofstream(out_dir + "/summary.md") << md;
  fmt::print("\n{}", md);
  return 0;
}
