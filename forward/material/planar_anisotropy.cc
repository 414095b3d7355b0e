#include "material/planar_anisotropy.h"

#include <fmt/format.h>

#include <Eigen/LU>
#include <cmath>

#include "core/error.h"
#include "material/hill48.h"
#include "material/yld2000.h"
#include "material/yld2000_fit.h"

namespace vs {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::unique_ptr<PlanarAnisotropy> hill(const Hill48Coefficients& c, std::string description) {
  auto out = std::make_unique<PlanarAnisotropy>();
  auto h = std::make_unique<Hill48>(c);
  out->quadratic = true;
  out->P = h->P();
  out->A = 3.0 * h->P_inverse();
  out->yield = std::move(h);
  out->description = std::move(description);
  return out;
}

}  // namespace

std::unique_ptr<PlanarAnisotropy> make_planar_anisotropy(const AnisotropySpec& spec,
                                                         const std::string& source) {
  std::unique_ptr<PlanarAnisotropy> out;
  try {
    switch (spec.model) {
      case AnisotropyModel::kNormal:
        return nullptr;
      case AnisotropyModel::kHill48R:
        out =
            hill(hill48_from_r_values(spec.r0, spec.r45, spec.r90),
                 fmt::format("Hill 1948 from r0 {}, r45 {}, r90 {}", spec.r0, spec.r45, spec.r90));
        break;
      case AnisotropyModel::kHill48Stress:
        out = hill(hill48_from_stresses(spec.sigma45_ratio, spec.sigma90_ratio, spec.sigma_b_ratio),
                   fmt::format("Hill 1948 from sigma45/sigma0 {}, sigma90/sigma0 {}, "
                               "sigma_b/sigma0 {}",
                               spec.sigma45_ratio, spec.sigma90_ratio, spec.sigma_b_ratio));
        break;
      case AnisotropyModel::kYld2000: {
        AnisotropyData data;
        data.sigma45 = spec.sigma45_ratio;
        data.sigma90 = spec.sigma90_ratio;
        data.sigma_b = spec.sigma_b_ratio;
        data.r0 = spec.r0;
        data.r45 = spec.r45;
        data.r90 = spec.r90;
        data.r_b = spec.r_b;
        Yld2000FitOptions options;
        options.exponent = spec.exponent;
        const Yld2000FitSummary fit = fit_yld2000(data, options);
        if (!fit.converged) {
          throw InputError(
              fmt::format("the Yld2000-2d identification did not converge ({})", fit.message));
        }
        out = std::make_unique<PlanarAnisotropy>();
        out->yield = std::make_unique<Yld2000>(fit.coefficients);
        const std::array<double, 8>& a = fit.coefficients.alpha;
        out->description = fmt::format(
            "Barlat Yld2000-2d, exponent {}, alpha {:.4f} {:.4f} {:.4f} {:.4f} {:.4f} {:.4f} "
            "{:.4f} {:.4f} (identified from the eight data, largest residual {:.1e})",
            spec.exponent, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], fit.max_residual);
        break;
      }
    }
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: material.anisotropy: {}", source, e.what()));
  }
  out->rd_angle_rad = spec.rolling_direction_deg * kPi / 180.0;
  out->description += fmt::format(", RD at {} deg from x", spec.rolling_direction_deg);
  return out;
}

}  // namespace vs
