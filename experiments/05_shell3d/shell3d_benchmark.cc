// Benchmark of the 3D forming solver (issue 3): the quarter circular blank of paper example 4a
// (data/scenes/ex4a_quarter_disc_sticking.toml) at several mesh sizes, against the axisymmetric
// solver on the same data. Per run: wall time to full travel, peak memory, time split (element
// assembly / sparse factorisation and solves / contact), punch force and thickness-strain
// deviation from the axisymmetric reference at the output travels. See README.md next to this file.
//
//   shell3d_benchmark [--divisions 4,8,16] [--rules mitc9,paper_selective] [--friction F]
//                     [--travel MM] [--outputs A,B,C] [--increment MM] [--axisym-elements N]
//                     [--scene FILE] [--csv FILE]
#include <fmt/format.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "run/simulate.h"
#include "scene/load_scene.h"
#include "shell3d/forming/axisym_comparison.h"
#include "shell3d/forming/forming_driver.h"

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

struct Args {
  std::string scene = std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml";
  std::vector<int> divisions = {4, 8, 16};
  std::vector<std::string> rules = {"mitc9"};
  std::string friction;  // empty: the scene's
  double travel = 0.0;   // 0: the scene's
  std::vector<double> outputs;
  double increment = 0.0;
  int axisym_elements = 60;
  std::string csv;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--scene") {
      a.scene = value;
    } else if (key == "--divisions") {
      a.divisions.clear();
      for (const auto& s : split(value)) a.divisions.push_back(std::stoi(s));
    } else if (key == "--rules") {
      a.rules = split(value);
    } else if (key == "--friction") {
      a.friction = value;
    } else if (key == "--travel") {
      a.travel = std::stod(value);
    } else if (key == "--outputs") {
      for (const auto& s : split(value)) a.outputs.push_back(std::stod(s));
    } else if (key == "--increment") {
      a.increment = std::stod(value);
    } else if (key == "--axisym-elements") {
      a.axisym_elements = std::stoi(value);
    } else if (key == "--csv") {
      a.csv = value;
    } else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      std::exit(2);
    }
  }
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  vs::Scene base = vs::load_scene(args.scene);
  if (args.travel > 0.0) base.process.punch_travel_mm = args.travel;
  if (!args.outputs.empty()) base.process.output_travels_mm = args.outputs;
  if (args.increment > 0.0) base.numerics.max_travel_increment_mm = args.increment;
  if (!args.friction.empty()) {
    for (auto& t : base.tools) {
      t.friction = args.friction == "sticking" ? std::numeric_limits<double>::infinity()
                                               : std::stod(args.friction);
    }
  }
  std::string friction_text = "?";
  for (const auto& t : base.tools)
    if (t.kind == vs::ToolKind::kHemisphericalPunch || t.kind == vs::ToolKind::kFlatPunch)
      friction_text = t.sticking() ? "sticking" : fmt::format("{}", t.friction);

  const vs::Scene axi_scene = vs::shell3d::axisymmetric_twin(base, args.axisym_elements);
  const auto ta = std::chrono::steady_clock::now();
  const vs::RunResult axi = vs::simulate(axi_scene);
  const double axi_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - ta).count();
  std::printf("# scene %s, friction %s, travel %.2f mm, increment %.3f mm, %d Simpson points\n",
              args.scene.c_str(), friction_text.c_str(), base.process.punch_travel_mm,
              base.numerics.max_travel_increment_mm, base.numerics.thickness_points);
  std::printf("# axisymmetric reference: %d elements, %s, %.2f s\n", args.axisym_elements,
              axi.message.c_str(), axi_s);
  std::printf("%-6s %-15s %5s %6s %8s %8s %8s %8s %6s %6s %6s %8s  %s\n", "div", "rule", "elem",
              "dofs", "wall_s", "asm_s", "fact_s", "cont_s", "nfact", "steps", "iters", "rss_MB",
              "travel_mm:F3d_kN/Faxi_kN/dF%/dFmean%/max|deps_t| ...");
  std::ofstream csv;
  if (!args.csv.empty()) {
    csv.open(args.csv);
    csv << "divisions,rule,friction,elements,dofs,completed,wall_s,assembly_s,factorisation_s,"
           "contact_s,factorisations,steps,iterations,peak_rss_MB,punch_travel_mm,"
           "punch_force_3d_N,punch_force_axisym_N,force_deviation,mean_force_deviation,"
           "eps_thickness_dev_y0,"
           "eps_thickness_dev_x0,eps_thickness_dev_diagonal\n";
  }
  for (const std::string& rule : args.rules) {
    for (int n : args.divisions) {
      vs::Scene scene = base;
      scene.blank.divisions = n;
      scene.numerics.element_rule = rule == "paper_selective"
                                        ? vs::ShellElementRule::kPaperSelective
                                        : vs::ShellElementRule::kMitc9;
      const auto t0 = std::chrono::steady_clock::now();
      const vs::shell3d::Shell3dResult r = vs::shell3d::simulate_shell3d(scene);
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double rss = peak_rss_mb();
      const auto cmp = vs::shell3d::compare_with_axisymmetric(scene, r, axi);
      std::string devs;
      for (const auto& c : cmp) {
        devs += fmt::format(" {:g}:{:.2f}/{:.2f}/{:+.2f}/{:+.2f}/{:.4f}", c.punch_travel_mm,
                            1e-3 * c.force_3d_N, 1e-3 * c.force_axisym_N, 100.0 * c.force_deviation,
                            100.0 * c.mean_force_deviation, c.max_eps_thickness_deviation());
        if (csv) {
          csv << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                             n, rule, friction_text, r.mesh.num_elements(), r.dofs, r.completed(),
                             wall, r.timings.assembly_s, r.timings.factorisation_s,
                             r.timings.contact_s, r.timings.factorisations, r.steps.size(),
                             r.total_iterations, rss, c.punch_travel_mm, c.force_3d_N,
                             c.force_axisym_N, c.force_deviation, c.mean_force_deviation,
                             c.eps_thickness_deviation_y0, c.eps_thickness_deviation_x0,
                             c.eps_thickness_deviation_diagonal);
        }
      }
      std::printf("%-6d %-15s %5d %6d %8.2f %8.2f %8.2f %8.3f %6d %6zu %6d %8.1f %s%s\n", n,
                  rule.c_str(), r.mesh.num_elements(), r.dofs, wall, r.timings.assembly_s,
                  r.timings.factorisation_s, r.timings.contact_s, r.timings.factorisations,
                  r.steps.size(), r.total_iterations, rss, devs.c_str(),
                  r.completed() ? "" : ("  FAILED: " + r.message).c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
