#include "output/plot_ticks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace vs {

double nice_tick_step(double lo, double hi, int target_count) {
  const double raw = (hi - lo) / std::max(target_count, 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / decade;
  // Thresholds are the geometric means of neighbouring steps, so the choice is "closest" on a
  // log scale: 1 up to sqrt(2), 2 up to sqrt(10), 5 up to sqrt(50), then 10.
  double nice = 10.0;
  if (fraction < 1.4142135623730951) {
    nice = 1.0;
  } else if (fraction < 3.1622776601683795) {
    nice = 2.0;
  } else if (fraction < 7.0710678118654755) {
    nice = 5.0;
  }
  return nice * decade;
}

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) return ticks;
  const double step = nice_tick_step(lo, hi, target_count);
  const double tolerance = 1e-9 * step;
  const double first = std::ceil((lo - tolerance) / step);
  const double last = std::floor((hi + tolerance) / step);
  // Ticks are index * step (not repeated addition) so no round-off accumulates.
  for (double index = first; index <= last; index += 1.0) {
    const double value = index * step;
    ticks.push_back(std::abs(value) < tolerance ? 0.0 : value);
  }
  return ticks;
}

TickRange nice_range(double lo, double hi, int target_count) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    // A single value (or a flat line): centre it in a small window.
    const double half = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= half;
    hi += half;
  }
  const double step = nice_tick_step(lo, hi, target_count);
  const double tolerance = 1e-9 * step;
  return {std::floor((lo + tolerance) / step) * step, std::ceil((hi - tolerance) / step) * step};
}

std::string format_tick(double value, double step) {
  if (std::abs(value) < 1e-9 * step) value = 0.0;  // no "-0"
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude >= 1e6 || step < 1e-4) return fmt::format("{:g}", value);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace vs
