#include "output/suspect_results.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vs {

LoadCurveNoise load_curve_noise(const std::vector<StepRecord>& steps) {
  LoadCurveNoise noise;
  double peak = 0.0;
  for (const StepRecord& r : steps) {
    if (std::isfinite(r.punch_force_N)) peak = std::max(peak, std::abs(r.punch_force_N));
  }
  if (steps.size() < 3 || !(peak > 0.0)) return noise;
  const double flat = 1e-6 * peak;
  int last_sign = 0;
  double sum_squares = 0.0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const double d = steps[k].punch_force_N - steps[k - 1].punch_force_N;
    if (k + 1 < steps.size()) {
      const double d2 =
          steps[k + 1].punch_force_N - 2.0 * steps[k].punch_force_N + steps[k - 1].punch_force_N;
      sum_squares += d2 * d2;
    }
    if (!std::isfinite(d) || std::abs(d) <= flat) continue;
    const int sign = d > 0.0 ? 1 : -1;
    ++noise.increments;
    if (last_sign != 0 && sign != last_sign) ++noise.reversals;
    last_sign = sign;
  }
  noise.rms_second_difference =
      std::sqrt(sum_squares / static_cast<double>(steps.size() - 2)) / peak;
  noise.noise_like = noise.reversals >= LoadCurveNoise::kMinReversals &&
                     noise.reversals >= LoadCurveNoise::kReversalFraction * noise.increments;
  return noise;
}

double free_wall_equilibrium_error(const Profile& p, double punch_force_N) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<int>& c = p.contact;
  const std::size_t n = c.size();
  if (p.vertical_force_N.size() != n || !(std::abs(punch_force_N) > 0.0)) return nan;
  std::vector<double> inside(n, punch_force_N);
  if (p.punch_force_node_N.size() == n + 1) {
    double sum = 0.0;
    for (std::size_t e = 0; e < n; ++e) inside[e] = (sum += p.punch_force_node_N[e]);
  }
  double best_mean = -1.0, worst = nan;
  for (std::size_t i = 0; i < n;) {
    if (c[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && !c[j]) ++j;  // free stretch [i, j)
    const bool at_rim = j == n;
    if (j >= i + 3) {
      const std::size_t a = i == 0 ? 0 : i + 1, b = at_rim ? j : j - 1;
      double mean = 0.0, dev = 0.0;
      for (std::size_t e = a; e < b; ++e) {
        mean += std::abs(p.vertical_force_N[e]) / static_cast<double>(b - a);
        dev = std::max(dev, std::abs(p.vertical_force_N[e] - inside[e]) / std::abs(punch_force_N));
      }
      if (b > a && mean > best_mean) {
        best_mean = mean;
        worst = dev;
      }
    }
    i = j;
  }
  return worst;
}

FreeWallEquilibrium free_wall_equilibrium(const RunResult& result) {
  FreeWallEquilibrium worst;
  for (const Profile& p : result.profiles) {
    for (const StepRecord& s : result.steps) {
      if (std::abs(s.punch_travel_mm - p.punch_travel_mm) > 1e-9 * (1.0 + p.punch_travel_mm)) {
        continue;
      }
      const double e = free_wall_equilibrium_error(p, s.punch_force_N);
      if (e > worst.error || (std::isnan(worst.error) && !std::isnan(e))) {
        worst.error = e;
        worst.travel_mm = p.punch_travel_mm;
      }
      break;
    }
  }
  return worst;
}

std::vector<std::string> suspect_result_warnings(const RunResult& result) {
  std::vector<std::string> warnings;
  const LoadCurveNoise noise = load_curve_noise(result.steps);
  if (noise.noise_like) {
    warnings.push_back(fmt::format(
        "the load-travel curve is noise-like: its slope reverses {} times in {} steps (rms "
        "second difference {:.2g} of the peak force); forces and strains of this run are not "
        "trustworthy (check the thickness against the tool radii and the mesh)",
        noise.reversals, noise.increments, noise.rms_second_difference));
  }
  const FreeWallEquilibrium eq = free_wall_equilibrium(result);
  if (eq.error > kFreeWallEquilibriumWarning) {
    warnings.push_back(fmt::format(
        "at punch travel {:.4g} mm the stress resultants carry a vertical force through the free "
        "wall that differs from the punch force by {:.2g} % (a converged step balances to the "
        "solver tolerance): the shape written there is off equilibrium, as in the implicit "
        "update's weakly damped stiff mode of a very thin sheet; numerics.implicit_theta = 1, "
        "numerics.implicit_solves = 3 or a smaller numerics.max_travel_increment_per_length "
        "remove it",
        eq.travel_mm, 100.0 * eq.error));
  }
  return warnings;
}

}  // namespace vs
