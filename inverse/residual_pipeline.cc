#include "residual_pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cup_height_curve.h"

namespace vs {

double interpolate_table(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto upper = std::upper_bound(xs.begin(), xs.end(), x);
  const auto i = static_cast<std::size_t>(upper - xs.begin());
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}

namespace {

bool same_travel(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, b); }

SimulatedCurve load_curve(const Measurement& m, const RunResult& run) {
  SimulatedCurve curve;
  std::vector<double> travel{0.0};
  std::vector<double> force{0.0};
  for (const auto& step : run.steps) {
    // Keep the table strictly increasing even if a step repeats a travel.
    if (step.punch_travel_mm <= travel.back()) continue;
    travel.push_back(step.punch_travel_mm);
    force.push_back(step.punch_force_N);
  }
  const double needed = m.x.back();
  if (travel.back() < needed - 1e-9 * std::max(1.0, needed)) {
    curve.message =
        fmt::format("{}: run stopped at {} mm, before the largest measured travel {} mm", m.name,
                    travel.back(), needed);
    return curve;
  }
  for (double x : m.x) curve.y.push_back(interpolate_table(travel, force, x));
  curve.ok = true;
  return curve;
}

SimulatedCurve profile_curve(const Measurement& m, const RunResult& run) {
  SimulatedCurve curve;
  const Profile* profile = nullptr;
  for (const auto& p : run.profiles) {
    if (same_travel(p.punch_travel_mm, m.travel_mm)) {
      profile = &p;
      break;
    }
  }
  if (profile == nullptr || profile->r0_mm.empty()) {
    curve.message = fmt::format("{}: the run has no profile at {} mm travel", m.name, m.travel_mm);
    return curve;
  }
  const auto& eps = m.kind == MeasurementKind::kThicknessStrain ? profile->eps_thickness
                                                                : profile->eps_circumferential;
  if (eps.size() != profile->r0_mm.size()) {
    curve.message =
        fmt::format("{}: profile at {} mm has inconsistent columns", m.name, m.travel_mm);
    return curve;
  }
  for (double x : m.x) curve.y.push_back(interpolate_table(profile->r0_mm, eps, x));
  curve.ok = true;
  return curve;
}

}  // namespace

SimulatedCurve simulate_curve(const Measurement& measurement, const RunResult& run,
                              const Scene* scene) {
  SimulatedCurve curve;
  if (measurement.kind == MeasurementKind::kLoadTravel) {
    curve = load_curve(measurement, run);
  } else if (measurement.kind == MeasurementKind::kCupHeightProfile) {
    if (scene == nullptr) {
      curve.message = fmt::format("{}: cup_height_profile data need the scene", measurement.name);
      return curve;
    }
    curve = cup_height_curve(measurement, *scene, run);
  } else {
    curve = profile_curve(measurement, run);
  }
  for (double y : curve.y) {
    if (!std::isfinite(y)) {
      curve.ok = false;
      curve.message = fmt::format("{}: simulated value is not finite", measurement.name);
      break;
    }
  }
  return curve;
}

SimulatedCurve data_set_curve(const DataSet& d, const RunResult& run) {
  SimulatedCurve curve = simulate_curve(d.measurement, run, d.scene_spec.get());
  if (curve.ok && !d.correction.empty()) {
    for (std::size_t i = 0; i < curve.y.size(); ++i) curve.y[i] += d.correction[i];
  }
  if (curve.ok && d.shape_only) {
    const double c = shape_offset(curve.y, d.measurement.y, d.weights);
    for (double& y : curve.y) y += c;
  }
  return curve;
}

ResidualPipeline::ResidualPipeline(std::vector<DataSet> data_sets)
    : data_sets_(std::move(data_sets)) {
  for (const auto& d : data_sets_) {
    offsets_.push_back(num_residuals_);
    num_residuals_ += static_cast<int>(d.measurement.x.size());
  }
}

Residuals ResidualPipeline::residuals(const std::vector<RunResult>& runs) const {
  Residuals result;
  result.values.resize(num_residuals_);
  for (std::size_t k = 0; k < data_sets_.size(); ++k) {
    const DataSet& d = data_sets_[k];
    const SimulatedCurve curve = data_set_curve(d, runs.at(d.scene));
    if (!curve.ok) {
      result.message = curve.message;
      return result;
    }
    for (std::size_t i = 0; i < curve.y.size(); ++i) {
      result.values[offsets_[k] + static_cast<int>(i)] =
          d.weights[i] * (curve.y[i] - d.measurement.y[i]);
    }
  }
  result.ok = true;
  return result;
}

}  // namespace vs
