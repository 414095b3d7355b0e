#include "lack_of_fit.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <utility>

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

namespace {

// The two tests on `normalised` (non-finite entries dropped) into `out`; false when there are
// too few signed residuals (out->text says so). `figures` gets the tests in words.
bool run_tests(const std::vector<double>& normalised, const std::string& name,
               const LackOfFitOptions& options, LackOfFit* out, bool* pattern,
               std::string* figures) {
  out->z_critical = normal_two_sided(1.0 - 2.0 * options.significance);
  std::vector<double> e;
  for (double v : normalised) {
    if (std::isfinite(v)) e.push_back(v);
  }
  double sum_sq = 0.0;
  for (double v : e) sum_sq += v * v;
  out->rms = e.empty() ? 0.0 : std::sqrt(sum_sq / static_cast<double>(e.size()));

  // Runs of equal sign (zeros carry no sign).
  int positive = 0, negative = 0, last = 0;
  for (double v : e) {
    const int sign = v > 0.0 ? 1 : v < 0.0 ? -1 : 0;
    if (sign == 0) continue;
    (sign > 0 ? positive : negative)++;
    if (sign != last) ++out->runs;
    last = sign;
  }
  out->points = positive + negative;
  if (out->points < kLackOfFitMinPoints) {
    out->text = fmt::format("data set '{}': too few residuals ({}) for the lack-of-fit tests", name,
                            out->points);
    return false;
  }
  const double n = out->points, np = positive, nm = negative;
  if (positive == 0 || negative == 0) {
    out->runs_expected = 1.0;
    out->runs_z = -std::numeric_limits<double>::infinity();
    out->runs_p = std::pow(2.0, 1.0 - n);
  } else {
    out->runs_expected = 1.0 + 2.0 * np * nm / n;
    const double variance = 2.0 * np * nm * (2.0 * np * nm - n) / (n * n * (n - 1.0));
    out->runs_z = variance > 0.0 ? (out->runs - out->runs_expected) / std::sqrt(variance) : 0.0;
    out->runs_p = 0.5 * std::erfc(-out->runs_z / std::sqrt(2.0));
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
  out->lag1 = denominator > 0.0 ? numerator / denominator : 0.0;
  out->lag1_z = (out->lag1 + 1.0 / m) * std::sqrt(m);

  *pattern = out->runs_p < options.significance || out->lag1_z > out->z_critical;
  *figures = fmt::format(
      "{} runs of one sign where {:.1f} are expected for independent noise{}, lag-1 "
      "autocorrelation {:.2f} (noise: {:.2f} +- {:.2f})",
      out->runs, out->runs_expected,
      std::isfinite(out->runs_z) ? fmt::format(" (z = {:.1f})", out->runs_z)
                                 : std::string(" (every residual has one sign)"),
      out->lag1, -1.0 / m, 1.0 / std::sqrt(m));
  return true;
}

// "0.00049 (strain)" for a strain (unit "1": every dimensionless ordinate is one), "42.1 N"
// otherwise.
std::string in_units(double value, const std::string& unit) {
  return unit.empty() || unit == "1" ? fmt::format("{:.3g} (strain)", value)
                                     : fmt::format("{:.3g} {}", value, unit);
}

// A ratio to 3 significant digits without an exponent: "2.7", "5830", "22100".
std::string times(double ratio) {
  if (!(ratio >= 1000.0) || !std::isfinite(ratio)) return fmt::format("{:.3g}", ratio);
  const double unit = std::pow(10.0, std::floor(std::log10(ratio)) - 2.0);
  return fmt::format("{:.0f}", std::round(ratio / unit) * unit);
}

// The verdict of a data set: noise without a pattern, else structural when it is `large`,
// negligible otherwise; with the matching text.
void set_verdict(bool pattern, bool large, std::string noise, std::string structural,
                 std::string negligible, LackOfFit* out) {
  if (!pattern) {
    out->verdict = LackOfFitVerdict::kNoise;
    out->text = std::move(noise);
  } else if (large) {
    out->verdict = LackOfFitVerdict::kStructural;
    out->text = std::move(structural);
  } else {
    out->verdict = LackOfFitVerdict::kNegligible;
    out->text = std::move(negligible);
  }
}

}  // namespace

LackOfFit lack_of_fit(const std::vector<double>& normalised, const std::string& name,
                      const LackOfFitOptions& options) {
  LackOfFit out;
  bool pattern = false;
  std::string tests;
  if (!run_tests(normalised, name, options, &out, &pattern, &tests)) return out;
  const std::string figures = fmt::format("{}, rms misfit {:.3g} sigma", tests, out.rms);
  set_verdict(pattern, out.rms >= options.min_rms,
              fmt::format("data set '{}': the misfit looks like noise ({})", name, figures),
              fmt::format("data set '{}': the misfit is STRUCTURAL, not noise: {}. The model "
                          "cannot follow the shape of this curve, so the statistical intervals "
                          "understate the uncertainty ([[model_form]] alternatives give a "
                          "model-form range)",
                          name, figures),
              fmt::format("data set '{}': the residuals follow a pattern but are far below the "
                          "stated sigma ({}): negligible",
                          name, figures),
              &out);
  return out;
}

LackOfFit lack_of_fit_unstated(const std::vector<double>& difference,
                               const std::vector<double>& resolution, const std::string& unit,
                               const std::string& name, const LackOfFitOptions& options) {
  std::vector<double> e;
  double sum_difference = 0.0, sum_resolution = 0.0;
  for (std::size_t i = 0; i < difference.size() && i < resolution.size(); ++i) {
    if (!std::isfinite(difference[i]) || !(resolution[i] > 0.0) || !std::isfinite(resolution[i])) {
      continue;
    }
    e.push_back(difference[i] / resolution[i]);
    sum_difference += difference[i] * difference[i];
    sum_resolution += resolution[i] * resolution[i];
  }
  LackOfFit out;
  out.sigma_stated = false;
  out.unit = unit;
  if (!e.empty()) {
    out.rms_difference = std::sqrt(sum_difference / static_cast<double>(e.size()));
    out.resolution = std::sqrt(sum_resolution / static_cast<double>(e.size()));
  }
  bool pattern = false;
  std::string tests;
  if (!run_tests(e, name, options, &out, &pattern, &tests)) return out;
  const std::string size = fmt::format("rms {} = {} times the forward solver's resolution {}",
                                       in_units(out.rms_difference, unit), times(out.rms),
                                       in_units(out.resolution, unit));
  const std::string unknown =
      "No sigma was stated for this data set, so its size against the measurement noise is "
      "unknown (the default weighting, a fraction of the curve's range, is not a noise "
      "estimate; state sigma to judge it)";
  set_verdict(
      pattern, out.rms >= options.min_resolutions,
      fmt::format("data set '{}': the misfit looks like noise ({}; misfit {}). {}", name, tests,
                  size, unknown),
      fmt::format("data set '{}': the misfit is STRUCTURAL, not noise: {}. It is systematic, {}: "
                  "far more than the solver's convergence leaves, so the model cannot follow "
                  "the shape of this curve. {}. The statistical intervals, which take the "
                  "residuals as independent, understate the uncertainty ([[model_form]] "
                  "alternatives give a model-form range)",
                  name, tests, size, unknown),
      fmt::format("data set '{}': the residuals follow a pattern but stay within {:g} forward "
                  "resolutions ({}; misfit {}): the solver's convergence noise, negligible",
                  name, options.min_resolutions, tests, size),
      &out);
  return out;
}

void note_unconverged_fit(const std::string& why, LackOfFit* lack_of_fit) {
  lack_of_fit->fit_converged = false;
  if (lack_of_fit->verdict != LackOfFitVerdict::kStructural) return;
  lack_of_fit->text += fmt::format(
      ". But the fit stopped before converging ({}): part of this misfit may be what the "
      "unfinished fit left, not the model's form; continue the fit (more iterations, another "
      "start) before reading it as model-form error",
      why.empty() ? "no reason given" : why);
}

}  // namespace vs
