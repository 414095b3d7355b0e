// The calibration report folder:
//   calibration.json   parameters (bounds, units, start, value, std error, 95% interval,
//                      determined?), correlation and covariance, singular values, condition,
//                      cost in total and per data set, forward runs and failures, wall time,
//                      termination and why, plain-language statements
//   evaluations.csv    every forward evaluation: index, status, cost, wall time, parameters
//   fit_<name>.csv     measured against simulated at the optimum, per data set
//   fit_<name>.svg     the same as a plot; cost.svg: cost against evaluation number
#pragma once

#include <string>
#include <vector>

#include "calibrate.h"
#include "calibration_config.h"

namespace vs {

// Creates `directory` if needed. Returns notes for the user (e.g. plots skipped). Throws
// InputError if the folder cannot be written.
std::vector<std::string> write_calibration_report(const CalibrationResult& result,
                                                  const CalibrationConfig& config,
                                                  const std::string& directory);

// The JSON report as text (also used by tests).
std::string calibration_json(const CalibrationResult& result, const CalibrationConfig& config);

// fit_<name>.csv of one data set as text.
std::string fit_csv(const DataSetFit& fit);

// evaluations.csv as text.
std::string evaluations_csv(const CalibrationResult& result);

}  // namespace vs
