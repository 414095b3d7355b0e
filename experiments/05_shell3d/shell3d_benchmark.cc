// Benchmark of the 3D forming solver (issue 3): the quarter circular blank of paper example 4a
// (data/scenes/ex4a_quarter_disc_sticking.toml) at several mesh sizes, against the axisymmetric
// solver on the same data. Per run: wall time to full travel, peak memory, time split (element
// assembly / sparse factorisation and solves / contact), punch force and thickness-strain
// deviation from the axisymmetric reference at the output travels. See README.md next to this file.
//
//   shell3d_benchmark [--divisions 4,8,16] [--rules mitc9,paper_selective] [--friction F]
//                     [--travel MM] [--outputs A,B,C] [--increment MM] [--axisym-elements N]
//                     [--scene FILE] [--csv FILE] [--speed-setting] [--per-length X]
//                     [--cutoff X] [--implicit] [--no-events] [--krylov-min N] [--goal]
//                     [--double-preconditioner] [--first-tolerance-factor X]
//                     [--start-refinement L] [--implicit-solves N] [--fine-reference X]
//                     [--contact-entry first_solve|last_solve] [--cholmod-factorisation]
//                     [--transverse-shear-scale X]
// --speed-setting: numerics.max_travel_increment_per_length = 0.05 and strain_rate_cutoff = 1e-2
// (the axisymmetric speed setting of experiments/01_performance); --per-length / --cutoff set the
// two keys one by one (after --speed-setting, whatever the order). --implicit: the 3D runs with
// numerics.time_integration = implicit (the reference stays at its defaults); --no-events: with
// numerics.contact_events = false; --krylov-min N: RunOptions::krylov_min_unknowns (Krylov steps on
// the held factorisation from N unknowns; a huge N turns them off); --double-preconditioner:
// RunOptions::single_precision_preconditioner = false; --cholmod-factorisation:
// RunOptions::parallel_factorisation = false (every factorisation by CHOLMOD on one thread);
// --first-tolerance-factor X:
// StepDriverOptions::implicit_first_tolerance_factor (the implicit update's first solve stops at X
// times numerics.tolerance); --start-refinement L: numerics.start_refinement (the scene default
// is 3 for 3D with the implicit update since 26 Nov 2026; figures before that are with 0);
// --implicit-solves N: numerics.implicit_solves (velocity solves per implicit step, 2 by default);
// --contact-entry first_solve|last_solve: numerics.contact_entry (the solve of an implicit step in
// which new contacts enter);
// --transverse-shear-scale X: numerics.transverse_shear_scale in the 3D runs and the twin (the
// same model on both sides; experiments/08_continuum_reference section 14);
// --fine-reference X: each run is also compared with a run of the same 3D mesh at X element lengths
// per step with contact events and no graded start (its time-stepping error alone, without the
// mesh's; for X small enough the reference's own error is negligible). --goal: after each run, the
// issue-3 performance goal (force and thickness strain within 2 % of the axisymmetric solver at
// every output travel, in under 10 s wall) with the figures it rests on.
//
// Report study (experiments/REPORT.md, run by experiments/run_all.sh): with --out DIR and/or
// --quick it runs the work-precision study of experiments/common/shell3d_study.h instead and
// writes DIR/shell3d_study.csv, DIR/summary.md and DIR/shell3d_work_precision.svg (DIR defaults
// to results/ next to this file); --summarise DIR regenerates the summary and the figure from
// DIR/shell3d_study.csv without running anything.
//   shell3d_benchmark [--quick] [--out DIR]
//   shell3d_benchmark --summarise DIR
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/axisym_comparison.h"
#include "common/harness.h"
#include "common/shell3d_study.h"
#include "common/step_stability.h"
#include "common/table.h"
#include "output/svg_plot.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

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

// --fine-reference: the same scene and mesh at `per_length` element lengths per step with contact
// events and no graded start (the default implicit update otherwise: two solves per step, second
// order, new contacts in the first solve, whatever the run's numerics.implicit_solves and
// numerics.contact_entry), and the deviation of r from
// it at every output travel both reached: force, and the largest nodal |d eps_t| = |ln(h / h_ref)|.
void print_against_fine_reference(vs::Scene scene, const vs::RunResult& r, double per_length) {
  scene.numerics.time_integration = vs::TimeIntegration::kImplicit;
  scene.numerics.max_travel_increment_per_length = per_length;
  scene.numerics.contact_events = true;
  scene.numerics.start_refinement = 0;
  scene.numerics.implicit_solves = 2;
  scene.numerics.contact_entry = vs::ContactEntry::kFirstSolve;
  const auto t0 = std::chrono::steady_clock::now();
  const vs::RunResult ref = vs::shell3d::simulate_shell3d(scene, vs::RunOptions{});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string devs;
  double last = -1.0;  // the stages end with the final state, often an output travel as well
  for (const auto& a : r.shell->stages) {
    if (a.punch_travel_mm == last) continue;
    last = a.punch_travel_mm;
    for (const auto& b : ref.shell->stages) {
      if (std::abs(a.punch_travel_mm - b.punch_travel_mm) > 1e-9 * (1.0 + b.punch_travel_mm))
        continue;
      double eps = 0.0;
      for (std::size_t i = 0; i < a.thickness_mm.size() && i < b.thickness_mm.size(); ++i)
        eps = std::max(eps, std::abs(std::log(a.thickness_mm[i] / b.thickness_mm[i])));
      const double f = vsx::force_at(r, a.punch_travel_mm);
      const double fr = vsx::force_at(ref, b.punch_travel_mm);
      devs += fmt::format(" {:g}:{:+.2f}/{:.4f}", a.punch_travel_mm, 100.0 * (f / fr - 1.0), eps);
      break;
    }
  }
  std::printf(
      "#   against the same mesh at %g element lengths per step with contact events (%zu steps, "
      "%.1f s%s), travel_mm:dF%%/max|deps_t|:%s\n",
      per_length, ref.steps.size(), wall, ref.completed() ? "" : ", FAILED", devs.c_str());
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
  bool study = false;  // --quick or --out: the report study
  bool quick = false;
  bool speed_setting = false;
  double per_length = 0.0, cutoff = 0.0;  // 0: the scene's (or the speed setting's)
  double shear_scale = 0.0;               // 0: the scene's
  bool implicit = false;                  // --implicit: numerics.time_integration = implicit
  bool no_events = false;                 // --no-events: numerics.contact_events = false
  bool goal = false;
  int krylov_min = vs::RunOptions{}.krylov_min_unknowns;
  bool double_preconditioner = false;
  bool cholmod_factorisation = false;
  double first_tolerance_factor = vs::StepDriverOptions{}.implicit_first_tolerance_factor;
  int start_refinement = -1;                      // -1: the scene's
  int implicit_solves = 0;                        // 0: the scene's
  std::optional<vs::ContactEntry> contact_entry;  // --contact-entry; empty: the scene's
  double fine_reference = 0.0;  // > 0: element lengths per step of a same-mesh reference run
  std::string summarise_dir;    // --summarise DIR: summary.md from DIR/shell3d_study.csv, no runs
  std::string out_dir = std::string(VS_SOURCE_DIR) + "/experiments/05_shell3d/results";
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--quick" || key == "--speed-setting" || key == "--goal" || key == "--implicit" ||
        key == "--no-events" || key == "--double-preconditioner" ||
        key == "--cholmod-factorisation") {
      if (key == "--double-preconditioner") a.double_preconditioner = true;
      if (key == "--cholmod-factorisation") a.cholmod_factorisation = true;
      if (key == "--no-events") a.no_events = true;
      if (key == "--quick") a.study = a.quick = true;
      if (key == "--implicit") a.implicit = true;
      if (key == "--speed-setting") a.speed_setting = true;
      if (key == "--goal") a.goal = true;
      --i;  // no value
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "option %s needs a value\n", key.c_str());
      std::exit(2);
    }
    const std::string value = argv[i + 1];
    if (key == "--summarise") {
      a.summarise_dir = value;
    } else if (key == "--out") {
      a.study = true;
      a.out_dir = value;
    } else if (key == "--scene") {
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
    } else if (key == "--per-length") {
      a.per_length = std::stod(value);
    } else if (key == "--cutoff") {
      a.cutoff = std::stod(value);
    } else if (key == "--transverse-shear-scale") {
      a.shear_scale = std::stod(value);
    } else if (key == "--axisym-elements") {
      a.axisym_elements = std::stoi(value);
    } else if (key == "--csv") {
      a.csv = value;
    } else if (key == "--krylov-min") {
      a.krylov_min = std::stoi(value);
    } else if (key == "--first-tolerance-factor") {
      a.first_tolerance_factor = std::stod(value);
    } else if (key == "--start-refinement") {
      a.start_refinement = std::stoi(value);
    } else if (key == "--implicit-solves") {
      a.implicit_solves = std::stoi(value);
      if (a.implicit_solves < 1 || a.implicit_solves > 3) {
        std::fprintf(stderr, "--implicit-solves must be 1, 2 or 3\n");
        std::exit(2);
      }
    } else if (key == "--contact-entry") {
      if (value != "first_solve" && value != "last_solve") {
        std::fprintf(stderr, "--contact-entry must be first_solve or last_solve\n");
        std::exit(2);
      }
      a.contact_entry =
          value == "last_solve" ? vs::ContactEntry::kLastSolve : vs::ContactEntry::kFirstSolve;
    } else if (key == "--fine-reference") {
      a.fine_reference = std::stod(value);
    } else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      std::exit(2);
    }
  }
  return a;
}

// Work-precision figure from the study's CSV: largest |mean-force deviation| and largest |d eps_t|
// against CPU time, one line per element rule (log-log), with the reference noise dashed.
bool write_study_figure(const std::string& dir) {
  vsx::Shell3dMeta meta;
  std::vector<vsx::Shell3dRow> rows;
  if (!vsx::read_shell3d_csv(dir + "/shell3d_study.csv", &meta, &rows)) return false;
  vs::SvgFigure fig;
  fig.title = "3D quarter disc against the axisymmetric solver: error against CPU time";
  fig.x_label = "log10(CPU time [s])";
  fig.y_label = "log10(largest deviation: force relative, eps_t absolute)";
  std::vector<std::string> rules;
  double noise_force = std::nan(""), noise_eps = std::nan("");
  double xmin = 1e300, xmax = -1e300;
  for (const auto& r : rows) {
    if (r.c.rule == "axisymmetric") {
      noise_force = r.dev.max_abs_mean_force;
      noise_eps = r.dev.max_eps_thickness;
    } else if (r.c.rule != "axisymmetric_reference" && r.completed && r.dev.travels > 0) {
      if (std::find(rules.begin(), rules.end(), r.c.rule) == rules.end()) rules.push_back(r.c.rule);
      xmin = std::min(xmin, std::log10(r.cpu_s));
      xmax = std::max(xmax, std::log10(r.cpu_s));
    }
  }
  int colour = 0;
  for (const std::string& rule : rules) {
    vs::PlotSeries force{
        rule + ": |mean-force deviation|", {}, {}, vs::SeriesStyle::kLineAndMarkers};
    vs::PlotSeries eps{rule + ": |d eps_t|", {}, {}, vs::SeriesStyle::kLineAndMarkers};
    force.colour = eps.colour = colour++;
    eps.dashed = true;
    for (const auto& r : rows) {
      if (r.c.rule != rule || !r.completed || r.dev.travels == 0) continue;
      force.x.push_back(std::log10(r.cpu_s));
      force.y.push_back(std::log10(std::max(r.dev.max_abs_mean_force, 1e-6)));
      eps.x.push_back(std::log10(r.cpu_s));
      eps.y.push_back(std::log10(std::max(r.dev.max_eps_thickness, 1e-6)));
    }
    fig.series.push_back(force);
    fig.series.push_back(eps);
  }
  if (xmin <= xmax) {
    vs::PlotSeries nf{"reference noise, force", {xmin, xmax}, {}, vs::SeriesStyle::kLine};
    vs::PlotSeries ne{"reference noise, eps_t", {xmin, xmax}, {}, vs::SeriesStyle::kLine};
    nf.y = {std::log10(noise_force), std::log10(noise_force)};
    ne.y = {std::log10(noise_eps), std::log10(noise_eps)};
    nf.colour = ne.colour = colour;
    ne.dashed = true;
    fig.series.push_back(nf);
    fig.series.push_back(ne);
  }
  vs::write_svg(fig, dir + "/shell3d_work_precision.svg");
  return true;
}

// The report study: reference, reference noise, every case; CSV and summary.md in args.out_dir.
int run_study(const Args& args) {
  const vsx::Shell3dStudy study = vsx::shell3d_study(VS_SOURCE_DIR, args.quick);
  std::filesystem::create_directories(args.out_dir);
  vsx::Shell3dMeta meta;
  meta.scene = study.scene_path.substr(study.scene_path.find_last_of('/') + 1);
  meta.friction = study.friction;
  meta.load_average = vsx::load_average();
  const vs::Scene base = vsx::shell3d_base_scene(study);
  const vsx::AxisymRun ref = vsx::run_axisym_twin(base, study.axisym_elements);
  const vsx::AxisymRun check = vsx::run_axisym_twin(base, study.axisym_check_elements);
  if (!ref.result.completed() || !check.result.completed()) {
    std::fprintf(stderr, "axisymmetric reference failed: %s %s\n", ref.result.message.c_str(),
                 check.result.message.c_str());
    return 1;
  }
  std::vector<vsx::Shell3dRow> rows = {
      vsx::axisym_row("axisymmetric", check,
                      vsx::compare_axisym(study.outputs_mm, check.result, ref.result)),
      vsx::axisym_row("axisymmetric_reference", ref,
                      vsx::compare_axisym(study.outputs_mm, ref.result, ref.result))};
  std::printf(
      "# 3D study%s: %s, friction %s, travel %g mm; reference %d elements (%.2f s); noise "
      "vs %d elements: max |dF mean| %.2f %%, max |d eps_t| %.4f\n",
      args.quick ? " (quick)" : "", meta.scene.c_str(), study.friction.c_str(), study.travel_mm,
      study.axisym_elements, ref.wall_s, study.axisym_check_elements,
      100.0 * rows[0].dev.max_abs_mean_force, rows[0].dev.max_eps_thickness);
  const std::string csv_path = args.out_dir + "/shell3d_study.csv";
  std::ofstream csv(csv_path);
  csv << vsx::kShell3dCsvHeader << vsx::shell3d_csv_lines(meta, rows[0])
      << vsx::shell3d_csv_lines(meta, rows[1]);
  for (const vsx::Shell3dCase& c : study.cases) {
    rows.push_back(vsx::run_shell3d_case(base, c, ref.result));
    const vsx::Shell3dRow& r = rows.back();
    csv << vsx::shell3d_csv_lines(meta, r) << std::flush;
    std::printf(
        "%-15s n=%-2d %4d el %6d dofs %8.2f s wall %8.2f s CPU %4d steps %5d iters: dF "
        "%+.2f %%, dF mean %+.2f %%, max |dF| %.2f %%, max |dF mean| %.2f %%, max |d "
        "eps_t| %.4f%s\n",
        c.rule.c_str(), c.divisions, r.elements, r.dofs, r.wall_s, r.cpu_s, r.steps, r.iterations,
        100.0 * r.dev.force_at_travel, 100.0 * r.dev.mean_force_at_travel,
        100.0 * r.dev.max_abs_force, 100.0 * r.dev.max_abs_mean_force, r.dev.max_eps_thickness,
        r.completed ? "" : ("  FAILED: " + r.message).c_str());
    std::fflush(stdout);
  }
  csv.close();
  // The summary from the CSV as written (the report regenerates it the same way).
  const std::string md = vsx::shell3d_summary_from_csv(csv_path);
  if (md.empty()) {
    std::fprintf(stderr, "cannot read back %s\n", csv_path.c_str());
    return 1;
  }
  vsx::write_text(args.out_dir + "/summary.md", md);
  write_study_figure(args.out_dir);
  std::printf("wrote %s, summary.md and shell3d_work_precision.svg\n\n%s", csv_path.c_str(),
              md.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  if (!args.summarise_dir.empty()) {
    const std::string md = vsx::shell3d_summary_from_csv(args.summarise_dir + "/shell3d_study.csv");
    if (md.empty()) {
      std::fprintf(stderr, "cannot read %s/shell3d_study.csv\n", args.summarise_dir.c_str());
      return 1;
    }
    vsx::write_text(args.summarise_dir + "/summary.md", md);
    write_study_figure(args.summarise_dir);
    std::printf("%s", md.c_str());
    return 0;
  }
  if (args.study) return run_study(args);
  vs::Scene base = vs::load_scene(args.scene);
  if (args.travel > 0.0) base.process.punch_travel_mm = args.travel;
  if (!args.outputs.empty()) base.process.output_travels_mm = args.outputs;
  if (args.increment > 0.0) base.numerics.max_travel_increment_mm = args.increment;
  if (args.speed_setting) {
    base.numerics.max_travel_increment_per_length = 0.05;
    base.numerics.strain_rate_cutoff = 1e-2;
  }
  if (args.per_length > 0.0) base.numerics.max_travel_increment_per_length = args.per_length;
  if (args.cutoff > 0.0) base.numerics.strain_rate_cutoff = args.cutoff;
  if (args.shear_scale > 0.0) base.numerics.transverse_shear_scale = args.shear_scale;
  if (args.implicit) base.numerics.time_integration = vs::TimeIntegration::kImplicit;
  if (args.no_events) base.numerics.contact_events = false;
  if (args.start_refinement >= 0) base.numerics.start_refinement = args.start_refinement;
  if (args.implicit_solves > 0) base.numerics.implicit_solves = args.implicit_solves;
  if (args.contact_entry) base.numerics.contact_entry = *args.contact_entry;
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
  std::printf(
      "# scene %s, friction %s, travel %.2f mm, increment %.3f mm (at most %.3f element sizes), "
      "strain-rate cut-off %g, %d Simpson points, %d OpenMP threads\n",
      args.scene.c_str(), friction_text.c_str(), base.process.punch_travel_mm,
      base.numerics.max_travel_increment_mm, base.numerics.max_travel_increment_per_length,
      base.numerics.strain_rate_cutoff, base.numerics.thickness_points, omp_get_max_threads());
  std::printf("# axisymmetric reference: %d elements, %s, %.2f s\n", args.axisym_elements,
              axi.message.c_str(), axi_s);
  std::printf("%-6s %-15s %5s %6s %8s %8s %8s %8s %6s %11s %6s %6s %8s  %s\n", "div", "rule",
              "elem", "dofs", "wall_s", "asm_s", "fact_s", "cont_s", "nfact", "krylov", "steps",
              "iters", "rss_MB", "travel_mm:F3d_kN/Faxi_kN/dF%/dFmean%/max|deps_t| ...");
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
      vs::RunOptions run_options;
      run_options.krylov_min_unknowns = args.krylov_min;
      run_options.single_precision_preconditioner = !args.double_preconditioner;
      run_options.parallel_factorisation = !args.cholmod_factorisation;
      run_options.driver.implicit_first_tolerance_factor = args.first_tolerance_factor;
      const vs::RunResult r = vs::shell3d::simulate_shell3d(scene, run_options);
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
                             n, rule, friction_text, r.shell->mesh.num_elements(), r.dofs,
                             r.completed(), wall, r.timings.assembly_s, r.timings.linear_solve_s,
                             r.timings.contact_s, r.timings.factorisations, r.steps.size(),
                             r.total_iterations, rss, c.punch_travel_mm, c.force_3d_N,
                             c.force_axisym_N, c.force_deviation, c.mean_force_deviation,
                             c.eps_thickness_deviation_y0, c.eps_thickness_deviation_x0,
                             c.eps_thickness_deviation_diagonal);
        }
      }
      std::printf("%-6d %-15s %5d %6d %8.2f %8.2f %8.2f %8.3f %6d %11s %6zu %6d %8.1f %s%s\n", n,
                  rule.c_str(), r.shell->mesh.num_elements(), r.dofs, wall, r.timings.assembly_s,
                  r.timings.linear_solve_s, r.timings.contact_s, r.timings.factorisations,
                  fmt::format("{}/{}", r.timings.krylov_steps, r.timings.krylov_iterations).c_str(),
                  r.steps.size(), r.total_iterations, rss, devs.c_str(),
                  r.completed() ? "" : ("  FAILED: " + r.message).c_str());
      if (!r.implicit_solve_iterations.empty()) {
        std::string per_solve;
        for (int it : r.implicit_solve_iterations) per_solve += fmt::format(" {}", it);
        std::printf("#   Newton iterations per implicit solve of a step (first, second, ..):%s\n",
                    per_solve.c_str());
      }
      if (args.fine_reference > 0.0) print_against_fine_reference(scene, r, args.fine_reference);
      if (args.goal) {
        double force = 0.0, mean = 0.0, eps = 0.0, eps_rel = 0.0;
        for (const auto& c : cmp) {
          force = std::max(force, std::abs(c.force_deviation));
          mean = std::max(mean, std::abs(c.mean_force_deviation));
          eps = std::max(eps, c.max_eps_thickness_deviation());
          eps_rel =
              std::max(eps_rel, c.max_eps_thickness_deviation() / c.max_abs_eps_thickness_axisym);
        }
        const bool all = r.completed() && cmp.size() == base.process.output_travels_mm.size();
        // Two readings of "thickness strain within 2 %": absolute (|d eps_t| <= 0.01, the bound
        // of the comparison test, stricter than 2 % strain) and relative to the largest
        // axisymmetric |eps_t| at that travel.
        const bool fast = wall < 10.0;
        const bool met_abs = all && force <= 0.02 && eps <= 0.01 && fast;
        const bool met_rel = all && force <= 0.02 && eps_rel <= 0.02 && fast;
        std::printf(
            "#   goal (< 10 s, force within 2 %%, thickness strain within 2 %% at every output "
            "travel): largest |dF| %.2f %% (mean over the last mm %.2f %%), largest |d eps_t| "
            "%.4f = %.1f %% of the largest axisymmetric |eps_t|, wall %.2f s: %s with "
            "|d eps_t| <= 0.01, %s relative to the largest |eps_t|\n",
            100.0 * force, 100.0 * mean, eps, 100.0 * eps_rel, wall, met_abs ? "MET" : "not met",
            met_rel ? "MET" : "not met");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
