// Lack-of-fit diagnostic of one data set (issue 15): are the normalised residuals at the optimum,
// e_i = (simulated_i - measured_i) / sigma_i in the order of the abscissa, independent noise, or
// a systematic pattern that the model cannot follow (model-form error)? Two classical tests of
// independence against positive serial dependence, each one-sided at `significance`:
//
// * Wald-Wolfowitz runs test on the signs of e (zeros dropped): with n+ positive and n- negative
//   signs, n = n+ + n-, independent signs give E[runs] = 1 + 2 n+ n- / n and
//   Var[runs] = 2 n+ n- (2 n+ n- - n) / (n^2 (n - 1)); too FEW runs (z = (runs - E) / sd below
//   -z_alpha) means long stretches of one sign. All signs equal (n+ or n- = 0) has probability
//   2^(1-n) under independence and is judged by that.
// * Lag-1 autocorrelation rho_1 = sum (e_i - m)(e_{i+1} - m) / sum (e_i - m)^2: for independent
//   noise approximately normal with mean -1/n and variance 1/n, so (rho_1 + 1/n) sqrt(n) above
//   z_alpha is a pattern.
//
// A pattern is only called structural when it matters: its rms (in stated sigmas) is at least
// `min_rms`. A perfect fit of noise-free synthetic data leaves a smooth residual of the forward
// solver's convergence noise, far below one sigma: that is "negligible", not model-form error.
//
// A data set WITHOUT a stated sigma (weighted by the relative default, a fraction of its range)
// has no noise scale to measure the pattern in: a threshold in default sigmas would make the
// verdict depend on an arbitrary number. The one scale that is known is the forward solver's
// resolution of each simulated value, delta_i (the noise floor of least_squares.h:
// noise_floor_factor x tolerance x the curve's largest |value|). lack_of_fit_unstated() runs the
// same two tests on e_i = (simulated_i - measured_i) / delta_i and calls a pattern structural
// when its rms is at least `min_resolutions` resolutions. Why that separates the solver's noise
// from model-form error: a fit that stops at the noise floor (D <= F, least_squares.h) leaves
// |Q^T r|^2 <= 2 |r| |delta| + |delta|^2 in the range of the Jacobian and the solver's jitter,
// at most |delta| by the choice of the factor, outside it, so |r|^2 <= 2 |r| |delta| +
// 2 |delta|^2, i.e. |r| <= (1 + sqrt 3) |delta|: rms <= 2.7 resolutions. A pattern of 10 or more
// cannot be the solver's convergence noise; the model does not follow the curve. Whether that
// misfit matters against the measurement noise cannot be said without a sigma, and the text says
// so, with the misfit's size in the data's own units.
#pragma once

#include <string>
#include <vector>

namespace vs {

struct LackOfFitOptions {
  double significance = 0.01;  // one-sided level of each of the two tests
  double min_rms = 0.5;        // rms of e (in sigmas) below which a pattern is negligible
  // No sigma stated: rms of the misfit, in forward resolutions, below which a pattern is the
  // solver's convergence noise (negligible); see the file comment for the bound 2.7.
  double min_resolutions = 10.0;
};

enum class LackOfFitVerdict {
  kNoise,       // no pattern: the residuals look like independent noise
  kStructural,  // a pattern of at least min_rms sigmas (min_resolutions forward resolutions
                // without a stated sigma): the model cannot represent the curve
  kNegligible,  // a pattern, but below that size
  kNotTested,   // fewer than kMinPoints residuals of either sign
};

std::string to_string(LackOfFitVerdict verdict);

struct LackOfFit {
  LackOfFitVerdict verdict = LackOfFitVerdict::kNotTested;
  int points = 0;    // residuals with a sign (non-zero)
  double rms = 0.0;  // of e: in sigmas, or in forward resolutions when sigma_stated is false
  // Without a stated sigma (lack_of_fit_unstated): the misfit and the forward resolution in the
  // data's units (N, 1 for strain, mm), both as rms over the points.
  bool sigma_stated = true;
  double rms_difference = 0.0;
  double resolution = 0.0;
  std::string unit;
  int runs = 0;
  double runs_expected = 0.0;
  double runs_z = 0.0;        // (runs - expected) / sd; -inf when every sign is equal
  double runs_p = 1.0;        // one-sided p-value of too few runs
  double lag1 = 0.0;          // lag-1 autocorrelation
  double lag1_z = 0.0;        // (lag1 + 1/n) sqrt(n)
  double z_critical = 0.0;    // one-sided normal quantile of the significance
  std::string text;           // the verdict in words
  bool fit_converged = true;  // false: the fit stopped early (note_unconverged_fit)
};

inline constexpr int kLackOfFitMinPoints = 8;

// `normalised` in the order of the data set's abscissa; `name` labels the text.
LackOfFit lack_of_fit(const std::vector<double>& normalised, const std::string& name,
                      const LackOfFitOptions& options);

// A data set with no stated sigma: `difference` = simulated - measured and `resolution` = the
// forward resolution delta_i > 0 of each point, both in the data's units `unit` ("N", "mm", or
// "1" for a strain), in the order of the abscissa. Points with a non-finite difference or a
// resolution that is not positive are left out.
LackOfFit lack_of_fit_unstated(const std::vector<double>& difference,
                               const std::vector<double>& resolution, const std::string& unit,
                               const std::string& name, const LackOfFitOptions& options);

// The fit stopped before converging (the iteration limit, or steps that kept failing): the
// misfit at its end holds what the unfinished fit left besides the model's form, and the bound
// of 2.7 resolutions (file comment) does not hold. A structural verdict then says so, with
// `why` (the optimiser's reason), and fit_converged is false; other verdicts are unchanged.
void note_unconverged_fit(const std::string& why, LackOfFit* lack_of_fit);

}  // namespace vs
