// Measures of experiments/06_step_stability, shared with its quick CTest variant
// (tests/system/experiments_quick_test.cc): how far outputs of a parameter sweep are from a
// straight line, and how rough one load-travel curve is.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "run/run_result.h"

namespace vsx {

// Largest deviation of y from its least-squares line in x.
inline double linear_fit_max_deviation(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double a = (sy - b * sx) / n;
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(y[i] - a - b * x[i]));
  return worst;
}

// Punch force at `travel`, linear between the neighbouring steps (the step grid need not contain
// the travel); NaN beyond the last step.
inline double force_at(const vs::RunResult& r, double travel) {
  for (std::size_t i = 1; i < r.steps.size(); ++i) {
    const vs::StepRecord& a = r.steps[i - 1];
    const vs::StepRecord& b = r.steps[i];
    if (b.punch_travel_mm >= travel - 1e-12 && b.punch_travel_mm > a.punch_travel_mm) {
      const double w = (travel - a.punch_travel_mm) / (b.punch_travel_mm - a.punch_travel_mm);
      return (1.0 - w) * a.punch_force_N + w * b.punch_force_N;
    }
  }
  return std::nan("");
}

// rms second difference of the force sampled every 0.25 mm over [from, to] mm, over the mean
// increment (a smooth curve gives ~0.01-0.04).
inline double load_roughness(const vs::RunResult& r, double from = 5.0, double to = 20.0) {
  std::vector<double> f;
  for (double t = from; t <= to + 1e-9; t += 0.25) f.push_back(force_at(r, t));
  double s2 = 0.0, inc = 0.0;
  int n = 0;
  for (std::size_t i = 1; i + 1 < f.size(); ++i) {
    const double d2 = f[i + 1] - 2.0 * f[i] + f[i - 1];
    s2 += d2 * d2;
    inc += f[i + 1] - f[i];
    ++n;
  }
  return std::sqrt(s2 / n) / (inc / n);
}

}  // namespace vsx
