#include "output/forming_limit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "material/hardening.h"

namespace vs {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRightSlope = 0.6;         // engineering major / minor strain, minor > 0
constexpr double kFittedThicknessMm = 3.0;  // thickest sheet of the Keeler-Brazier fit

}  // namespace

const char* forming_zone_name(FormingZone zone) {
  switch (zone) {
    case FormingZone::kSafe:
      return "safe";
    case FormingZone::kMarginal:
      return "marginal";
    case FormingZone::kFailed:
      return "failed";
    case FormingZone::kUnknown:
      return "none";
  }
  return "none";
}

double keeler_brazier_flc0_percent(double n, double thickness_mm) {
  return (23.3 + 14.13 * thickness_mm) * n / 0.21;
}

double hardening_exponent(const HardeningSpec& hardening) {
  if (hardening.law == HardeningLaw::kSwift || hardening.law == HardeningLaw::kHollomon) {
    return hardening.n;
  }
  const Hardening curve(hardening);
  return std::log(curve.flow_stress(0.2) / curve.flow_stress(0.1)) / std::log(2.0);
}

FormingLimitCurve forming_limit_curve(const Scene& scene) {
  const FormingLimitSpec& spec = scene.forming_limit;
  FormingLimitCurve flc;
  flc.model = spec.model;
  flc.safety_margin = spec.safety_margin;
  if (spec.model == FormingLimitModel::kKeelerBrazier) {
    const HardeningSpec& h = scene.material.hardening;
    flc.n = hardening_exponent(h);
    flc.n_source = h.law == HardeningLaw::kSwift || h.law == HardeningLaw::kHollomon
                       ? "material.hardening.n"
                       : "slope of ln sigma over ln eps between eps 0.1 and 0.2";
    flc.thickness_mm = scene.blank.thickness_mm;
    flc.flc0_percent = keeler_brazier_flc0_percent(flc.n, flc.thickness_mm);
    if (flc.thickness_mm > kFittedThicknessMm) {
      flc.warnings.push_back(fmt::format(
          "forming limit: Keeler-Brazier was fitted to sheets up to {} mm thick; at {:.3g} mm "
          "its curve is an extrapolation (give [forming_limit] model = \"table\" for a measured "
          "one)",
          kFittedThicknessMm, flc.thickness_mm));
    }
  } else if (spec.model == FormingLimitModel::kTable) {
    flc.minor = spec.table_minor;
    flc.major = spec.table_major;
  }
  return flc;
}

double FormingLimitCurve::major_limit(double eps_minor) const {
  if (!defined() || std::isnan(eps_minor)) return kNaN;
  if (model == FormingLimitModel::kKeelerBrazier) {
    const double e0 = flc0_percent / 100.0;
    if (eps_minor <= 0.0) return std::log1p(e0) - eps_minor;
    return std::log1p(e0 + kRightSlope * std::expm1(eps_minor));
  }
  if (minor.empty()) return kNaN;
  if (eps_minor <= minor.front()) return major.front();
  if (eps_minor >= minor.back()) return major.back();
  const auto hi = std::upper_bound(minor.begin(), minor.end(), eps_minor);
  const std::size_t k = static_cast<std::size_t>(hi - minor.begin());
  const double t = (eps_minor - minor[k - 1]) / (minor[k] - minor[k - 1]);
  return major[k - 1] + t * (major[k] - major[k - 1]);
}

std::string FormingLimitCurve::description() const {
  switch (model) {
    case FormingLimitModel::kKeelerBrazier:
      return fmt::format(
          "keeler-brazier: n {:.4g} ({}), t {:.4g} mm, FLC0 {:.3g} % engineering = {:.4g} true "
          "major strain; safety margin {:.3g}",
          n, n_source, thickness_mm, flc0_percent, major_limit(0.0), safety_margin);
    case FormingLimitModel::kTable:
      return fmt::format(
          "table: {} points, minor strain {:.4g} to {:.4g}, FLC0 {:.4g} true major strain; "
          "safety margin {:.3g}",
          minor.size(), minor.front(), minor.back(), major_limit(0.0), safety_margin);
    case FormingLimitModel::kNone:
      return "none";
  }
  return "none";
}

FormingMargin forming_margin(const FormingLimitCurve& flc, double eps_major, double eps_minor) {
  FormingMargin m;
  m.margin = flc.major_limit(eps_minor) - eps_major;
  if (std::isnan(m.margin)) {
    m.margin = kNaN;
    return m;
  }
  m.zone = m.margin < 0.0                 ? FormingZone::kFailed
           : m.margin < flc.safety_margin ? FormingZone::kMarginal
                                          : FormingZone::kSafe;
  return m;
}

FlcPolyline flc_polyline(const FormingLimitCurve& flc, double lo, double hi, double offset) {
  FlcPolyline line;
  if (!flc.defined() || !(lo < hi)) return line;
  std::vector<double> minor = {lo, hi};
  if (lo < 0.0 && hi > 0.0) minor.push_back(0.0);
  for (double x : flc.minor) {
    if (x > lo && x < hi) minor.push_back(x);
  }
  // The curved right branch: 40 chords over the range are within ~1e-4 strain of the curve.
  if (flc.model == FormingLimitModel::kKeelerBrazier) {
    for (int k = 1; k < 40; ++k) {
      const double x = lo + (hi - lo) * k / 40.0;
      if (x > 0.0) minor.push_back(x);
    }
  }
  std::sort(minor.begin(), minor.end());
  minor.erase(std::unique(minor.begin(), minor.end()), minor.end());
  for (double x : minor) {
    line.minor.push_back(x);
    line.major.push_back(flc.major_limit(x) - offset);
  }
  return line;
}

}  // namespace vs
