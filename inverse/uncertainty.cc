#include "uncertainty.h"

#include <fmt/format.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "quantiles.h"

namespace vs {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool near_bound(double value, double bound, double scale) {
  return std::isfinite(bound) && std::abs(value - bound) <= 1e-6 * scale;
}

}  // namespace

bool UncertaintyOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (!(confidence > 0.0 && confidence < 1.0)) return fail("confidence must be in (0, 1)");
  if (!(rank_tolerance > 0.0 && rank_tolerance < 1.0)) return fail("rank_tolerance in (0, 1)");
  if (!(correlation_threshold > 0.0 && correlation_threshold <= 1.0)) {
    return fail("correlation_threshold must be in (0, 1]");
  }
  if (!(relative_error_threshold > 0.0)) return fail("relative_error_threshold must be > 0");
  if (!(lack_of_fit.significance > 0.0 && lack_of_fit.significance < 0.5)) {
    return fail("lack_of_fit_significance must be in (0, 0.5)");
  }
  if (!(lack_of_fit.min_rms >= 0.0) || !std::isfinite(lack_of_fit.min_rms)) {
    return fail("lack_of_fit_min_rms must be finite and >= 0");
  }
  if (!(lack_of_fit.min_resolutions >= 0.0) || !std::isfinite(lack_of_fit.min_resolutions)) {
    return fail("lack_of_fit_min_resolutions must be finite and >= 0");
  }
  return true;
}

UncertaintySummary estimate_uncertainty(const Eigen::MatrixXd& jacobian, double cost,
                                        const Eigen::VectorXd& values, const Eigen::VectorXd& scale,
                                        const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                        const std::vector<std::string>& names,
                                        const UncertaintyOptions& options) {
  const Eigen::Index m = jacobian.rows();
  const Eigen::Index p = jacobian.cols();
  UncertaintySummary out;
  out.num_residuals = static_cast<int>(m);
  out.num_parameters = static_cast<int>(p);
  const Eigen::Index dof = m - p - std::max(0, options.eliminated_parameters);
  out.degrees_of_freedom = static_cast<int>(dof);

  const bool scaled = options.scale_by_residual_variance && dof > 0;
  out.residual_variance = scaled ? 2.0 * cost / static_cast<double>(dof) : 1.0;
  if (scaled) {
    out.quantile = student_t_two_sided(options.confidence, static_cast<double>(dof));
    out.quantile_kind = fmt::format("student_t({})", dof);
  } else {
    out.quantile = normal_two_sided(options.confidence);
    out.quantile_kind = "normal";
  }
  if (options.scale_by_residual_variance && dof <= 0) {
    out.statements.push_back(fmt::format(
        "only {} residuals for {} parameters{}: the residual variance cannot be estimated; the "
        "intervals assume the stated measurement sigmas",
        m, p,
        options.eliminated_parameters > 0
            ? fmt::format(" and {} eliminated offset(s)", options.eliminated_parameters)
            : std::string()));
  }

  // J_s = J diag(scale) = U S V^T;  Cov_s = s^2 V S^-2 V^T over the determined directions.
  const Eigen::MatrixXd js = jacobian * scale.asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(js, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  out.singular_values.assign(s.data(), s.data() + s.size());
  const double s_max = s.size() > 0 ? s[0] : 0.0;
  Eigen::Index rank = 0;
  while (rank < s.size() && s[rank] > options.rank_tolerance * s_max) ++rank;
  out.rank = static_cast<int>(rank);
  out.condition_number = rank == p && rank > 0 ? s_max / s[rank - 1] : kInf;

  // A parameter is undetermined if it has a sizeable component in the null space.
  std::vector<bool> in_null_space(p, false);
  for (Eigen::Index k = rank; k < p; ++k) {
    for (Eigen::Index j = 0; j < p; ++j) {
      if (std::abs(v(j, k)) > 1e-3) in_null_space[j] = true;
    }
  }
  Eigen::MatrixXd cov_s = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index k = 0; k < rank; ++k) {
    cov_s += v.col(k) * v.col(k).transpose() / (s[k] * s[k]);
  }
  cov_s *= out.residual_variance;
  out.covariance = scale.asDiagonal() * cov_s * scale.asDiagonal();
  for (Eigen::Index j = 0; j < p; ++j) {
    if (!in_null_space[j]) continue;
    out.covariance.row(j).setConstant(kNaN);
    out.covariance.col(j).setConstant(kNaN);
  }

  out.correlation = Eigen::MatrixXd::Constant(p, p, kNaN);
  for (Eigen::Index i = 0; i < p; ++i) {
    for (Eigen::Index j = 0; j < p; ++j) {
      const double denominator = std::sqrt(out.covariance(i, i) * out.covariance(j, j));
      if (std::isfinite(denominator) && denominator > 0.0) {
        out.correlation(i, j) = out.covariance(i, j) / denominator;
      }
    }
  }

  for (Eigen::Index j = 0; j < p; ++j) {
    ParameterUncertainty u;
    u.name = names.at(j);
    u.value = values[j];
    u.std_error = in_null_space[j] ? kInf : std::sqrt(out.covariance(j, j));
    u.interval_lower = u.value - out.quantile * u.std_error;
    u.interval_upper = u.value + out.quantile * u.std_error;
    u.at_bound = near_bound(u.value, lower[j], scale[j]) || near_bound(u.value, upper[j], scale[j]);
    if (in_null_space[j]) {
      u.determined = false;
      out.statements.push_back(fmt::format(
          "{} is not determined by the data (the Jacobian has rank {} of {}; this parameter lies "
          "in its null space): its value is where the optimiser left it, not a result",
          u.name, rank, p));
    } else {
      // Relative to the value, or to the declared typical magnitude when the value is near
      // zero (a friction of 0 +- 0.001 is well determined; 0.001 / 0 is not a percentage).
      const bool near_zero = std::abs(u.value) < 0.01 * scale[j];
      const double reference = near_zero ? scale[j] : std::abs(u.value);
      const double relative = u.std_error / reference;
      if (relative > options.relative_error_threshold) {
        u.determined = false;
        out.statements.push_back(
            near_zero ? fmt::format("{} is poorly determined: standard error {:.3g} is {:.3g}% of "
                                    "its scale {:.3g} (the value {:.3g} is near zero)",
                                    u.name, u.std_error, 100.0 * relative, scale[j], u.value)
                      : fmt::format("{} is poorly determined: standard error {:.3g} is {:.3g}% of "
                                    "its value",
                                    u.name, u.std_error, 100.0 * relative));
      }
    }
    if (u.at_bound) {
      out.statements.push_back(fmt::format(
          "{} ended on a bound ({:.6g}): the interval ignores the bound and the optimum may lie "
          "beyond it",
          u.name, u.value));
    }
    out.parameters.push_back(u);
  }
  for (Eigen::Index i = 0; i < p; ++i) {
    for (Eigen::Index j = i + 1; j < p; ++j) {
      const double c = out.correlation(i, j);
      if (std::isfinite(c) && std::abs(c) > options.correlation_threshold) {
        out.parameters[i].determined = false;
        out.parameters[j].determined = false;
        out.statements.push_back(fmt::format(
            "{} and {} are poorly determined separately: correlation {:+.3f}; the data fix a "
            "combination of them, not each one",
            names[i], names[j], c));
      }
    }
  }
  if (rank == p && out.condition_number > 1.0 / options.rank_tolerance * 1e-2) {
    out.statements.push_back(fmt::format(
        "the scaled Jacobian is ill-conditioned (condition number {:.3g})", out.condition_number));
  }
  return out;
}

void add_forward_resolution(const Eigen::MatrixXd& jacobian, double noise_floor_cost,
                            UncertaintySummary* summary) {
  if (!(noise_floor_cost > 0.0) || jacobian.cols() == 0) return;
  const Eigen::MatrixXd inverse =
      (jacobian.transpose() * jacobian).completeOrthogonalDecomposition().pseudoInverse();
  for (Eigen::Index j = 0; j < jacobian.cols(); ++j) {
    auto& u = summary->parameters.at(static_cast<std::size_t>(j));
    if (!std::isfinite(u.std_error) || !(inverse(j, j) > 0.0)) continue;
    u.forward_resolution = std::sqrt(2.0 * noise_floor_cost * inverse(j, j));
    u.interval_lower -= u.forward_resolution;
    u.interval_upper += u.forward_resolution;
  }
}

}  // namespace vs
