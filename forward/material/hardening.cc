#include "material/hardening.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "material/elastic_start.h"

namespace vs {

Hardening::Hardening(const HardeningSpec& spec) : spec_(spec) {
  if (spec_.law == HardeningLaw::kHollomon) {
    hollomon_plateau_strain_ = std::pow(spec_.sigma0_MPa / spec_.K_MPa, 1.0 / spec_.n);
  }
  assert(spec_.law != HardeningLaw::kTable ||
         (spec_.table_strain.size() >= 2 &&
          spec_.table_strain.size() == spec_.table_stress_MPa.size()));
}

Hardening::Hardening(const HardeningSpec& spec, const ElasticSpec& elastic) : Hardening(spec) {
  if (elastic.start_on()) start_modulus_MPa_ = elastic.E_MPa;
}

double Hardening::flow_stress(double eps) const {
  if (start_modulus_MPa_ > 0.0)
    return elastic_start_stress(*this, start_modulus_MPa_, eps, nullptr);
  return curve_stress(eps);
}

double Hardening::flow_stress_and_slope(double eps, double* slope) const {
  if (start_modulus_MPa_ > 0.0) return elastic_start_stress(*this, start_modulus_MPa_, eps, slope);
  *slope = curve_slope(eps);
  return curve_stress(eps);
}

double Hardening::slope(double eps) const {
  if (start_modulus_MPa_ > 0.0) {
    double s = 0.0;
    elastic_start_stress(*this, start_modulus_MPa_, eps, &s);
    return s;
  }
  return curve_slope(eps);
}

namespace {

// Index i of the table segment [i, i+1] holding eps (first/last segment outside the table).
std::size_t segment(const std::vector<double>& x, double eps) {
  auto it = std::upper_bound(x.begin(), x.end(), eps);
  std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - x.begin(), 1)) - 1;
  return std::min(i, x.size() - 2);
}

}  // namespace

double Hardening::curve_stress(double eps) const {
  eps = std::max(eps, 0.0);
  switch (spec_.law) {
    case HardeningLaw::kSwift:
      return spec_.K_MPa * std::pow(spec_.eps0 + eps, spec_.n);
    case HardeningLaw::kHollomon:
      return eps <= hollomon_plateau_strain_ ? spec_.sigma0_MPa
                                             : spec_.K_MPa * std::pow(eps, spec_.n);
    case HardeningLaw::kVoce:
      return spec_.sigma0_MPa + spec_.Q_MPa * (1.0 - std::exp(-spec_.b * eps));
    case HardeningLaw::kTable: {
      const auto& x = spec_.table_strain;
      const auto& y = spec_.table_stress_MPa;
      const std::size_t i = segment(x, eps);
      const double s = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
      return spec_.table_scale * (y[i] + s * (eps - x[i]));
    }
  }
  return 0.0;
}

double Hardening::curve_slope(double eps) const {
  eps = std::max(eps, 0.0);
  switch (spec_.law) {
    case HardeningLaw::kSwift:
      return spec_.K_MPa * spec_.n * std::pow(spec_.eps0 + eps, spec_.n - 1.0);
    case HardeningLaw::kHollomon:
      return eps <= hollomon_plateau_strain_ ? 0.0
                                             : spec_.K_MPa * spec_.n * std::pow(eps, spec_.n - 1.0);
    case HardeningLaw::kVoce:
      return spec_.Q_MPa * spec_.b * std::exp(-spec_.b * eps);
    case HardeningLaw::kTable: {
      const auto& x = spec_.table_strain;
      const auto& y = spec_.table_stress_MPa;
      const std::size_t i = segment(x, eps);
      return spec_.table_scale * (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
    }
  }
  return 0.0;
}

}  // namespace vs
