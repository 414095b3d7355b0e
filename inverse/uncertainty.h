// Linearised uncertainty at the optimum, from the Jacobian J = d r / d x of the weighted
// residuals:  Cov = s^2 (J^T J)^-1, with s^2 = 2 cost / (m - p) = |r|^2 / (m - p) (the residual
// variance; for correctly stated sigmas it is ~1). Exact for a linear model; for a nonlinear
// one it is a local approximation (see ecosystem.md B.2), which is why the summary also says
// plainly when the numbers mean little: rank deficiency, |correlation| above a threshold, a
// relative standard error above a threshold, or a parameter sitting on a bound.
//
// Intervals: value +- q * std_error with q the two-sided Student-t quantile with m - p degrees of
// freedom when s^2 is estimated from the residuals (the textbook choice for linear least
// squares with unknown variance), or the normal quantile when the stated sigmas are trusted
// (scale_by_residual_variance = false) or m <= p.
//
// Computed with an SVD of J * diag(scale) (the same dense-SVD algorithm as
// ceres::Covariance's DENSE_SVD), so that rank and condition number are judged in the units the
// user declared typical for each parameter.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "lack_of_fit.h"

namespace vs {

struct UncertaintyOptions {
  double confidence = 0.95;
  bool scale_by_residual_variance = true;
  // Singular values below rank_tolerance * largest count as zero.
  double rank_tolerance = 1e-8;
  double correlation_threshold = 0.95;  // |corr| above this: "poorly determined"
  // std_error / |value| above this: "poorly determined". 0.1 means a 95 % interval wider than
  // about +-20 % of the value: too wide to use the number for prediction.
  double relative_error_threshold = 0.1;
  // The per-data-set lack-of-fit diagnostic (lack_of_fit.h).
  LackOfFitOptions lack_of_fit;
  // Parameters eliminated from the residuals before the fit (the offset of each shape-only data
  // set, cup_height_curve.h): not in the Jacobian, but they use degrees of freedom, so the
  // residual variance and the Student-t quantile take m - p - eliminated_parameters. Set by
  // calibrate(), not a config key.
  int eliminated_parameters = 0;

  bool IsValid(std::string* why) const;
};

struct ParameterUncertainty {
  std::string name;
  double value = 0.0;
  double std_error = 0.0;       // +inf when not determined (null-space direction)
  double interval_lower = 0.0;  // value -+ quantile * std_error
  double interval_upper = 0.0;
  bool determined = true;  // false: in the null space, strongly correlated, or huge error
  bool at_bound = false;
  // How far the forward solver's resolution lets the estimate sit from the least-squares
  // optimum (add_forward_resolution); included in the interval.
  double forward_resolution = 0.0;
};

struct UncertaintySummary {
  int num_residuals = 0;
  int num_parameters = 0;
  int degrees_of_freedom = 0;           // m - p (- eliminated parameters)
  double residual_variance = 1.0;       // s^2 used to scale (1 when not scaled)
  double quantile = 0.0;                // the q of the intervals
  std::string quantile_kind;            // "student_t(dof)" or "normal"
  std::vector<double> singular_values;  // of J * diag(scale), descending
  int rank = 0;
  double condition_number = 0.0;  // largest / smallest singular value (inf if rank deficient)
  Eigen::MatrixXd covariance;     // own units; NaN rows/columns for undetermined parameters
  Eigen::MatrixXd correlation;
  std::vector<ParameterUncertainty> parameters;
  std::vector<std::string> statements;  // plain-language warnings, empty if all is well
  bool well_determined() const { return statements.empty(); }
};

// `jacobian` is m x p in the parameters' own units; `cost` = 0.5 |r|^2 at `values`.
// `lower`/`upper` only serve the at-bound warning.
// Widens each parameter (with a finite standard error)'s interval by its forward resolution
// sqrt(2 F [(J^T J)^-1]_jj): a fit that stops where the linearised model offers a decrease
// D <= F (the noise floor, least_squares.h) leaves the parameters within that distance of the
// least-squares optimum (|e_j^T dx| <= sqrt(e_j^T (J^T J)^-1 e_j) |J dx| and |J dx|^2 = 2 D).
// With noise-free data the statistical interval shrinks to the solver's jitter and this term
// is what keeps the truth inside; with noisy data it is negligible. `jacobian` in own units.
void add_forward_resolution(const Eigen::MatrixXd& jacobian, double noise_floor_cost,
                            UncertaintySummary* summary);

UncertaintySummary estimate_uncertainty(const Eigen::MatrixXd& jacobian, double cost,
                                        const Eigen::VectorXd& values, const Eigen::VectorXd& scale,
                                        const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                        const std::vector<std::string>& names,
                                        const UncertaintyOptions& options);

}  // namespace vs
