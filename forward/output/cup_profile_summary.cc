#include "output/cup_profile_summary.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>

namespace vs {

namespace {

double wrap_deg(double a) {
  double w = std::fmod(a, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

struct Sorted {
  std::vector<double> a;  // [0, 360), increasing
  std::vector<double> h;
};

// Angle of point i with whole turns added so that the periodic sequence is increasing:
// point i + k n sits at a[i] + 360 k.
double unwrapped_angle(const Sorted& s, std::ptrdiff_t i) {
  const auto n = static_cast<std::ptrdiff_t>(s.a.size());
  const std::ptrdiff_t k = i >= 0 ? i / n : -((-i + n - 1) / n);
  return s.a[static_cast<std::size_t>(i - k * n)] + 360.0 * static_cast<double>(k);
}

double height_at(const Sorted& s, std::ptrdiff_t i) {
  const auto n = static_cast<std::ptrdiff_t>(s.a.size());
  return s.h[static_cast<std::size_t>(((i % n) + n) % n)];
}

// The extremum at the run of equal heights starting at i and ending at j (inclusive indices of
// the periodic sequence): its middle for a run, else the parabola through i - 1, i, i + 1.
ProfileExtremum refine(const Sorted& s, std::ptrdiff_t i, std::ptrdiff_t j) {
  const double hi = height_at(s, i);
  if (j > i) return {wrap_deg(0.5 * (unwrapped_angle(s, i) + unwrapped_angle(s, j))), hi};
  const double a0 = unwrapped_angle(s, i - 1), a1 = unwrapped_angle(s, i),
               a2 = unwrapped_angle(s, i + 1);
  const double h0 = height_at(s, i - 1), h2 = height_at(s, i + 1);
  const double d01 = (hi - h0) / (a1 - a0);
  const double d12 = (h2 - hi) / (a2 - a1);
  const double c = (d12 - d01) / (a2 - a0);
  if (!(c != 0.0) || !std::isfinite(c)) return {wrap_deg(a1), hi};
  const double x = std::clamp(0.5 * (a0 + a1) - d01 / (2.0 * c), a0, a2);
  const double value = h0 + d01 * (x - a0) + c * (x - a0) * (x - a1);
  return {wrap_deg(x), value};
}

// Prominence of the extremum formed by the run [i, j] of equal heights: `sign` +1 for a maximum
// (height above the key col), -1 for a minimum (depth below the key rim), by symmetry.
double prominence(const Sorted& s, std::ptrdiff_t i, std::ptrdiff_t j, double sign) {
  const auto n = static_cast<std::ptrdiff_t>(s.a.size());
  const double hi = sign * height_at(s, i);
  const std::ptrdiff_t first = ((i % n) + n) % n;
  // The lowest point met walking from `from` in steps of `step` until a higher point (at most
  // once round). An equal height counts as higher if it comes first in angle, so that of two
  // equal extrema exactly one is the higher (else twins split by a small bump would both be
  // shallow, or both deep).
  auto lowest_before_higher = [&](std::ptrdiff_t from, std::ptrdiff_t step) {
    double lowest = hi;
    for (std::ptrdiff_t k = from, m = 0; m < n; k += step, ++m) {
      const double h = sign * height_at(s, k);
      if (h > hi || (h == hi && ((k % n) + n) % n < first)) break;
      lowest = std::min(lowest, h);
    }
    return lowest;
  };
  const double right = lowest_before_higher(j + 1, 1);
  const double left = lowest_before_higher(i - 1, -1);
  // With no higher point either way (the highest extremum) both walks went all round: the lowest
  // point of the profile.
  return hi - std::max(left, right);
}

}  // namespace

CupProfileSummary summarize_cup_profile(const std::vector<double>& angle_deg,
                                        const std::vector<double>& height_mm,
                                        const CupProfileSummaryOptions& options) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  CupProfileSummary out;
  const std::size_t n = std::min(angle_deg.size(), height_mm.size());
  out.points = static_cast<int>(n);
  out.mean_height_mm = out.min_height_mm = out.max_height_mm = out.amplitude_mm = kNaN;
  if (n == 0) return out;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    return wrap_deg(angle_deg[p]) < wrap_deg(angle_deg[q]);
  });
  Sorted s;
  for (std::size_t k : order) {
    s.a.push_back(wrap_deg(angle_deg[k]));
    s.h.push_back(height_mm[k]);
  }
  out.min_height_mm = *std::min_element(s.h.begin(), s.h.end());
  out.max_height_mm = *std::max_element(s.h.begin(), s.h.end());
  out.amplitude_mm = out.max_height_mm - out.min_height_mm;
  if (n == 1) {
    out.mean_height_mm = s.h[0];
    return out;
  }
  double integral = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = static_cast<std::ptrdiff_t>(i);
    integral += 0.5 * (height_at(s, p) + height_at(s, p + 1)) *
                (unwrapped_angle(s, p + 1) - unwrapped_angle(s, p));
  }
  out.mean_height_mm = integral / 360.0;
  if (out.amplitude_mm == 0.0) return out;  // flat: no extrema
  // Each run of equal heights once, from its first point (one whose predecessor differs).
  const auto count = static_cast<std::ptrdiff_t>(n);
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const double hi = height_at(s, i);
    const double before = height_at(s, i - 1);
    if (before == hi) continue;
    std::ptrdiff_t j = i;
    while (height_at(s, j + 1) == hi) ++j;
    const double after = height_at(s, j + 1);
    const double enough = options.min_prominence_mm;
    if (hi > before && hi > after && prominence(s, i, j, 1.0) >= enough) {
      out.ears.push_back(refine(s, i, j));
    }
    if (hi < before && hi < after && prominence(s, i, j, -1.0) >= enough) {
      out.valleys.push_back(refine(s, i, j));
    }
  }
  const auto by_angle = [](const ProfileExtremum& p, const ProfileExtremum& q) {
    return p.angle_deg < q.angle_deg;
  };
  std::stable_sort(out.ears.begin(), out.ears.end(), by_angle);
  std::stable_sort(out.valleys.begin(), out.valleys.end(), by_angle);
  return out;
}

double angle_distance_deg(double a_deg, double b_deg) {
  const double d = wrap_deg(a_deg - b_deg);
  return std::min(d, 360.0 - d);
}

double max_extremum_offset_deg(const std::vector<ProfileExtremum>& found,
                               const std::vector<ProfileExtremum>& reference) {
  if (found.empty() || reference.empty()) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0.0;
  for (const ProfileExtremum& r : reference) {
    double nearest = 180.0;
    for (const ProfileExtremum& f : found) {
      nearest = std::min(nearest, angle_distance_deg(f.angle_deg, r.angle_deg));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

}  // namespace vs
