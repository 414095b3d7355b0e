#include "calibrate_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "calibrate.h"
#include "calibration_config.h"
#include "core/error.h"
#include "default_forward_model.h"

namespace vs {
namespace {

struct CalibrateArgs {
  std::string config;
  std::string output_directory;
  bool quiet = false;
};

void run_calibrate(const CalibrateArgs& args) {
  try {
    const CalibrationConfig config = load_calibration_config(args.config);
    CalibrationOptions options;
    options.output_directory = args.output_directory;
    if (!args.quiet) {
      options.progress = [](const std::string& line) {
        fmt::print("{}\n", line);
        std::fflush(stdout);
      };
    }
    const CalibrationResult result = calibrate(config, options, make_default_forward_model());
    fmt::print("{}", result.brief_report());
    if (result.termination == CalibrationTermination::kFailed) throw CLI::RuntimeError(1);
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    throw CLI::RuntimeError(2);
  }
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* sub = app.add_subcommand(
      "calibrate", "Identify scene parameters (friction, hardening, R, ...) from measured curves");
  sub->add_option("CONFIG", args->config, "Calibration file (TOML)")->required();
  sub->add_option("-o,--output", args->output_directory,
                  "Report folder (overrides [output] directory)");
  sub->add_flag("--quiet", args->quiet, "Print only the final summary");
  sub->callback([args] { run_calibrate(*args); });
}

}  // namespace vs
