// Stability of the explicit (Heun) geometry update against the travel step, measured as what a
// calibration sees: how smoothly the outputs move when a parameter moves a little.
//
// For ex1 (hemispherical stretching, punch friction 0.1, R 1.5, 20 mm, tolerance 1e-8) and each
// mesh and travel step (numerics.max_travel_increment_per_length, the step relative to the
// element length), the punch friction is swept over 0.0990..0.1010 in 11 runs. For a smooth
// forward map the outputs are nearly linear over such a small range; the experiment reports the
// largest deviation from the least-squares line ("jitter") of the punch force at 10, 16 and 20 mm
// and of the thickness strain at 20 mm, the roughness of one load-travel curve (rms second
// difference on the 0.25 mm grid, relative to the mean increment), and the CPU time per run.
//
//   build/experiments/step_stability [--quick] [--out DIR]
// (default DIR: experiments/06_step_stability/results/ of the source tree)
#include "common/step_stability.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "common/harness.h"
#include "common/table.h"

int main(int argc, char** argv) {
  const std::string src = VS_SOURCE_DIR;
  const vsx::StudyArgs args =
      vsx::parse_args(argc, argv, src + "/experiments/06_step_stability/results");
  const bool quick = args.quick;
  const std::string& out_dir = args.out_dir;
  std::filesystem::create_directories(out_dir);
  const std::vector<int> meshes = quick ? std::vector<int>{24} : std::vector<int>{24, 48};
  const std::vector<double> factors = !args.steps.empty() ? args.steps
                                      : quick             ? std::vector<double>{0.1, 0.025}
                                              : std::vector<double>{0.1, 0.05, 0.025, 0.0125};
  const int sweep = quick ? 5 : 11;
  // The default strain-rate cut-off, and the 100x larger one of the performance benchmark's speed
  // setting (rigid zones creep at 1 % of the nominal rate; at the larger steps only).
  struct Cutoff {
    std::string value;
    double smallest_factor;  // run only steps per element length >= this
  };
  const std::vector<Cutoff> cutoffs = quick ? std::vector<Cutoff>{{"1e-4", 0.0}}
                                            : std::vector<Cutoff>{{"1e-4", 0.0}, {"1e-2", 0.05}};
  std::string md =
      "| elements | step / element length | strain-rate cut-off | travel step (mm) | jitter F(10 "
      "mm) "
      "/ F | jitter F(16 mm) / F | jitter F(20 mm) / F | jitter eps_t,min(20 mm) | load roughness "
      "| CPU s per run |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  std::ofstream csv(out_dir + "/step_stability.csv");
  csv << "elements,step_per_length,strain_rate_cutoff,travel_step_mm,jitter_F10_rel,jitter_F16_rel,"
         "jitter_F20_rel,"
         "jitter_eps_t_min20,load_roughness,cpu_s_per_run\n";
  for (const Cutoff& cut : cutoffs) {
    for (int el : meshes) {
      for (double f : factors) {
        if (f < cut.smallest_factor) continue;
        std::vector<double> mu, f10, f16, f20, emin;
        double rough = 0.0, cpu = 0.0, step_mm = 0.0;
        for (int k = 0; k < sweep; ++k) {
          const double m = 0.099 + 0.002 * k / (sweep - 1);
          vsx::Overrides sets = {{"blank.elements", std::to_string(el)},
                                 {"process.punch_travel_mm", "20"},
                                 {"process.output_travels_mm", "[10.0, 20.0]"},
                                 {"material.r_value", "1.5"},
                                 {"numerics.tolerance", "1e-8"},
                                 {"numerics.max_travel_increment_per_length", fmt::format("{}", f)},
                                 {"numerics.strain_rate_cutoff", cut.value},
                                 {"tool.punch.friction", fmt::format("{:.6f}", m)}};
          for (const auto& [key, value] : args.sets) sets.push_back({key, value});
          const vs::Scene scene =
              vsx::make_scene(vsx::scene_path(src, "ex1_hemispherical_stretching"), sets);
          step_mm =
              std::min(scene.numerics.max_travel_increment_mm, f * scene.blank.radius_mm / el);
          const vsx::TimedRun run = vsx::run_once(scene, 600.0);
          if (!run.result.completed()) {
            fmt::print(stderr, "{} el, factor {}: run failed: {}\n", el, f, run.result.message);
            continue;
          }
          cpu += run.cpu_s;
          mu.push_back(m);
          f10.push_back(vsx::force_at(run.result, 10.0));
          f16.push_back(vsx::force_at(run.result, 16.0));
          f20.push_back(vsx::force_at(run.result, 20.0));
          const vs::Profile& p = run.result.profiles[1];
          emin.push_back(*std::min_element(p.eps_thickness.begin(), p.eps_thickness.end()));
          if (k == sweep / 2) rough = vsx::load_roughness(run.result);
        }
        if (mu.size() < 3) continue;
        const double j10 = vsx::linear_fit_max_deviation(mu, f10) / f10.front();
        const double j16 = vsx::linear_fit_max_deviation(mu, f16) / f16.front();
        const double j20 = vsx::linear_fit_max_deviation(mu, f20) / f20.front();
        const double je = vsx::linear_fit_max_deviation(mu, emin);
        const double c = cpu / static_cast<double>(mu.size());
        // Relative force jitter in scientific notation: at the default step it is ~1e-8.
        md += fmt::format(
            "| {} | {} | {} | {:.4f} | {:.1e} | {:.1e} | {:.1e} | {:.1e} | {:.3f} | {:.2f} |\n", el,
            f, cut.value, step_mm, j10, j16, j20, je, rough, c);
        csv << fmt::format("{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g}\n", el, f,
                           cut.value, step_mm, j10, j16, j20, je, rough, c);
        fmt::print(
            "{} elements, step/length {}, cut-off {}: jitter F10 {:.1e} F16 {:.1e} F20 {:.1e} "
            "(relative) eps {:.1e}, roughness {:.3f}, {:.2f} s/run\n",
            el, f, cut.value, j10, j16, j20, je, rough, c);
      }
    }
  }
  std::ofstream(out_dir + "/summary.md") << md;
  fmt::print("\n{}", md);
  return 0;
}
