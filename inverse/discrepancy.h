// Model-discrepancy correction ([[discrepancy]], calibration_config.h): what a higher-fidelity
// reference model gives minus what the forward model gives, both at the reference's parameters,
// at every point of each data set the reference covers. The fit then compares the data with
// forward + correction.
//
// Why: a forward model with a model-form error (the shell against a continuum, experiments/08)
// is fitted by moving the parameters the error resembles (friction, for a pole that thins too
// little), and the statistical interval does not show it. A reference that resolves what the
// forward model leaves out, run once or twice at nominal parameters, measures that error where
// the data are; the correction removes it to the extent that it does not change with the
// parameters. Each source alone is a model-form alternative, so the report shows how far that
// assumption moves the fit.
#pragma once

#include <string>
#include <vector>

#include "calibration_config.h"
#include "residual_pipeline.h"
#include "run/run_result.h"

namespace vs {

// One data set's correction from one source.
struct DiscrepancyCurve {
  std::string data;                // data set name
  std::string file;                // the reference's file
  std::string unit;                // of the data's ordinate (N, 1, mm)
  std::vector<double> correction;  // reference - forward at the data set's abscissae
  double rms = 0.0;                // of the correction, in the data's unit
  double max_abs = 0.0;
};

// A source's corrections, learned from the forward runs at its parameters.
struct DiscrepancySource {
  std::string name;
  std::string edits;  // its `set`, "address=value ..."
  bool ok = false;
  std::string message;                   // why not (ok = false)
  std::vector<DiscrepancyCurve> curves;  // the data sets it covers, in the pipeline's order
};

// The reference curves of `spec` against `runs` (runs[s]: scene s at the source's parameters),
// at each covered data set's abscissae (the reference interpolated linearly; its range covers
// the data's, validate_calibration_config checks). The forward curve is simulate_curve's.
DiscrepancySource learn_discrepancy(const DiscrepancySpec& spec,
                                    const std::vector<DataSet>& data_sets,
                                    const std::vector<RunResult>& runs);

// Per data set (the order of data_sets): the mean correction over the sources that cover it;
// empty where none does. Every source must be ok.
std::vector<std::vector<double>> mean_corrections(const std::vector<DiscrepancySource>& sources,
                                                  const std::vector<DataSet>& data_sets);

}  // namespace vs
