#include "measurement.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "inverse_test_support.h"

namespace vs {
namespace {

using namespace vs::testing;

std::string error_of(const fs::path& path, MeasurementKind kind) {
  try {
    read_measurement_csv(path.string(), kind);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

constexpr const char* kHeader = "# source: bench test 12\n# units: mm, kN\n";

TEST(Measurement, ReadsLoadCurveInKilonewtonsWithSigma) {
  const fs::path dir = scratch_dir();
  write_file(dir / "load.csv", std::string(kHeader) +
                                   "# lubricant: none\n"
                                   "punch_travel_mm, punch_force_kN, sigma\n"
                                   "1.0, 2.5, 0.1\n\n2.0,3.5,0.1\n");
  const Measurement m =
      read_measurement_csv((dir / "load.csv").string(), MeasurementKind::kLoadTravel);
  ASSERT_EQ(m.x.size(), 2u);
  EXPECT_DOUBLE_EQ(m.y[1], 3500.0);
  EXPECT_DOUBLE_EQ(m.point_sigma[0], 100.0);
  ASSERT_EQ(m.provenance.size(), 3u);
  EXPECT_EQ(m.provenance[2].first, "lubricant");
}

TEST(Measurement, ReadsProfileColumnsInAnyOrder) {
  const fs::path dir = scratch_dir();
  write_file(dir / "t.csv", "# source: s\n# units: mm, 1\neps_thickness,r0_mm\n-0.1,0\n-0.2,5\n");
  const Measurement m =
      read_measurement_csv((dir / "t.csv").string(), MeasurementKind::kThicknessStrain);
  EXPECT_DOUBLE_EQ(m.x[1], 5.0);
  EXPECT_DOUBLE_EQ(m.y[1], -0.2);
}

TEST(Measurement, RejectsBadFiles) {
  const fs::path dir = scratch_dir();
  const std::string h = kHeader;
  struct Case {
    const char* name;
    std::string text;
    const char* expected;
  };
  const Case cases[] = {
      {"empty", "", "provenance"},
      {"header_only", h + "punch_travel_mm,punch_force_N\n", "no data rows"},
      {"non_numeric", h + "punch_travel_mm,punch_force_N\n1,2\n2,abc\n", "bad.csv:5: 'abc'"},
      {"trailing_junk", h + "punch_travel_mm,punch_force_N\n1,2x\n", "is not a number"},
      {"non_finite", h + "punch_travel_mm,punch_force_N\n1,inf\n", "not finite"},
      {"nan", h + "punch_travel_mm,punch_force_N\n1,nan\n", "not finite"},
      {"non_monotone", h + "punch_travel_mm,punch_force_N\n1,2\n3,4\n2,5\n",
       "bad.csv:6: punch_travel_mm = 2 does not increase"},
      {"repeated_x", h + "punch_travel_mm,punch_force_N\n1,2\n1,4\n", "does not increase"},
      {"missing_units", "# source: x\npunch_travel_mm,punch_force_N\n1,2\n", "# units:"},
      {"missing_source", "# units: mm, N\npunch_travel_mm,punch_force_N\n1,2\n", "# source:"},
      {"unknown_column", h + "punch_travel_mm,punch_force_lbf\n1,2\n",
       "unknown or repeated column"},
      {"missing_column", h + "punch_travel_mm\n1\n", "needs columns"},
      {"wrong_count", h + "punch_travel_mm,punch_force_N\n1,2,3\n", "expected 2"},
      {"bad_sigma", h + "punch_travel_mm,punch_force_N,sigma\n1,2,0\n", "sigma must be > 0"},
  };
  for (const auto& c : cases) {
    write_file(dir / "bad.csv", c.text);
    const std::string error = error_of(dir / "bad.csv", MeasurementKind::kLoadTravel);
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.name << ": " << error;
  }
  EXPECT_NE(error_of(dir / "missing.csv", MeasurementKind::kLoadTravel).find("cannot open"),
            std::string::npos);
}

TEST(Measurement, WriteThenReadGivesTheSameNumbers) {
  const fs::path dir = scratch_dir();
  Measurement m;
  m.kind = MeasurementKind::kCircumferentialStrain;
  m.x = {0.0, 1.0 / 3.0, 2.0};
  m.y = {0.1, -1e-7, 0.3};
  m.point_sigma = {0.01, 0.01, 0.02};
  m.provenance = {{"source", "test"}, {"units", "mm, 1"}};
  write_measurement_csv(m, (dir / "m.csv").string());
  const Measurement back = read_measurement_csv((dir / "m.csv").string(), m.kind);
  EXPECT_EQ(back.x, m.x);
  EXPECT_EQ(back.y, m.y);
  EXPECT_EQ(back.point_sigma, m.point_sigma);
}

}  // namespace
}  // namespace vs
