// Scalar and curve measures of a forward run used by the experiments: peak load, pole thickness
// strain, thinnest-point position, load-curve and strain-profile differences, and Richardson
// extrapolation. Header-only (shared with the quick CTest variant).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "run/run_result.h"

namespace vsx {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of (x, y) at xq, x increasing; constant beyond the ends.
inline double interp(const std::vector<double>& x, const std::vector<double>& y, double xq) {
  if (x.empty()) return kNaN;
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t j = static_cast<std::size_t>(it - x.begin());
  const double t = (xq - x[j - 1]) / (x[j] - x[j - 1]);
  return y[j - 1] + t * (y[j] - y[j - 1]);
}

struct Peak {
  double force_N = kNaN;
  double travel_mm = kNaN;
};

inline Peak peak_load(const vs::RunResult& r) {
  Peak p;
  for (const vs::StepRecord& s : r.steps) {
    if (!(s.punch_force_N <= p.force_N)) {
      p.force_N = s.punch_force_N;
      p.travel_mm = s.punch_travel_mm;
    }
  }
  return p;
}

inline double final_travel(const vs::RunResult& r) {
  return r.steps.empty() ? 0.0 : r.steps.back().punch_travel_mm;
}

// The load-travel curve with repeated travels (zero-length steps) collapsed to their last value.
inline void load_curve(const vs::RunResult& r, std::vector<double>* t, std::vector<double>* f) {
  t->clear();
  f->clear();
  for (const vs::StepRecord& s : r.steps) {
    if (!t->empty() && s.punch_travel_mm <= t->back()) {
      f->back() = s.punch_force_N;
      continue;
    }
    t->push_back(s.punch_travel_mm);
    f->push_back(s.punch_force_N);
  }
}

// Relative L2 difference of two load curves on `n` equally spaced travels in [0, up_to_mm].
inline double load_curve_rel_l2(const vs::RunResult& run, const vs::RunResult& ref, double up_to_mm,
                                int n = 201) {
  std::vector<double> ta, fa, tb, fb;
  load_curve(run, &ta, &fa);
  load_curve(ref, &tb, &fb);
  if (ta.empty() || tb.empty()) return kNaN;
  double num = 0.0, den = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = up_to_mm * i / (n - 1);
    const double d = interp(ta, fa, t) - interp(tb, fb, t);
    const double b = interp(tb, fb, t);
    num += d * d;
    den += b * b;
  }
  return den > 0.0 ? std::sqrt(num / den) : kNaN;
}

// The output profile written at `travel_mm` (nullptr if the run did not reach it).
inline const vs::Profile* profile_at(const vs::RunResult& r, double travel_mm) {
  for (const vs::Profile& p : r.profiles) {
    if (std::abs(p.punch_travel_mm - travel_mm) <= 1e-6 * std::max(1.0, travel_mm)) return &p;
  }
  return nullptr;
}

// Max abs difference of the thickness strain, both profiles interpolated on r0 at the reference's
// element midpoints.
inline double thickness_strain_max_abs(const vs::Profile& run, const vs::Profile& ref) {
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.r0_mm.size(); ++i) {
    const double a = interp(run.r0_mm, run.eps_thickness, ref.r0_mm[i]);
    worst = std::max(worst, std::abs(a - ref.eps_thickness[i]));
  }
  return worst;
}

inline double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Thickness strain at the pole: eps_t is even in r, so eps = a + b r^2 through the first two
// element midpoints gives the pole value a independently of the mesh.
inline double pole_thickness_strain(const vs::Profile& p) {
  if (p.r0_mm.size() < 2) return kNaN;
  const double r1 = p.r0_mm[0] * p.r0_mm[0], r2 = p.r0_mm[1] * p.r0_mm[1];
  return (p.eps_thickness[0] * r2 - p.eps_thickness[1] * r1) / (r2 - r1);
}

// Initial radius of the thinnest point: the minimum of eps_t over the element midpoints, refined
// by the parabola through it and its neighbours (the pole is its own mirror image).
inline double thinnest_r0(const vs::Profile& p) {
  const std::vector<double>& e = p.eps_thickness;
  if (e.size() < 3) return kNaN;
  const std::size_t k = static_cast<std::size_t>(std::min_element(e.begin(), e.end()) - e.begin());
  if (k == 0) {
    // Mirror: eps(-r0) = eps(r0); the vertex of the even parabola a + b r^2 is the pole itself
    // unless the second point is lower, which min_element excludes.
    return 0.0;
  }
  if (k + 1 >= e.size()) return p.r0_mm[k];
  const double x0 = p.r0_mm[k - 1], x1 = p.r0_mm[k], x2 = p.r0_mm[k + 1];
  const double y0 = e[k - 1], y1 = e[k], y2 = e[k + 1];
  const double d1 = (y1 - y0) / (x1 - x0), d2 = (y2 - y1) / (x2 - x1);
  const double a = (d2 - d1) / (x2 - x0);
  if (!(a > 0.0)) return x1;
  const double xv = 0.5 * (x0 + x1) - d1 / (2.0 * a);
  return std::clamp(xv, x0, x2);
}

// Richardson extrapolation from three values at refinement ratio 2 (q2 finest).
struct Richardson {
  double order = kNaN;      // observed order p = log2(|q1 - q0| / |q2 - q1|)
  double value = kNaN;      // extrapolated value (= q2 when the order is not trustworthy)
  double error_est = kNaN;  // estimated |error| of q2
  bool asymptotic = false;  // monotone and 0.5 <= p <= 4: extrapolation used
};

inline Richardson richardson(double q0, double q1, double q2) {
  Richardson r;
  const double d1 = q1 - q0, d2 = q2 - q1;
  r.value = q2;
  r.error_est = std::abs(d2);
  if (d2 == 0.0) {
    r.order = std::numeric_limits<double>::infinity();
    r.error_est = 0.0;
    return r;
  }
  r.order = std::log2(std::abs(d1 / d2));
  if (d1 * d2 > 0.0 && r.order >= 0.5 && r.order <= 4.0) {
    r.asymptotic = true;
    r.error_est = std::abs(d2) / (std::pow(2.0, r.order) - 1.0);
    r.value = q2 + d2 / (std::pow(2.0, r.order) - 1.0);
  }
  return r;
}

// Relative error |a - b| / |b|.
inline double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace vsx
