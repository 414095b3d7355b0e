#include "stepping/travel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vs {

std::vector<double> travel_grid(double total_mm, double increment_mm,
                                const std::vector<double>& outputs_mm, int start_levels) {
  std::vector<double> targets = outputs_mm;
  for (double tr = increment_mm; tr < total_mm * (1.0 - 1e-12); tr += increment_mm) {
    targets.push_back(tr);
  }
  for (int k = 0; k < start_levels; ++k) {
    const int parts = 1 << (start_levels - k);
    for (int j = 1; j < parts; ++j) {
      const double tr = increment_mm * (k + static_cast<double>(j) / parts);
      if (tr < total_mm * (1.0 - 1e-12)) targets.push_back(tr);
    }
  }
  targets.push_back(total_mm);
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end(),
                            [&](double a, double b) { return std::abs(a - b) <= 1e-9 * total_mm; }),
                targets.end());
  return targets;
}

double step_to_next_target(const std::vector<double>& targets, double travel_mm,
                           double speed_mm_per_s, double max_strain_increment, double max_rate) {
  double dt_target = std::numeric_limits<double>::infinity();
  for (double tr : targets) {
    if (tr > travel_mm * (1.0 + 1e-12) + 1e-12) {
      dt_target = (tr - travel_mm) / speed_mm_per_s;
      break;
    }
  }
  // Strain cap: equal sub-steps to the next grid point.
  if (max_rate <= 0.0) return dt_target;
  const double strain_dt = max_strain_increment / max_rate;
  return dt_target / std::ceil(dt_target / strain_dt * (1.0 - 1e-12));
}

}  // namespace vs
