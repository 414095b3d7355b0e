// The forming-limit curve against closed forms: Keeler-Brazier FLC0, its two branches in true
// strains, the exponent of flow curves without n, a user table, margins and zones, the FLD
// figure's curves and the summary's smallest margin.
#include "output/forming_limit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "output/fld.h"
#include "output/run_plots.h"
#include "output/run_summary.h"
#include "output/suspect_results.h"
#include "test_data.h"

namespace vs {
namespace {

Scene keeler_scene(double n, double thickness_mm) {
  Scene s;
  s.blank.thickness_mm = thickness_mm;
  s.material.hardening.law = HardeningLaw::kSwift;
  s.material.hardening.n = n;
  return s;
}

TEST(FormingLimit, KeelerBrazierPlaneStrainPoint) {
  // (23.3 + 14.13 t) n / 0.21: n = 0.21 leaves the thickness term, n = 0.105 halves it.
  EXPECT_DOUBLE_EQ(keeler_brazier_flc0_percent(0.21, 1.0), 37.43);
  EXPECT_DOUBLE_EQ(keeler_brazier_flc0_percent(0.105, 2.0), 0.5 * (23.3 + 28.26));
  // Example 1's steel: n 0.216, t 0.85 mm -> 36.3194 % engineering = ln(1.363194) true.
  const FormingLimitCurve flc = forming_limit_curve(keeler_scene(0.216, 0.85));
  EXPECT_NEAR(flc.flc0_percent, 36.3194, 1e-4);
  EXPECT_NEAR(flc.major_limit(0.0), std::log(1.363194), 1e-6);
  EXPECT_EQ(flc.n_source, "material.hardening.n");
  EXPECT_TRUE(flc.warnings.empty());
}

TEST(FormingLimit, KeelerBrazierBranchesInTrueStrain) {
  const FormingLimitCurve flc = forming_limit_curve(keeler_scene(0.2, 1.0));
  const double e0 = flc.flc0_percent / 100.0;
  // Left: constant thickness strain -(major + minor) = -ln(1 + e0).
  for (double minor : {-0.4, -0.2, -0.05}) {
    EXPECT_NEAR(flc.major_limit(minor) + minor, std::log1p(e0), 1e-14) << minor;
  }
  // Right: engineering major = e0 + 0.6 engineering minor (e = exp(eps) - 1).
  for (double e_minor : {0.05, 0.2, 0.4}) {
    const double e_major = std::expm1(flc.major_limit(std::log1p(e_minor)));
    EXPECT_NEAR(e_major, e0 + 0.6 * e_minor, 1e-13) << e_minor;
  }
  EXPECT_TRUE(std::isnan(flc.major_limit(std::nan(""))));
}

TEST(FormingLimit, ExponentOfCurvesWithoutN) {
  HardeningSpec voce;
  voce.law = HardeningLaw::kVoce;
  voce.sigma0_MPa = 200.0;
  voce.Q_MPa = 150.0;
  voce.b = 8.0;
  const double s1 = 200.0 + 150.0 * (1.0 - std::exp(-0.8));
  const double s2 = 200.0 + 150.0 * (1.0 - std::exp(-1.6));
  EXPECT_NEAR(hardening_exponent(voce), std::log(s2 / s1) / std::log(2.0), 1e-12);
  // A tabulated power law K eps^0.25 gives 0.25 back between its points at 0.1 and 0.2.
  HardeningSpec table;
  table.law = HardeningLaw::kTable;
  table.table_strain = {0.0, 0.1, 0.2, 0.4};
  table.table_stress_MPa = {100.0, 500.0 * std::pow(0.1, 0.25), 500.0 * std::pow(0.2, 0.25),
                            500.0 * std::pow(0.4, 0.25)};
  EXPECT_NEAR(hardening_exponent(table), 0.25, 1e-12);
  HardeningSpec hollomon;
  hollomon.law = HardeningLaw::kHollomon;
  hollomon.n = 0.31;
  EXPECT_EQ(hardening_exponent(hollomon), 0.31);
}

TEST(FormingLimit, ThickBlankIsAnExtrapolationWithAWarning) {
  const FormingLimitCurve flc = forming_limit_curve(keeler_scene(0.2, 4.0));
  ASSERT_EQ(flc.warnings.size(), 1u);
  EXPECT_NE(flc.warnings[0].find("up to 3 mm"), std::string::npos) << flc.warnings[0];
}

TEST(FormingLimit, TableIsLinearAndConstantBeyondItsEnds) {
  Scene s;
  s.forming_limit.model = FormingLimitModel::kTable;
  s.forming_limit.table_minor = {-0.3, 0.0, 0.2};
  s.forming_limit.table_major = {0.6, 0.3, 0.4};
  const FormingLimitCurve flc = forming_limit_curve(s);
  EXPECT_DOUBLE_EQ(flc.major_limit(-0.15), 0.45);
  EXPECT_DOUBLE_EQ(flc.major_limit(0.0), 0.3);
  EXPECT_DOUBLE_EQ(flc.major_limit(0.1), 0.35);
  EXPECT_DOUBLE_EQ(flc.major_limit(-0.9), 0.6);
  EXPECT_DOUBLE_EQ(flc.major_limit(0.7), 0.4);
  EXPECT_NE(flc.description().find("table: 3 points"), std::string::npos);
}

TEST(FormingLimit, MarginsAndZones) {
  Scene s;
  s.forming_limit.model = FormingLimitModel::kTable;
  s.forming_limit.table_minor = {-0.5, 0.5};
  s.forming_limit.table_major = {0.3, 0.3};
  s.forming_limit.safety_margin = 0.1;
  const FormingLimitCurve flc = forming_limit_curve(s);
  const FormingMargin safe = forming_margin(flc, 0.15, 0.0);
  EXPECT_DOUBLE_EQ(safe.margin, 0.15);
  EXPECT_EQ(safe.zone, FormingZone::kSafe);
  EXPECT_EQ(forming_margin(flc, 0.25, 0.1).zone, FormingZone::kMarginal);
  EXPECT_EQ(forming_margin(flc, 0.3, 0.1).zone, FormingZone::kMarginal);  // on the curve
  EXPECT_EQ(forming_margin(flc, 0.31, 0.1).zone, FormingZone::kFailed);
  EXPECT_EQ(forming_margin(FormingLimitCurve{}, 0.31, 0.1).zone, FormingZone::kUnknown);
  EXPECT_STREQ(forming_zone_name(FormingZone::kFailed), "failed");
}

TEST(FormingLimit, PolylineFollowsTheCurveAndItsMargin) {
  const FormingLimitCurve flc = forming_limit_curve(keeler_scene(0.2, 1.0));
  const FlcPolyline line = flc_polyline(flc, -0.3, 0.4, 0.1);
  ASSERT_GE(line.minor.size(), 20u);
  EXPECT_EQ(line.minor.front(), -0.3);
  EXPECT_EQ(line.minor.back(), 0.4);
  bool has_plane_strain = false;
  for (std::size_t k = 0; k < line.minor.size(); ++k) {
    EXPECT_DOUBLE_EQ(line.major[k], flc.major_limit(line.minor[k]) - 0.1);
    has_plane_strain = has_plane_strain || line.minor[k] == 0.0;
    if (k > 0) {
      EXPECT_GT(line.minor[k], line.minor[k - 1]);
    }
  }
  EXPECT_TRUE(has_plane_strain);
  EXPECT_TRUE(flc_polyline(FormingLimitCurve{}, -0.3, 0.4, 0.0).minor.empty());
}

TEST(FormingLimit, PointsFigureAndSummaryUseTheCurve) {
  Scene s;
  s.forming_limit.model = FormingLimitModel::kTable;
  s.forming_limit.table_minor = {-0.5, 0.5};
  s.forming_limit.table_major = {0.12, 0.12};  // the test data reach major 0.2 at 2 mm
  const RunResult r = test::completed_result();
  std::vector<FldPoint> points = fld_points(r);
  apply_forming_limit(forming_limit_curve(s), &points);
  const FldPoint* least = least_margin_point(points);
  ASSERT_NE(least, nullptr);
  EXPECT_EQ(least->element, 1u);  // eps_major 0.2 (2 x 0.05 x 2 mm)
  EXPECT_DOUBLE_EQ(least->flc_margin, 0.12 - 0.2);
  EXPECT_EQ(least->zone, FormingZone::kFailed);
  EXPECT_NE(fld_points_csv(points).find(",failed\n"), std::string::npos);

  const SvgFigure f = fld_figure(s, r, {}, forming_limit_curve(s));
  ASSERT_EQ(f.series.size(), 3u);  // points, FLC, FLC - margin
  EXPECT_EQ(f.series[1].label, "FLC (table)");
  EXPECT_DOUBLE_EQ(f.series[1].y.front(), 0.12);
  EXPECT_TRUE(f.series[2].dashed);
  EXPECT_DOUBLE_EQ(f.series[2].y.front(), 0.12 - 0.1);

  const RunSummary summary = summarize_run(s, r);
  EXPECT_DOUBLE_EQ(summary.flc_min_margin, 0.12 - 0.2);
  EXPECT_EQ(summary.flc_min_zone, "failed");
  EXPECT_EQ(summary.flc_min_element, 1);
  EXPECT_DOUBLE_EQ(summary.flc_min_r0_mm, 15.0);
  const std::string report = summary_report(summary);
  EXPECT_NE(report.find("FLC margin        -0.0800 (failed) at element 1, r0 15.000 mm"),
            std::string::npos)
      << report;
  // Thinning of the thinnest element: 0.88 mm of the 1 mm default blank.
  EXPECT_NEAR(summary.final_thinning_percent, 12.0, 1e-12);
  EXPECT_NE(report.find("(thinning 12.0 %) at r0"), std::string::npos) << report;
}

TEST(FormingLimit, NoCurveNoMargins) {
  Scene s;
  s.forming_limit.model = FormingLimitModel::kNone;
  const RunResult r = test::completed_result();
  const RunSummary summary = summarize_run(s, r);
  EXPECT_EQ(summary.flc_description, "none");
  EXPECT_TRUE(std::isnan(summary.flc_min_margin));
  EXPECT_EQ(summary_report(summary).find("FLC"), std::string::npos);
  EXPECT_EQ(fld_figure(s, r, {}, forming_limit_curve(s)).series.size(), 1u);
}

}  // namespace
}  // namespace vs
