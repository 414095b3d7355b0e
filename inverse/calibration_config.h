// A calibration, as read from its TOML file. Every key is declared once, with type, unit, range,
// default and documentation, in calibration_keys.cc; docs/calibration-reference.md is generated
// from that declaration (vshell print-calibration-reference).
//
// Unknown keys, wrong types and out-of-range values are InputErrors naming file:line and the key.
// The measurement files are read and checked here too, so every configuration and data error is
// raised before any forward run.
#pragma once

#include <algorithm>
#include <optional>
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

// Default data.relative_sigma: a data set with no sigma, weight or sigma column gets
// sigma = 1 % of the range (max - min) of its measured ordinate.
inline constexpr double kDefaultRelativeSigma = 0.01;

struct DataSpec {
  Measurement measurement;  // already read and checked; name and travel_mm filled in
  std::string scene;        // SceneEntry::name; empty = the only scene
  double sigma = 0.0;       // > 0: weights 1/sigma (unless the CSV has a sigma column)
  double weight = 0.0;      // > 0: weights = weight
  // Used when sigma, weight and the sigma column are all absent: sigma = relative_sigma x the
  // range of the measured ordinate (data_set_sigma()).
  double relative_sigma = kDefaultRelativeSigma;
  bool shape_only = false;  // cup_height_profile: fit up to a constant offset (cup_height_curve.h)
  std::string where;        // config file:line
};

// How a data set's points are weighted, for the weights and the report.
struct DataSigma {
  double sigma = 0.0;  // per-point sigma when uniform (0 with a sigma column or a weight)
  std::string text;    // "sigma = 50 N (given)", "sigma = 0.0021 (1 % of the measured range)"
};
// Throws InputError for a relative default on a curve of zero range.
DataSigma data_set_sigma(const DataSpec& d);

enum class OptimizerMethod { kLevenbergMarquardt, kGlobalThenLocal };

// Default optimizer.noise_floor_factor: the forward outputs are taken to be resolved to
// factor x forward tolerance x each curve's largest |value|. experiments/06_step_stability
// measured the jitter at tolerance 1e-8 as ~1e-8 of the force and ~5e-8 in thickness strain
// (strains up to ~0.3: ~2e-7 of the curve), i.e. 1x and ~17x the tolerance; 20 covers both.
inline constexpr double kDefaultNoiseFloorFactor = 20.0;

struct OptimizerSettings {
  OptimizerMethod method = OptimizerMethod::kLevenbergMarquardt;
  LeastSquaresOptions least_squares;  // progress and residual_noise are set by calibrate()
  FdOptions fd;
  GlobalSearchOptions global;
  int threads = 2;
  double noise_floor_factor = kDefaultNoiseFloorFactor;  // 0: no noise-floor stop
};

// One alternative model choice of the model-form sensitivity ([[model_form]]): the fit is
// repeated with these scene edits added to [forward.set], from the identified values.
struct ModelFormSpec {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;  // address, value as text
  std::string where;                                           // config file:line
  std::vector<std::string> drop_data;  // data sets (names) the alternative fit leaves out
  // The [[discrepancy]] sources (names) the alternative keeps; all when unset, none when empty.
  std::optional<std::vector<std::string>> discrepancy;
  bool drops(const std::string& data_name) const {
    return std::find(drop_data.begin(), drop_data.end(), data_name) != drop_data.end();
  }
};

// A model-discrepancy source ([[discrepancy]]): the curves of a higher-fidelity reference model
// (a continuum FE run, ...) at known parameters, one per data set it covers. calibrate() runs the
// forward model at the same parameters and adds, at every data point, reference - forward to the
// simulated values of the fit (the bias term of Kennedy and O'Hagan, J. R. Statist. Soc. B 63,
// 2001, here fixed at its value at the reference's parameters: the forward model's model-form
// error under the data's conditions, taken to change little with the parameters; each source
// alone is a model-form alternative, which measures that). Several sources: their mean.
struct DiscrepancySpec {
  std::string name;
  // The reference's parameters (every free one) and any other scene edits, as in [forward.set].
  std::vector<std::pair<std::string, std::string>> set;
  // Data-set name and the reference's curve for it (read with the data set's kind).
  std::vector<std::pair<std::string, Measurement>> references;
  std::string where;  // config file:line
};

struct CalibrationConfig {
  std::string path;  // the config file ("" when built in code)
  std::vector<SceneEntry> scenes;
  std::vector<ParameterSpec> parameters;
  std::vector<DataSpec> data;
  OptimizerSettings optimizer;
  UncertaintyOptions uncertainty;
  ForwardSettings forward;
  std::vector<ModelFormSpec> model_forms;
  std::vector<DiscrepancySpec> discrepancies;
  // With two or more discrepancy sources, calibrate() adds a model-form alternative per source
  // (that source alone); false in the refits themselves.
  bool discrepancy_alternatives = true;
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
