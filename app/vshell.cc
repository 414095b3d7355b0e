// vshell: the forward solver's command line. Parsing, scene loading and output only; the physics
// lives in vs_physics and the files in vs_output.
//
//   vshell run SCENE [-o DIR] [--set ADDRESS=VALUE ...] [--quiet | --verbose]
//   vshell check SCENE [--set ADDRESS=VALUE ...]
//   vshell print-defaults | print-reference | print-calibration-reference
//   vshell calibrate ...            (app/calibrate_command.h)
//
// Exit codes: 0 run completed (or command done), 2 bad input (scene, options, unwritable output
// folder), 3 the run failed but its results up to the failure were written, 1 anything else.
#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "calibrate_command.h"
#include "calibration_keys.h"
#include "core/error.h"
#include "fit_hardening_command.h"
#include "output/build_info.h"
#include "output/load_travel_stream.h"
#include "output/progress.h"
#include "output/run_folder.h"
#include "output/run_summary.h"
#include "output/run_writer.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "scene/scene.h"
#include "scene/scene_table.h"

namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitRunFailed = 3;

struct SceneArgs {
  std::string path;
  std::vector<std::string> sets;  // ADDRESS=VALUE overrides, applied in order
};

struct RunArgs {
  SceneArgs scene;
  std::string output_dir;
  bool quiet = false;
  bool verbose = false;
};

// The scene file with the --set overrides applied, validated exactly as load_scene() would.
vs::Scene load_scene_with_overrides(const SceneArgs& args) {
  toml::table table = vs::read_scene_table(args.path);
  for (const std::string& set : args.sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw vs::InputError("--set " + set +
                           ": expected ADDRESS=VALUE, e.g. tool.punch.friction=0.1");
    }
    vs::set_scene_value_from_text(table, set.substr(0, eq), set.substr(eq + 1));
  }
  return vs::scene_from_table(table, args.path, fs::path(args.path).parent_path().string());
}

void add_scene_args(CLI::App& command, SceneArgs& args) {
  command
      .add_option("SCENE", args.path, "Scene file (TOML); `vshell print-defaults` shows every key")
      ->required()
      ->type_name("FILE");
  // One value per --set so that `--set a=1 scene.toml` cannot swallow the scene path.
  command
      .add_option("--set", args.sets,
                  "Override one scene value before validation, in the scene's units (mm, N, s, "
                  "MPa), e.g. --set tool.punch.friction=0.1 --set material.hardening.K_MPa=520 "
                  "--set process.punch_travel_mm=30 (friction=inf: sticking). Repeatable")
      ->type_name("ADDRESS=VALUE")
      ->allow_extra_args(false);
}

// The line of RunResult::built with this label, without it ("-" if there is none).
std::string built_line(const vs::RunResult& result, std::string_view label) {
  for (const std::string& line : result.built) {
    if (line.rfind(label, 0) == 0) return line.substr(label.size());
  }
  return "-";
}

int run_command(const RunArgs& args) {
  const vs::Scene scene = load_scene_with_overrides(args.scene);
  // The run writes into a staging folder that replaces the output folder only when it is
  // complete (output/run_folder.h): the folder always describes exactly one run.
  vs::RunFolder folder(args.output_dir.empty() ? scene.output.directory : args.output_dir,
                       "run.json");
  const std::string& dir = folder.path();
  // Streamed so that a crash keeps every converged step; rewritten identically at the end.
  vs::LoadTravelStream stream((fs::path(dir) / "load_travel.csv").string());
  vs::ProgressPrinter::Options progress_options;
  progress_options.total_travel_mm = scene.process.punch_travel_mm;
  progress_options.quiet = args.quiet;
  vs::ProgressPrinter progress(progress_options, std::cerr);

  vs::RunOptions options;
  options.verbose = args.verbose;
  options.on_step = [&](const vs::StepRecord& record) {
    stream.append(record);
    progress.update(record);
  };
  const auto start = std::chrono::steady_clock::now();
  const vs::RunResult result = vs::simulate(scene, options);
  progress.finish();
  vs::write_run_folder(scene, result, dir);
  stream.close();
  folder.commit();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const vs::RunSummary summary = vs::summarize_run(scene, result);
  for (const std::string& w : summary.warnings) std::cerr << "warning: " << w << '\n';
  const vs::RunTimings& t = result.timings;
  std::cout << vs::summary_report(summary) << '\n'
            << fmt::format("model             {}\n", built_line(result, "model: "))
            << fmt::format("update            {}\n", built_line(result, "time integration: "))
            << fmt::format(
                   "time split        assembly {:.2f} s, linear solves {:.2f} s, contact {:.2f} s "
                   "of {:.2f} s\n",
                   t.assembly_s, t.linear_solve_s, t.contact_s, t.total_s)
            << fmt::format("wall time         {:.2f} s\n", wall_s)
            << fmt::format("output folder     {}\n", folder.destination());
  return result.completed() ? kExitOk : kExitRunFailed;
}

int check_command(const SceneArgs& args) {
  const vs::Scene scene = load_scene_with_overrides(args);
  std::string tools;
  for (const vs::ToolSpec& tool : scene.tools) tools += (tools.empty() ? "" : ", ") + tool.name;
  if (scene.geometry == vs::Geometry::kShell3d) {
    std::cout << "ok\n"
              << fmt::format(
                     "{}: \"{}\": 3D shell, {} {} mm, thickness {} mm, {} model, {} "
                     "divisions{}; tools: {}; punch travel {} mm\n",
                     scene.source, scene.title,
                     scene.blank.shape == vs::BlankShape::kCircle ? "circular blank, radius"
                                                                  : "square blank, half side",
                     scene.blank.radius_mm, scene.blank.thickness_mm,
                     scene.blank.symmetry == vs::BlankSymmetry::kFull ? "full" : "quarter",
                     scene.blank.divisions,
                     scene.blank.shape == vs::BlankShape::kCircle &&
                             scene.blank.ring_divisions() != scene.blank.divisions
                         ? fmt::format(" ({} across the ring)", scene.blank.ring_divisions())
                         : std::string(),
                     tools.empty() ? "none" : tools, scene.process.punch_travel_mm);
    return kExitOk;
  }
  std::cout << "ok\n"
            << fmt::format(
                   "{}: \"{}\": blank radius {} mm, thickness {} mm, {} elements; tools: {}; "
                   "punch travel {} mm\n",
                   scene.source, scene.title, scene.blank.radius_mm, scene.blank.thickness_mm,
                   scene.blank.elements, tools.empty() ? "none" : tools,
                   scene.process.punch_travel_mm);
  return kExitOk;
}

void print_text(const std::string& text) {
  std::cout << text;
  if (!text.empty() && text.back() != '\n') std::cout << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  // The 3D element loops use an OpenMP team of one thread per core. On a machine that is busy
  // with other work, a team whose partner thread is descheduled spins at every barrier (measured:
  // the 3D cup of data/calibration to 8 mm beside two CalculiX runs, 10.1 s with two threads,
  // 2.4 s with one). Unless the user sizes the team (OMP_NUM_THREADS, OMP_DYNAMIC), let OpenMP
  // size it to the idle cores (libgomp: cores minus the 15-minute load average, at least one).
  // The answer does not depend on the team size (the assembly sums in a fixed order).
  if (std::getenv("OMP_NUM_THREADS") == nullptr && std::getenv("OMP_DYNAMIC") == nullptr) {
    omp_set_dynamic(1);
  }
  CLI::App app{
      "vshell: thin sheet-metal forming with the viscous shell formulation (Onate & Zienkiewicz "
      "1983), axisymmetric (geometry = \"axisymmetric\") or general 3D (geometry = "
      "\"shell3d\"), and its calibration."};
  app.footer(
      "Units everywhere: mm, N, s, MPa. Exit codes: 0 done, 2 bad input, 3 run failed (results "
      "up to the failure kept), 1 internal error.");
  app.set_version_flag(
      "--version", fmt::format("vshell {} ({})", vs::program_version(), vs::program_git_describe()),
      "Print the program version and exit");
  app.require_subcommand(1);
  int exit_code = kExitOk;

  RunArgs run_args;
  CLI::App* run = app.add_subcommand(
      "run",
      "Run a scene (either geometry) and write its run folder: scene.toml (the scene as run, "
      "every key with the value used: runs again as is), load_travel.csv (streamed during "
      "the run), thinnest_point.csv, strains_travel_<travel>mm.csv (3D: "
      "strains_travel_<travel>mm_<line>.csv for the lines x, y, diagonal), fld_points.csv "
      "(with each element's margin to the forming-limit curve of [forming_limit]), "
      "strain_paths.csv (axisymmetric with output.history), stage_<k>.vtu + stages.pvd (3D, "
      "ParaView, stage_0 at zero travel), cup_profile.csv + cup_profile.svg (3D with a free "
      "blank edge: rim height against the angle from the rolling direction), SVG plots and "
      "run.json");
  add_scene_args(*run, run_args.scene);
  run->add_option("-o,--output", run_args.output_dir,
                  "Output folder, created if missing (default: the scene's output.directory, "
                  "relative to the current folder)")
      ->type_name("DIR");
  CLI::Option* quiet =
      run->add_flag("-q,--quiet", run_args.quiet, "No progress lines; print only the summary");
  run->add_flag("-v,--verbose", run_args.verbose,
                "Also print every step's nonlinear iteration table to stderr")
      ->excludes(quiet);
  run->callback([&] { exit_code = run_command(run_args); });

  SceneArgs check_args;
  CLI::App* check = app.add_subcommand(
      "check", "Validate a scene (with any --set overrides) and print a one-line summary");
  add_scene_args(*check, check_args);
  check->callback([&] { exit_code = check_command(check_args); });

  app.add_subcommand("print-defaults",
                     "Print an annotated scene file with every key, its default, unit and range")
      ->callback([] { print_text(vs::scene_defaults_toml()); });
  app.add_subcommand("print-reference", "Print the scene key reference (Markdown)")->callback([] {
    print_text(vs::scene_reference_markdown());
  });
  app.add_subcommand("print-calibration-reference",
                     "Print the calibration config reference (Markdown, "
                     "docs/calibration-reference.md)")
      ->callback([] { print_text(vs::calibration_reference_markdown()); });

  vs::add_calibrate_command(app, exit_code);
  vs::add_fit_hardening_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0; every real parse error is bad input.
    return app.exit(e) == 0 ? kExitOk : kExitBadInput;
  } catch (const CLI::Error& e) {
    return app.exit(e);  // CLI::RuntimeError(code) from a subcommand
  } catch (const vs::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitInternal;
  }
  return exit_code;
}
