#include "calibrate_command.h"

#include <fmt/format.h>
#include <glog/logging.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "calibrate.h"
#include "calibration_config.h"
#include "default_forward_model.h"
#include "output/run_folder.h"

namespace vs {
namespace {

struct CalibrateArgs {
  std::string config;
  std::string output_directory;
  bool quiet = false;
};

// Input errors (InputError) propagate to vshell's main: "error: ..." on stderr, exit code 2.
// A calibration that could not fit (every forward run failing, ...) is a failed run: the report
// is written, the reason goes to stderr as one line and the exit code is 3.
int run_calibrate(const CalibrateArgs& args) {
  // Ceres reports a failed solve through glog as well ("Terminating: ..."), before
  // InitGoogleLogging; the reason is in the result and printed below, so glog stays quiet.
  FLAGS_minloglevel = google::GLOG_FATAL;
  const CalibrationConfig config = load_calibration_config(args.config);
  // The report goes to a staging folder that replaces the output folder when it is complete
  // (output/run_folder.h); a folder that is not an earlier report is refused before the fit.
  RunFolder folder(args.output_directory.empty() ? config.output_directory : args.output_directory,
                   "calibration.json");
  CalibrationOptions options;
  options.output_directory = folder.path();
  options.report_destination = folder.destination();
  if (!args.quiet) {
    options.progress = [](const std::string& line) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    };
  }
  CalibrationResult result = calibrate(config, options, make_default_forward_model());
  folder.commit();
  result.output_directory = folder.destination();
  fmt::print("{}", result.brief_report());
  std::fflush(stdout);
  if (result.termination != CalibrationTermination::kFailed) return 0;
  std::string reason = result.message;
  for (char& c : reason) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  fmt::print(stderr, "error: calibration failed: {}\n", reason);
  return 3;
}

}  // namespace

void add_calibrate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* sub = app.add_subcommand(
      "calibrate", "Identify scene parameters (friction, hardening, R, ...) from measured curves");
  sub->footer(
      "The config format, every key with its default, unit and range, the measurement CSV "
      "format and the report files: docs/calibration-reference.md (also printed by `vshell "
      "print-calibration-reference`). Exit codes: 0 done, 2 bad input, 3 calibration failed.");
  sub->add_option("CONFIG", args->config,
                  "Calibration file (TOML); every key is documented in "
                  "docs/calibration-reference.md (`vshell print-calibration-reference`)")
      ->required();
  sub->add_option("-o,--output", args->output_directory,
                  "Report folder (overrides [output] directory)");
  sub->add_flag("--quiet", args->quiet, "Print only the final summary");
  sub->callback([args, &exit_code] { exit_code = run_calibrate(*args); });
}

}  // namespace vs
