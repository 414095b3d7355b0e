// Twin calibration of experiments/07_calibration_cost, shared with its quick CTest variant
// (tests/system/experiments_quick_test.cc): "measured" data from a fine forward model of example 1
// with known parameters, then the parameters identified with a coarser forward model inside the
// fit; the relative error of the identified values is the bias the coarse model's discretisation
// error puts into a calibration. Header-only.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "calibrate.h"
#include "default_forward_model.h"
#include "harness.h"
#include "synthetic.h"

namespace vsx {

// One parameter of the twin: its true value, bounds and scale for the optimiser.
struct TrueParameter {
  std::string address;
  double value;
  double lower, upper, scale;
};

// The four parameters of issue 4 (example 1 with R = 1.5).
inline std::vector<TrueParameter> calibration_truth() {
  return {{"tool.punch.friction", 0.1, 0.0, 0.5, 0.1},
          {"material.hardening.K_MPa", 589.0, 100.0, 2000.0, 500.0},
          {"material.hardening.n", 0.216, 0.05, 0.6, 0.2},
          {"material.r_value", 1.5, 0.3, 5.0, 1.0}};
}

// What is measured and how: the travel, the load at every whole millimetre, the thickness strain
// at r0 = 0, 2.5, .. 55 mm at `strain_travels_mm`; every parameter starts at `start` x truth;
// `free` picks the identified parameters (the others are fixed at the truth).
struct TwinSetup {
  std::string scene_path;
  double travel_mm = 20.0;
  std::vector<double> strain_travels_mm = {10.0, 20.0};
  std::vector<TrueParameter> truth = calibration_truth();
  std::vector<bool> free = {true, true, true, true};
  double start = 0.8;
  int threads = 2;
};

// Scene edits of every run of the twin (data and fits): travel, outputs, solver tolerance.
inline Overrides twin_common_edits(const TwinSetup& s) {
  std::string outputs = "[";
  for (std::size_t i = 0; i < s.strain_travels_mm.size(); ++i)
    outputs += fmt::format("{}{:.1f}", i ? ", " : "", s.strain_travels_mm[i]);
  outputs += "]";
  return {{"process.punch_travel_mm", fmt::format("{}", s.travel_mm)},
          {"process.output_travels_mm", outputs},
          {"numerics.tolerance", "1e-8"}};
}

struct TwinData {
  Overrides fine;  // every edit of the data run
  std::vector<vs::Measurement> data;
  double wall_s = 0.0;
  bool ok = false;
  std::string message;
};

// Noise-free data from the model `fine_discretisation` at the true parameters.
inline TwinData twin_data(const TwinSetup& s, const Overrides& fine_discretisation) {
  TwinData d;
  d.fine = twin_common_edits(s);
  for (const Override& o : fine_discretisation) d.fine.push_back(o);
  for (const TrueParameter& t : s.truth) d.fine.push_back({t.address, fmt::format("{}", t.value)});
  const vs::Scene scene = make_scene(s.scene_path, d.fine);
  const TimedRun run = run_once(scene, 3600.0);
  d.wall_s = run.wall_s;
  d.ok = run.result.completed();
  d.message = run.result.message;
  if (!d.ok) return d;
  std::vector<double> travels, radii;
  for (int i = 1; i <= static_cast<int>(std::floor(s.travel_mm + 1e-9)); ++i) travels.push_back(i);
  for (int i = 0; i <= 22; ++i) radii.push_back(2.5 * i);
  std::vector<vs::SyntheticDataSpec> specs = {
      {vs::MeasurementKind::kLoadTravel, "load", 0.0, travels, 0.0, 0.0}};
  for (double t : s.strain_travels_mm)
    specs.push_back({vs::MeasurementKind::kThicknessStrain, fmt::format("thick_{:g}mm", t), t,
                     radii, 0.0, 0.0});
  d.data = vs::make_synthetic_measurements(scene, run.result, specs, 1);
  return d;
}

struct TwinFit {
  std::vector<double> error;  // identified / true - 1 per parameter (0 for fixed ones)
  double max_error = 0.0;     // largest |error| over the free parameters
  int forward_runs = 0;
  double wall_s = 0.0;
  bool converged = false;
  std::string message;
};

// Identifies the free parameters from `data` with the forward model `discretisation` (on top of
// the common edits): central differences with relative step 0.05, sigma 200 N for the load and
// 0.002 for the thickness strains (about 1 % of each curve).
inline TwinFit twin_fit(const TwinSetup& s, const TwinData& data, const Overrides& discretisation) {
  vs::CalibrationConfig c;
  c.scenes = {{"scene", s.scene_path, "experiment"}};
  c.forward.tolerance = 1e-8;
  for (const Override& o : twin_common_edits(s))
    c.forward.overrides.push_back({o.address, o.value});
  for (const Override& o : discretisation) c.forward.overrides.push_back({o.address, o.value});
  for (std::size_t i = 0; i < s.truth.size(); ++i) {
    const TrueParameter& t = s.truth[i];
    const bool is_free = i < s.free.size() && s.free[i];
    vs::ParameterSpec p;
    p.address = t.address;
    p.initial = is_free ? s.start * t.value : t.value;
    p.lower = t.lower;
    p.upper = t.upper;
    p.scale = t.scale;
    p.fixed = !is_free;
    p.where = "experiment";
    c.parameters.push_back(p);
  }
  for (const vs::Measurement& m : data.data) {
    vs::DataSpec d;
    d.measurement = m;
    d.sigma = m.kind == vs::MeasurementKind::kLoadTravel ? 200.0 : 0.002;
    d.where = "experiment";
    c.data.push_back(d);
  }
  c.optimizer.threads = s.threads;
  c.optimizer.fd.relative_step = 0.05;
  vs::CalibrationOptions options;
  options.write_report = false;
  const vs::CalibrationResult r = vs::calibrate(c, options, vs::make_default_forward_model());
  TwinFit f;
  for (std::size_t i = 0; i < s.truth.size(); ++i) {
    f.error.push_back(r.parameters[i].value / s.truth[i].value - 1.0);
    if (!r.parameters[i].spec.fixed) f.max_error = std::max(f.max_error, std::abs(f.error.back()));
  }
  f.forward_runs = r.forward_runs;
  f.wall_s = r.wall_time_s;
  f.converged = r.termination == vs::CalibrationTermination::kConverged;
  f.message = r.message;
  return f;
}

}  // namespace vsx
