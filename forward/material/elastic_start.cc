#include "material/elastic_start.h"

#include <algorithm>
#include <cmath>

namespace vs {

double elastic_start_stress(const Hardening& curve, double E_MPa, double e, double* slope) {
  e = std::max(e, 0.0);
  const double s0 = curve.curve_stress(0.0);
  if (E_MPa * e <= s0) {
    if (slope != nullptr) *slope = E_MPa;
    return E_MPa * e;
  }
  // Root of g(s) = s - sigma_y(e - s / E) in [s0, sigma_y(e)]: Newton, bisection if it leaves
  // the bracket. g is increasing, so the bracket shrinks from the side of each iterate's sign.
  double lo = s0, hi = curve.curve_stress(e);
  double s = hi;
  double H = curve.curve_slope(e - s / E_MPa);
  for (int it = 0; it < 100; ++it) {
    const double ep = std::max(e - s / E_MPa, 0.0);
    const double g = s - curve.curve_stress(ep);
    H = curve.curve_slope(ep);
    if (g > 0.0) {
      hi = s;
    } else {
      lo = s;
    }
    if (g == 0.0 || hi - lo <= 1e-15 * hi) break;
    double next = s - g / (1.0 + H / E_MPa);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - s) <= 1e-15 * s) {
      s = next;
      break;
    }
    s = next;
  }
  if (slope != nullptr) {
    H = curve.curve_slope(std::max(e - s / E_MPa, 0.0));
    *slope = E_MPa * H / (E_MPa + H);
  }
  return s;
}

double elastic_thickness_strain(double E_MPa, double nu, double sigma_1_MPa, double sigma_2_MPa,
                                double sigma_33_MPa) {
  return (sigma_33_MPa - nu * (sigma_1_MPa + sigma_2_MPa)) / E_MPa;
}

double thickness_strain_correction(const ElasticSpec& elastic, double sigma_1_MPa,
                                   double sigma_2_MPa, double sigma_33_MPa) {
  if (!elastic.strains_on()) return 0.0;
  if (elastic.start_on()) {
    return (1.0 - 2.0 * elastic.nu) * (sigma_1_MPa + sigma_2_MPa + sigma_33_MPa) / elastic.E_MPa;
  }
  return elastic_thickness_strain(elastic.E_MPa, elastic.nu, sigma_1_MPa, sigma_2_MPa,
                                  sigma_33_MPa);
}

}  // namespace vs
