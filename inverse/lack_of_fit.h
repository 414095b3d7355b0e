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
#pragma once

#include <string>
#include <vector>

namespace vs {

struct LackOfFitOptions {
  double significance = 0.01;  // one-sided level of each of the two tests
  double min_rms = 0.5;        // rms of e (in sigmas) below which a pattern is negligible
};

enum class LackOfFitVerdict {
  kNoise,       // no pattern: the residuals look like independent noise
  kStructural,  // a pattern of at least min_rms sigmas: the model cannot represent the curve
  kNegligible,  // a pattern, but below min_rms sigmas
  kNotTested,   // fewer than kMinPoints residuals of either sign
};

std::string to_string(LackOfFitVerdict verdict);

struct LackOfFit {
  LackOfFitVerdict verdict = LackOfFitVerdict::kNotTested;
  int points = 0;  // residuals with a sign (non-zero)
  double rms = 0.0;
  int runs = 0;
  double runs_expected = 0.0;
  double runs_z = 0.0;      // (runs - expected) / sd; -inf when every sign is equal
  double runs_p = 1.0;      // one-sided p-value of too few runs
  double lag1 = 0.0;        // lag-1 autocorrelation
  double lag1_z = 0.0;      // (lag1 + 1/n) sqrt(n)
  double z_critical = 0.0;  // one-sided normal quantile of the significance
  std::string text;         // the verdict in words
};

inline constexpr int kLackOfFitMinPoints = 8;

// `normalised` in the order of the data set's abscissa; `name` labels the text.
LackOfFit lack_of_fit(const std::vector<double>& normalised, const std::string& name,
                      const LackOfFitOptions& options);

}  // namespace vs
