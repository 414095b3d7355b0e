#include "output/suspect_results.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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
  return warnings;
}

}  // namespace vs
