// The forming-limit curve (FLC) of a scene ([forming_limit], scene.h) in true (logarithmic)
// strains, as the forming-limit diagram plots them, and the margin of a strain state to it.
//
// Keeler-Brazier, in the form given by the AHSS Application Guidelines ("Forming Limit Curves",
// ahssinsights.org, after Keeler and Brazier 1977): the lowest point of the curve, at plane
// strain, is
//   FLC0 = (23.3 + 14.13 t) n / 0.21   [% engineering major strain; t in mm, fitted for t <= 3]
// with the hardening exponent n; the left branch (minor < 0) is a line of constant thinning in
// true strains, the right branch rises with slope 0.6 in engineering strains (the source: "at
// least through minor strains of 20 %"; extended beyond). With e0 = FLC0 / 100, in true strains
// (e = exp(eps) - 1 converts engineering e to true eps):
//   minor <= 0:  major = ln(1 + e0) - minor                   (thickness strain -ln(1 + e0))
//   minor >= 0:  major = ln(1 + e0 + 0.6 (exp(minor) - 1))    (e_major = e0 + 0.6 e_minor)
// Both give ln(1 + e0) at minor = 0. n is material.hardening.n for Swift and Hollomon; Voce and
// table flow curves have none, so n is the mean slope of ln sigma over ln eps between eps = 0.1
// and 0.2 (two points of the tensile range ASTM E646 uses for n).
//
// A user table is linear between its points and constant beyond its ends (conservative: both
// branches rise away from plane strain).
//
// Margin of a point = FLC(minor) - major, in major true strain: negative beyond the curve
// ("failed"), below safety_margin "marginal", else "safe".
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace vs {

enum class FormingZone { kSafe, kMarginal, kFailed, kUnknown };

// "safe", "marginal", "failed"; "none" when there is no curve or no strain.
const char* forming_zone_name(FormingZone zone);

struct FormingLimitCurve {
  FormingLimitModel model = FormingLimitModel::kNone;
  double safety_margin = 0.1;  // major true strain
  // Keeler-Brazier:
  double n = 0.0;
  std::string n_source;  // "material.hardening.n" or how it was taken from the flow curve
  double thickness_mm = 0.0;
  double flc0_percent = 0.0;  // engineering major strain at plane strain [%]
  // Table (true strains; minor strictly increasing):
  std::vector<double> minor, major;
  // Caveats for run.json (Keeler-Brazier beyond the thickness it was fitted to).
  std::vector<std::string> warnings;

  bool defined() const { return model != FormingLimitModel::kNone; }
  // Major true strain on the curve at `eps_minor`; NaN without a curve or for a NaN strain.
  double major_limit(double eps_minor) const;
  // One line for run.json and the summary, e.g. "keeler-brazier: n 0.216 (material.hardening.n),
  // t 0.85 mm, FLC0 36.3 % engineering = 0.309 true major strain".
  std::string description() const;
};

// FLC0 [% engineering major strain] of Keeler-Brazier.
double keeler_brazier_flc0_percent(double n, double thickness_mm);

// The exponent of a flow curve: material.hardening.n (Swift, Hollomon), else
// ln(sigma(0.2) / sigma(0.1)) / ln 2.
double hardening_exponent(const HardeningSpec& hardening);

FormingLimitCurve forming_limit_curve(const Scene& scene);

struct FormingMargin {
  double margin = 0.0;  // FLC(minor) - major [true strain]; NaN when unknown
  FormingZone zone = FormingZone::kUnknown;
};

FormingMargin forming_margin(const FormingLimitCurve& flc, double eps_major, double eps_minor);

// The curve lowered by `offset` (0: the FLC; safety_margin: the margin line) as a polyline from
// minor strain `lo` to `hi` (lo < hi): the branch ends, plane strain and the table points inside,
// and enough points between them to draw the curved right branch. Empty without a curve.
struct FlcPolyline {
  std::vector<double> minor, major;
};
FlcPolyline flc_polyline(const FormingLimitCurve& flc, double lo, double hi, double offset);

}  // namespace vs
