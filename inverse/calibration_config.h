// A calibration, as read from its TOML file:
//
//   scene = "../scenes/ex1_hemispherical_stretching.toml"   # relative to this file
//   # or several scenes, each data set then names its scene:
//   # [[scene]]  name = "stretch"  file = "stretch.toml"
//
//   [[parameter]]
//   address = "tool.punch.friction"   # dotted scene address (scene/scene_table.h)
//   initial = 0.05                    # default: the scene's value
//   lower = 0.0                       # default: -inf (global search needs finite bounds)
//   upper = 0.5                       # default: +inf
//   scale = 0.01                      # typical magnitude; default: |initial| (1 if 0)
//   fixed = false
//
//   [[data]]
//   kind = "load_travel"              # | thickness_strain | circumferential_strain
//   file = "load.csv"                 # relative to this file (measurement.h for the format)
//   sigma = 50.0                      # std dev in internal units (N, strain); or weight = ...
//   travel_mm = 20                    # profiles only: the punch travel they were taken at
//   name = "load"                     # optional label; default: file name without .csv
//   scene = "stretch"                 # only with several scenes
//
//   [optimizer]
//   method = "levenberg_marquardt"    # | "global_then_local"
//   max_iterations = 50               # Ceres iterations
//   function_tolerance = 1e-10
//   gradient_tolerance = 1e-12
//   parameter_tolerance = 1e-10
//   fd = "central"                    # | "ridders"
//   relative_step = 2e-3              # FD step = relative_step * scale
//   ridders_levels = 3
//   threads = 2                       # parallel forward runs
//   global_algorithm = "mlsl_lds"     # global_then_local: | crs2 | direct | bobyqa
//   seed = 1                          # global_then_local: NLopt seed
//   max_evaluations = 200             # global_then_local: NLopt evaluation limit
//
//   [uncertainty]
//   confidence = 0.95
//   scale_by_residual_variance = true
//   correlation_threshold = 0.95
//   relative_error_threshold = 0.1
//
//   [forward]
//   tolerance = 1e-9                  # overrides numerics.tolerance during calibration
//   [forward.set]                     # any other scene edits, e.g. a coarser mesh
//   "blank.elements" = 24
//
//   [output]
//   directory = "calib_out"           # relative to the current working directory
//   plots = true
//
// Unknown keys and wrong types are InputErrors naming file:line and the key. The measurement
// files are read and checked here too, so every configuration and data error is raised before
// any forward run.
#pragma once

#include <string>
#include <vector>

#include "fd_jacobian.h"
#include "global_search.h"
#include "least_squares.h"
#include "measurement.h"
#include "parameter_spec.h"
#include "scene_binding.h"
#include "uncertainty.h"

namespace vs {

struct SceneEntry {
  std::string name;   // label data sets refer to; "scene" when there is one
  std::string path;   // resolved path of the scene file
  std::string where;  // config file:line
};

struct DataSpec {
  Measurement measurement;  // already read and checked; name and travel_mm filled in
  std::string scene;        // SceneEntry::name; empty = the only scene
  double sigma = 0.0;       // > 0: weights 1/sigma (unless the CSV has a sigma column)
  double weight = 0.0;      // > 0: weights = weight
  std::string where;        // config file:line
};

enum class OptimizerMethod { kLevenbergMarquardt, kGlobalThenLocal };

struct OptimizerSettings {
  OptimizerMethod method = OptimizerMethod::kLevenbergMarquardt;
  LeastSquaresOptions least_squares;  // progress is set by calibrate()
  FdOptions fd;
  GlobalSearchOptions global;
  int threads = 2;
};

struct CalibrationConfig {
  std::string path;  // the config file ("" when built in code)
  std::vector<SceneEntry> scenes;
  std::vector<ParameterSpec> parameters;
  std::vector<DataSpec> data;
  OptimizerSettings optimizer;
  UncertaintyOptions uncertainty;
  ForwardSettings forward;
  std::string output_directory = "calib_out";
  bool plots = true;
};

// Reads the config, the measurement files it names, and checks everything that can be checked
// without the scenes (calibrate() checks the rest, also before any forward run).
CalibrationConfig load_calibration_config(const std::string& path);

}  // namespace vs

namespace vs {

// The checks that do not need the scenes: at least one free parameter and one data set, valid
// parameters (bounds contain the start, scale > 0, no duplicates), each data set weighted,
// profile travels given, data-set names usable as file names, valid optimiser settings, finite
// bounds for a global search, at least as many points as free parameters. Throws InputError.
void validate_calibration_config(const CalibrationConfig& config);

}  // namespace vs
