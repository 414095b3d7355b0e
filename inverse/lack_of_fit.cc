#include "lack_of_fit.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "quantiles.h"

namespace vs {

std::string to_string(LackOfFitVerdict verdict) {
  switch (verdict) {
    case LackOfFitVerdict::kNoise:
      return "noise";
    case LackOfFitVerdict::kStructural:
      return "structural";
    case LackOfFitVerdict::kNegligible:
      return "negligible";
    case LackOfFitVerdict::kNotTested:
      return "not_tested";
  }
  return "?";
}

LackOfFit lack_of_fit(const std::vector<double>& normalised, const std::string& name,
                      const LackOfFitOptions& options) {
  LackOfFit out;
  out.z_critical = normal_two_sided(1.0 - 2.0 * options.significance);
  std::vector<double> e;
  for (double v : normalised) {
    if (std::isfinite(v)) e.push_back(v);
  }
  double sum_sq = 0.0;
  for (double v : e) sum_sq += v * v;
  out.rms = e.empty() ? 0.0 : std::sqrt(sum_sq / static_cast<double>(e.size()));

  // Runs of equal sign (zeros carry no sign).
  int positive = 0, negative = 0, last = 0;
  for (double v : e) {
    const int sign = v > 0.0 ? 1 : v < 0.0 ? -1 : 0;
    if (sign == 0) continue;
    (sign > 0 ? positive : negative)++;
    if (sign != last) ++out.runs;
    last = sign;
  }
  out.points = positive + negative;
  if (out.points < kLackOfFitMinPoints) {
    out.text = fmt::format("data set '{}': too few residuals ({}) for the lack-of-fit tests", name,
                           out.points);
    return out;
  }
  const double n = out.points, np = positive, nm = negative;
  if (positive == 0 || negative == 0) {
    out.runs_expected = 1.0;
    out.runs_z = -std::numeric_limits<double>::infinity();
    out.runs_p = std::pow(2.0, 1.0 - n);
  } else {
    out.runs_expected = 1.0 + 2.0 * np * nm / n;
    const double variance = 2.0 * np * nm * (2.0 * np * nm - n) / (n * n * (n - 1.0));
    out.runs_z = variance > 0.0 ? (out.runs - out.runs_expected) / std::sqrt(variance) : 0.0;
    out.runs_p = 0.5 * std::erfc(-out.runs_z / std::sqrt(2.0));
  }

  // Lag-1 autocorrelation of the residuals about their mean.
  double mean = 0.0;
  for (double v : e) mean += v;
  mean /= static_cast<double>(e.size());
  double denominator = 0.0, numerator = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    denominator += (e[i] - mean) * (e[i] - mean);
    if (i + 1 < e.size()) numerator += (e[i] - mean) * (e[i + 1] - mean);
  }
  const double m = static_cast<double>(e.size());
  out.lag1 = denominator > 0.0 ? numerator / denominator : 0.0;
  out.lag1_z = (out.lag1 + 1.0 / m) * std::sqrt(m);

  const bool few_runs = out.runs_p < options.significance;
  const bool correlated = out.lag1_z > out.z_critical;
  const std::string figures = fmt::format(
      "{} runs of one sign where {:.1f} are expected for independent noise{}, lag-1 "
      "autocorrelation {:.2f} (noise: {:.2f} +- {:.2f}), rms misfit {:.3g} sigma",
      out.runs, out.runs_expected,
      std::isfinite(out.runs_z) ? fmt::format(" (z = {:.1f})", out.runs_z)
                                : std::string(" (every residual has one sign)"),
      out.lag1, -1.0 / m, 1.0 / std::sqrt(m), out.rms);
  if (!few_runs && !correlated) {
    out.verdict = LackOfFitVerdict::kNoise;
    out.text = fmt::format("data set '{}': the misfit looks like noise ({})", name, figures);
  } else if (out.rms >= options.min_rms) {
    out.verdict = LackOfFitVerdict::kStructural;
    out.text = fmt::format(
        "data set '{}': the misfit is STRUCTURAL, not noise: {}. The model cannot follow the "
        "shape of this curve, so the statistical intervals understate the uncertainty "
        "([[model_form]] "
        "alternatives give a model-form range)",
        name, figures);
  } else {
    out.verdict = LackOfFitVerdict::kNegligible;
    out.text = fmt::format(
        "data set '{}': the residuals follow a pattern but are far below the stated sigma "
        "({}): negligible",
        name, figures);
  }
  return out;
}

}  // namespace vs
