// Measured data + forward runs -> residual vector. Per data set: map the simulation onto the
// measured abscissae (linear interpolation on the fixed measured grid, so the residual is a
// smooth function of the parameters even though the solver's own steps move with contact
// events), difference, weight. Residual_i = w_i (simulated_i - measured_i) with w_i = 1/sigma_i
// (per point or per data set) or a plain weight.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "measurement.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct DataSet {
  Measurement measurement;
  int scene = 0;                // index of the scene whose runs this data set is compared with
  std::vector<double> weights;  // one per point: 1/sigma or the configured weight
  // cup_height_profile: the scene the rim is read with (blank outline, rolling direction; the
  // scene as configured: parameters may not move those keys, calibrate() checks).
  std::shared_ptr<const Scene> scene_spec;
  // cup_height_profile: compare the shape only, up to the best constant offset
  // (cup_height_curve.h).
  bool shape_only = false;
  // Model-discrepancy correction (discrepancy.h), one per point, added to the simulated values
  // before anything else; empty: none.
  std::vector<double> correction;
};

// Linear interpolation in a strictly increasing table; constant beyond the ends.
double interpolate_table(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// Simulated values at a data set's abscissae, or why there are none.
struct SimulatedCurve {
  bool ok = false;
  std::string message;    // why not, e.g. "run stopped at 12.5 mm before 20 mm"
  std::vector<double> y;  // at measurement.x, internal units
};

// Load curve: the run's (travel, force) steps, starting from (0, 0), interpolated linearly at
// each measured travel; the run must reach the largest measured travel.
// Profiles: the profile recorded at measurement.travel_mm, interpolated linearly in r0_mm; outside
// the range of element midpoints the end value is used (at most half an element away).
// Cup height profiles: the final rim profile at the measured angles (cup_height_curve.h); they
// need `scene` (else ok = false).
SimulatedCurve simulate_curve(const Measurement& measurement, const RunResult& run,
                              const Scene* scene = nullptr);

// A data set's simulated values as compared: simulate_curve, plus the data set's discrepancy
// correction, shifted by the shape-only offset when the data set asks for it (the values the
// residuals and fit_<name>.csv use).
SimulatedCurve data_set_curve(const DataSet& data_set, const RunResult& run);

struct Residuals {
  bool ok = false;
  std::string message;
  Eigen::VectorXd values;  // all data sets, concatenated in order
};

class ResidualPipeline {
 public:
  explicit ResidualPipeline(std::vector<DataSet> data_sets);

  int num_residuals() const { return num_residuals_; }
  const std::vector<DataSet>& data_sets() const { return data_sets_; }
  // First residual of data set k; data set k owns [offset(k), offset(k) + its point count).
  int offset(int k) const { return offsets_.at(k); }

  // `runs[s]` is the run of scene s. Fails (ok = false) if any data set cannot be mapped.
  Residuals residuals(const std::vector<RunResult>& runs) const;

 private:
  std::vector<DataSet> data_sets_;
  std::vector<int> offsets_;
  int num_residuals_ = 0;
};

}  // namespace vs
