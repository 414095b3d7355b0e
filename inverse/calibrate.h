// The calibration toolkit's entry point: base scene(s) + parameters + measured curves ->
// identified parameters with uncertainty, a log of every forward run, and a report folder.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "calibration_config.h"
#include "discrepancy.h"
#include "forward_cache.h"
#include "forward_model.h"
#include "lack_of_fit.h"
#include "uncertainty.h"

namespace vs {

struct CalibrationOptions {
  // Progress lines (one per optimiser iteration, plus a few stage lines). Empty = silent.
  std::function<void(const std::string&)> progress;
  // Also a progress line for every forward evaluation whose runs took at least this long in
  // total [s] (3D runs take minutes, and an iteration needs several).
  double progress_evaluation_s = 2.0;
  bool write_report = true;
  // Replaces config.output_directory when not empty (vshell calibrate -o DIR).
  std::string output_directory;
  // Where the report ends up, when output_directory is a staging folder that replaces it at the
  // end (vshell calibrate); "" = output_directory. The identified scenes run beside it.
  std::string report_destination;
  // Statistical uncertainty at the optimum (one more Jacobian); the model-form refits skip it.
  bool uncertainty = true;
};

enum class CalibrationTermination {
  kConverged,     // Ceres met a convergence tolerance
  kNotConverged,  // iteration limit: the last point is reported but is not an optimum
  kFailed,        // no usable point (e.g. the forward model fails at the start)
};

std::string to_string(CalibrationTermination termination);

// Measured against simulated at the optimum, for one data set (fit_<name>.csv and the plots).
struct DataSetFit {
  std::string name;
  MeasurementKind kind = MeasurementKind::kLoadTravel;
  double travel_mm = 0.0;
  std::vector<double> x, measured, simulated, weight;
  double cost = 0.0;            // 0.5 sum of weighted squared residuals
  double rms_difference = 0.0;  // sqrt(mean((simulated - measured)^2)), in N, strain or mm
  bool ok = false;
  // cup_height_profile with shape_only: `simulated` includes this offset (cup_height_curve.h).
  bool shape_only = false;
  double shape_offset_mm = 0.0;
  LackOfFit lack_of_fit;  // of weight x (simulated - measured), in abscissa order
  // The discrepancy correction included in `simulated` (discrepancy.h); empty: none.
  std::vector<double> correction;
};

// A free parameter that ended on a bound, and what the bound does to the fit: the cost
// gradient there and, from the linearised model with the other parameters held, where the fit
// would go without the bound and how much lower the cost would be.
struct BoundEffect {
  std::string name;
  int side = 0;  // -1 lower, +1 upper
  double bound = 0.0;
  double gradient = 0.0;       // d cost / d parameter at the bound, own units
  bool active = false;         // the gradient pushes outward: the bound holds the fit back
  double unconstrained = 0.0;  // value - gradient / (J^T J)_jj
  double cost_decrease = 0.0;  // gradient^2 / (2 (J^T J)_jj), when active
  std::string text;
};

// The fit repeated under one alternative model choice ([[model_form]]).
struct ModelFormFit {
  std::string name;
  std::string edits;                      // "blank.elements=48 ...", ", without data thick_15"
  std::vector<std::string> dropped_data;  // ModelFormSpec::drop_data
  std::string termination;
  std::string message;
  std::vector<double> values;  // free parameters, free order (empty if it failed)
  double final_cost = 0.0;
  int forward_runs = 0;
  std::vector<std::string> forward_warnings;  // its CalibrationResult::forward_warnings
};

// Per free parameter: the smallest and largest identified value over the main fit and every
// model-form fit.
struct ModelFormRange {
  std::string name;
  double lower = 0.0;
  double upper = 0.0;
  bool exceeds_interval = false;  // the range is wider than the statistical interval
};

struct ParameterResult {
  ParameterSpec spec;  // as used (initial and scale filled in from the scene when defaulted)
  std::string unit;
  double value = 0.0;  // identified (or the fixed value)
};

// How one data set was weighted (DataSigma::text), stated in the report.
struct DataWeighting {
  std::string name;
  std::string text;
  bool relative_default = false;  // sigma from relative_sigma x range (none was given)
};

struct CalibrationResult {
  std::vector<ParameterResult> parameters;    // all, in config order
  std::vector<DataWeighting> data_weighting;  // one per data set, in config order
  std::vector<std::string> scene_sources;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  int forward_runs = 0;        // scene runs started (points x scenes)
  int failed_evaluations = 0;  // points whose residuals could not be formed
  double wall_time_s = 0.0;
  CalibrationTermination termination = CalibrationTermination::kFailed;
  std::string ceres_termination;           // CONVERGENCE, NO_CONVERGENCE, FAILURE, ...
  std::string message;                     // why it stopped
  bool noise_floor = false;                // stopped at the forward solver's noise floor
  double noise_floor_cost = 0.0;           // the cost resolution F at the end (least_squares.h)
  int passes = 1;                          // Ceres solves (active-set restarts + 1)
  std::vector<BoundEffect> bound_effects;  // free parameters ending on a bound
  std::vector<ModelFormFit> model_form;    // one per [[model_form]]
  std::vector<ModelFormRange> model_form_ranges;  // free order, when model_form is not empty
  int model_form_forward_runs = 0;
  // [[discrepancy]] sources, learned before the fit (discrepancy.h), and their forward runs.
  std::vector<DiscrepancySource> discrepancies;
  int discrepancy_forward_runs = 0;
  bool global_search_used = false;
  GlobalSearchSummary global;  // when used
  std::vector<DataSetFit> fits;
  // Per scene (config order): the scene with the identified values written in, as the fit ran
  // it (with the forward settings), as a scene file (scene_echo.h) with a comment header naming
  // the values; "" where it could not be built, none for a failed fit. Written as
  // identified_<scene>.toml: `vshell run` on it reproduces the fit's run, into the folder
  // run_identified_<scene> beside the report (its output.directory).
  std::vector<std::string> identified_scenes;
  // The forward model's trust caveats (RunResult::warnings) at the identified parameters, e.g.
  // elements shorter than the thickness; "<scene>: " in front with several scenes. A fit is only
  // as good as the runs it matches, so the report repeats them.
  std::vector<std::string> forward_warnings;
  bool uncertainty_available = false;
  UncertaintySummary uncertainty;   // free parameters only, in free order
  std::string uncertainty_message;  // why not available
  std::vector<std::shared_ptr<const Evaluation>> evaluations;  // every forward evaluation
  std::string output_directory;           // where the report went ("" if not written)
  std::vector<std::string> report_notes;  // e.g. plots skipped

  // Free parameters' identified values, in free order.
  Eigen::VectorXd free_values() const;
  // One line per parameter with value, +- std error and the statements.
  std::string brief_report() const;
};

// Validates everything (config, scenes, parameter addresses, bounds, data travels against the
// scenes) before the first forward run; throws InputError. Forward failures during the fit are
// counted, never thrown.
CalibrationResult calibrate(const CalibrationConfig& config, const CalibrationOptions& options,
                            ForwardModel model);

}  // namespace vs
