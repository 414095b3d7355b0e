// Issue 17: the cup-height (earing) profile of 3D cup draws against the measured ESAFORM 2021
// AA6016-T4 profile. Runs every scene given on the command line (with the --set overrides added
// to each), takes the rim profile of the final stage (output/cup_profile.h: rim height against
// the angle from the rolling direction, a quarter model unfolded to 360 deg) and writes
//   DIR/earing_study.csv, DIR/earing_study.md   one row per run: scene, symmetry, divisions,
//                                               steps, factorisations, wall time, final travel,
//                                               mean height, min, max, amplitude, ears, valleys
//                                               and the differences to the measured profile
//   DIR/<k>_<scene>_cup_profile.csv             the profile of run k (as a run folder's
//                                               cup_profile.csv)
//   DIR/earing_profiles.svg                     every run's profile and the measured points
//   DIR/reference_profiles.csv                  with --reference: the same summary of each
//                                               reference profile (other codes' results)
// See README.md next to this file.
//
//   earing_study [SCENE.toml ...] [--set KEY=VALUE ...] [--measured FILE] [--reference FILE ...]
//                [--out DIR] [--quick]
// --measured: the measured profile (default: the ESAFORM 2021 file in data/measured/);
// --reference: a profile file computed elsewhere (repeatable; the format of --measured), summarised
//   and plotted (thin dashed lines) beside the runs; with references, the scenes may be omitted;
// --quick: the first scene only.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "common/harness.h"
#include "common/table.h"
#include "core/error.h"
#include "output/cup_profile_output.h"
#include "output/cup_profile_summary.h"
#include "output/svg_plot.h"
#include "scene/cup_profile_file.h"

namespace {

using namespace vsx;

const std::string kDefaultMeasured =
    std::string(VS_SOURCE_DIR) +
    "/data/measured/esaform2021-aa6016t4-cup/AA6016_Experiment_Fig91_CupProfile_angle.txt";

struct Args {
  std::vector<std::string> scenes;
  std::string measured = kDefaultMeasured;
  std::vector<std::string> references;
  StudyArgs study;
};

// Scene files are the arguments that are not options or option values; the rest goes to the
// shared parser (--set, --out, --quick).
Args parse(int argc, char** argv) {
  Args a;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--measured" && i + 1 < argc) {
      a.measured = argv[++i];
    } else if (s == "--reference" && i + 1 < argc) {
      a.references.push_back(argv[++i]);
    } else if ((s == "--set" || s == "--out" || s == "--steps") && i + 1 < argc) {
      rest.push_back(argv[i]);
      rest.push_back(argv[++i]);
    } else if (s.rfind("--", 0) == 0) {
      rest.push_back(argv[i]);
    } else {
      a.scenes.push_back(s);
    }
  }
  a.study = parse_args(static_cast<int>(rest.size()), rest.data(),
                       std::string(VS_SOURCE_DIR) + "/experiments/10_earing/results");
  if (a.scenes.empty() && a.references.empty()) {
    std::cerr << "usage: " << argv[0]
              << " [SCENE.toml ...] [--set KEY=VALUE ...] [--measured FILE] "
                 "[--reference FILE ...] [--out DIR] [--quick]\n";
    std::exit(2);
  }
  if (a.study.quick && !a.scenes.empty()) a.scenes.resize(1);
  return a;
}

std::string angles(const std::vector<vs::ProfileExtremum>& list) {
  if (list.empty()) return "-";
  std::string s;
  for (const vs::ProfileExtremum& e : list)
    s += fmt::format("{}{:.1f}", s.empty() ? "" : " ", e.angle_deg);
  return s;
}

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// The summary columns shared by the runs' table and the references' table.
std::vector<std::string> summary_cells(const vs::CupProfileSummary& s,
                                       const vs::CupProfileSummary& measured) {
  return {std::to_string(s.points),
          fmt::format("{:.3f}", s.mean_height_mm),
          fmt::format("{:.3f}", s.min_height_mm),
          fmt::format("{:.3f}", s.max_height_mm),
          fmt::format("{:.3f}", s.amplitude_mm),
          angles(s.ears),
          angles(s.valleys),
          fmt::format("{:+.3f}", s.mean_height_mm - measured.mean_height_mm),
          fmt::format("{:.3f}", s.amplitude_mm / measured.amplitude_mm),
          g4(vs::max_extremum_offset_deg(s.ears, measured.ears))};
}

const std::vector<std::string> kSummaryHeader = {
    "rim_points",    "mean_height_mm",         "min_height_mm",
    "max_height_mm", "amplitude_mm",           "ears_deg",
    "valleys_deg",   "mean_minus_measured_mm", "amplitude_over_measured",
    "ear_offset_deg"};

// Reference profiles (other codes' results): one summary row each, and a thin dashed line each.
Table reference_table(const std::vector<std::string>& files, const vs::CupProfileSummary& measured,
                      vs::SvgFigure& figure) {
  Table table;
  table.header = {"reference"};
  table.header.insert(table.header.end(), kSummaryHeader.begin(), kSummaryHeader.end());
  for (const std::string& file : files) {
    const vs::CupProfilePoints p = vs::read_cup_profile_file(file);
    const vs::CupProfileSummary s = vs::summarize_cup_profile(p.angle_deg, p.height_mm);
    std::vector<std::string> row = {stem(file)};
    const std::vector<std::string> cells = summary_cells(s, measured);
    row.insert(row.end(), cells.begin(), cells.end());
    table.add(row);
    vs::PlotSeries line;
    line.x = p.angle_deg;
    line.y = p.height_mm;
    line.colour = 7;
    line.dashed = true;
    line.line_width_px = 0.8;
    figure.series.push_back(std::move(line));
  }
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  Overrides overrides;
  for (const auto& [k, v] : args.study.sets) overrides.push_back({k, v});
  vs::CupProfilePoints measured;
  vs::CupProfileSummary ms;
  try {
    measured = vs::read_cup_profile_file(args.measured);
    ms = vs::summarize_cup_profile(measured.angle_deg, measured.height_mm);
  } catch (const vs::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::filesystem::create_directories(args.study.out_dir);
  fmt::print("measured {}: mean {:.3f} mm, {:.3f}-{:.3f} mm, amplitude {:.3f} mm, ears {}\n",
             args.measured, ms.mean_height_mm, ms.min_height_mm, ms.max_height_mm, ms.amplitude_mm,
             angles(ms.ears));
  fmt::print("machine: {}, load average {} at start\n", machine_description(), load_average());

  Table table;
  table.header = {"run",   "scene",          "overrides", "symmetry",        "divisions",
                  "steps", "factorisations", "wall_s",    "final_travel_mm", "run_end"};
  table.header.insert(table.header.end(), kSummaryHeader.begin(), kSummaryHeader.end());
  vs::SvgFigure figure;
  figure.title = "Cup height around the rim: computed profiles and the measured ESAFORM 2021 cup";
  figure.x_label = "angle from the rolling direction [deg]";
  figure.y_label = "cup height [mm]";
  figure.x_range = vs::AxisRange{0.0, 360.0};
  int failures = 0;
  for (std::size_t k = 0; k < args.scenes.size(); ++k) {
    const std::string& path = args.scenes[k];
    vs::Scene scene;
    try {
      scene = make_scene(path, overrides);
    } catch (const vs::InputError& e) {
      std::cerr << e.what() << "\n";
      return 2;
    }
    const TimedRun run = run_once(scene, std::numeric_limits<double>::infinity());
    const vs::RunResult& r = run.result;
    const vs::CupProfileReport report = vs::cup_profile_report(scene, r);
    const std::string label = fmt::format("{}_{}", k + 1, stem(path));
    std::vector<std::string> row = {
        std::to_string(k + 1),
        stem(path),
        describe(overrides),
        scene.blank.symmetry == vs::BlankSymmetry::kFull ? "full" : "quarter",
        std::to_string(scene.blank.divisions),
        std::to_string(r.steps.size()),
        std::to_string(r.timings.factorisations),
        fmt::format("{:.1f}", run.wall_s),
        r.steps.empty() ? "-" : fmt::format("{:.2f}", r.steps.back().punch_travel_mm),
        r.completed() ? "completed" : "failed: " + r.message};
    if (!report.available) {
      ++failures;
      row.push_back(report.reason.empty() ? "no profile" : report.reason);
      while (row.size() < table.header.size()) row.push_back("-");
      table.add(row);
      fmt::print("run {} ({}): no profile: {}\n", k + 1, path, report.reason);
      continue;
    }
    const vs::CupProfileSummary& s = report.summary;
    const std::vector<std::string> cells = summary_cells(s, ms);
    row.insert(row.end(), cells.begin(), cells.end());
    table.add(row);
    write_text(args.study.out_dir + "/" + label + "_cup_profile.csv",
               vs::cup_profile_csv(report.profile));
    vs::PlotSeries line = vs::cup_profile_series(report.profile);
    line.label = fmt::format("{} {} n={}", k + 1, stem(path), scene.blank.divisions);
    line.style = vs::SeriesStyle::kLineAndMarkers;
    line.colour = static_cast<int>(k) + 1;
    figure.series.push_back(std::move(line));
    fmt::print(
        "run {} ({}{}): {} steps, {} factorisations, {:.1f} s, mean {:.3f} mm, amplitude "
        "{:.3f} mm, ears {}\n",
        k + 1, path, cli_args(overrides), r.steps.size(), r.timings.factorisations, run.wall_s,
        s.mean_height_mm, s.amplitude_mm, angles(s.ears));
  }
  Table references;
  try {
    references = reference_table(args.references, ms, figure);
  } catch (const vs::InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (!args.references.empty()) figure.series.back().label = "other codes (--reference), dashed";
  vs::PlotSeries m;
  m.label = "measured (ESAFORM 2021, Habraken et al. 2022 Fig. 91)";
  m.colour = 0;
  m.style = vs::SeriesStyle::kMarkers;
  m.marker_radius_px = 3.5;
  m.x = measured.angle_deg;
  m.y = measured.height_mm;
  figure.series.push_back(std::move(m));

  if (!args.scenes.empty()) write_text(args.study.out_dir + "/earing_study.csv", table.csv());
  if (!args.references.empty())
    write_text(args.study.out_dir + "/reference_profiles.csv", references.csv());
  const std::string md = fmt::format(
      "# Earing study\n\nMeasured ({}): mean {:.3f} mm, min {:.3f} mm, max {:.3f} mm, amplitude "
      "{:.3f} mm, ears at {} deg, valleys at {} deg.\n\nMachine: {}; load average {} at the "
      "end.\n\n{}{}",
      std::filesystem::path(args.measured).filename().string(), ms.mean_height_mm, ms.min_height_mm,
      ms.max_height_mm, ms.amplitude_mm, angles(ms.ears), angles(ms.valleys), machine_description(),
      load_average(), args.scenes.empty() ? std::string() : table.markdown(),
      args.references.empty()
          ? std::string()
          : "\n## Reference profiles (other codes)\n\n" + references.markdown());
  write_text(args.study.out_dir + "/earing_study.md", md);
  vs::write_svg(figure, args.study.out_dir + "/earing_profiles.svg");
  if (!args.scenes.empty()) std::cout << table.text();
  if (!args.references.empty()) std::cout << references.text();
  return failures == 0 ? 0 : 1;
}
