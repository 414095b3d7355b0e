#include "cup_height_curve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "output/cup_profile.h"
#include "output/cup_profile_output.h"

namespace vs {

double periodic_interpolate_deg(const std::vector<double>& angle_deg,
                                const std::vector<double>& value, double at_deg) {
  const std::size_t n = std::min(angle_deg.size(), value.size());
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  double at = std::fmod(at_deg, 360.0);
  if (at < 0.0) at += 360.0;
  if (at >= 360.0) at = 0.0;
  const double first = angle_deg.front(), last = angle_deg[n - 1];
  if (at < first || at >= last) {
    // Across 0/360: from (last, value[n-1]) to (first + 360, value[0]).
    const double a = at < first ? at + 360.0 : at;
    const double t = (a - last) / (first + 360.0 - last);
    return value[n - 1] + t * (value[0] - value[n - 1]);
  }
  const auto upper = std::upper_bound(angle_deg.begin(), angle_deg.begin() + n, at);
  const auto i = static_cast<std::size_t>(upper - angle_deg.begin());
  const double t = (at - angle_deg[i - 1]) / (angle_deg[i] - angle_deg[i - 1]);
  return value[i - 1] + t * (value[i] - value[i - 1]);
}

SimulatedCurve cup_height_curve(const Measurement& m, const Scene& scene, const RunResult& run) {
  SimulatedCurve curve;
  if (run.geometry != Geometry::kShell3d || !run.shell) {
    curve.message = fmt::format(
        "{}: cup_height_profile data need a 3D cup run (geometry = \"shell3d\")", m.name);
    return curve;
  }
  if (!run.completed()) {
    curve.message = fmt::format("{}: the run did not complete, so it has no final cup profile ({})",
                                m.name, run.message);
    return curve;
  }
  if (run.shell->stages.empty()) {
    curve.message = fmt::format("{}: the run has no 3D stage", m.name);
    return curve;
  }
  const CupProfileResult p = rim_cup_profile(scene, *run.shell, run.shell->stages.back(),
                                             profile_rolling_direction_deg(scene));
  if (!p.available) {
    curve.message = fmt::format("{}: the run has no rim profile: {}", m.name, p.reason);
    return curve;
  }
  const auto& angles = p.profile.angle_from_rd_deg;
  if (angles.size() < 2) {
    curve.message = fmt::format("{}: the rim profile has {} point(s); 2 or more are needed", m.name,
                                angles.size());
    return curve;
  }
  for (std::size_t i = 1; i < angles.size(); ++i) {
    if (!(angles[i] > angles[i - 1])) {
      curve.message = fmt::format("{}: two rim nodes at {} deg from RD", m.name, angles[i]);
      return curve;
    }
  }
  for (double x : m.x) curve.y.push_back(periodic_interpolate_deg(angles, p.profile.height_mm, x));
  curve.ok = true;
  return curve;
}

double shape_offset(const std::vector<double>& simulated, const std::vector<double>& measured,
                    const std::vector<double>& weights) {
  if (simulated.size() != measured.size() || simulated.size() != weights.size()) return 0.0;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < simulated.size(); ++i) {
    const double w2 = weights[i] * weights[i];
    num += w2 * (measured[i] - simulated[i]);
    den += w2;
  }
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace vs
