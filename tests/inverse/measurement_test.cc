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
  const std::string h = "# source: bench test 12\n# units: mm, N\n";
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
       "bad.csv:3: unknown column 'punch_force_lbf' for load_travel data"},
      {"repeated_column", h + "punch_travel_mm,punch_force_N,punch_force_N\n1,2,3\n",
       "bad.csv:3: repeated column 'punch_force_N'"},
      {"units_mismatch", std::string(kHeader) + "punch_travel_mm,punch_force_N\n1,2\n",
       "bad.csv:2: units 'mm, kN' do not match the columns: the abscissa is in mm and "
       "punch_force_N in N"},
      {"units_unknown", "# source: x\n# units: inch, lbf\npunch_travel_mm,punch_force_N\n1,2\n",
       "bad.csv:2: unknown unit 'inch' on the units line (known: mm, N, kN, 1, -, MPa, s, mm/s, "
       "deg)"},
      {"units_free_text", "# source: x\n# units: whatever\npunch_travel_mm,punch_force_N\n1,2\n",
       "unknown unit 'whatever'"},
      {"tab_separated", h + "punch_travel_mm\tpunch_force_N\n1\t2\n",
       "bad.csv:3: unknown column 'punch_travel_mm<U+0009 TAB>punch_force_N' (it contains U+0009 "
       "TAB)"},
      {"no_break_space", h + "punch_travel_mm,punch_force_N\xC2\xA0\n1,2\n",
       "(it contains U+00A0 NO-BREAK SPACE)"},
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

TEST(Measurement, ByteOrderMarkAndTabsAroundTheHeaderAreHarmless) {
  const fs::path dir = scratch_dir();
  write_file(dir / "bom.csv",
             "\xEF\xBB\xBF# source: s\n# units: mm, N\n\tpunch_travel_mm,punch_force_N\t\n"
             "1,2\n2,3\n");
  EXPECT_EQ(read_measurement_csv((dir / "bom.csv").string(), MeasurementKind::kLoadTravel).y[1],
            3.0);
  write_file(dir / "bom_header.csv", "\xEF\xBB\xBFpunch_travel_mm,punch_force_N\n1,2\n");
  EXPECT_NE(error_of(dir / "bom_header.csv", MeasurementKind::kLoadTravel).find("# source:"),
            std::string::npos);  // the header is recognised; only the provenance is missing
}

// vshell's own output files, written by `vshell run`, read back as measurements.
TEST(Measurement, ReadsVshellOutputFilesAsWritten) {
  const fs::path dir = scratch_dir();
  write_file(dir / "load_travel.csv",
             "step,time_s,punch_travel_mm,punch_force_N,iterations,residual_norm,update_norm,"
             "contact_nodes,cutbacks,min_thickness_mm,thinnest_r0_mm,thinnest_r_mm,volume_mm3,"
             "rim_draw_in_mm\n"
             "0,0,0,200.278246,8,2.4e-12,1.3e-13,1,0,0.85,0.5918,0.5918,9352.30626,0\n"
             "1,0.02959,0.02959,202.364123,3,7.4e-10,4.6e-10,1,0,0.849995318,0.5918,0.5918,"
             "9352.30626,0\n");
  const Measurement load =
      read_measurement_csv((dir / "load_travel.csv").string(), MeasurementKind::kLoadTravel);
  ASSERT_EQ(load.x.size(), 2u);
  EXPECT_EQ(load.x[1], 0.02959);
  EXPECT_EQ(load.y[1], 202.364123);
  write_file(dir / "strains_travel_010.00mm.csv",  // with thinning_percent (since Nov 2026)
             "# punch_travel_mm=10\n"
             "r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,"
             "thinning_percent,eps_effective,contact\n"
             "0.5,0.6,10,0.8,0.05,0.04,-0.09,8.6,0.09,1\n"
             "1.5,1.7,9.9,0.81,0.05,0.03,-0.08,7.7,0.08,1\n");
  const Measurement thick = read_measurement_csv((dir / "strains_travel_010.00mm.csv").string(),
                                                 MeasurementKind::kThicknessStrain);
  EXPECT_EQ(thick.travel_mm, 10.0);
  EXPECT_EQ(thick.y[1], -0.08);
  const Measurement circ = read_measurement_csv((dir / "strains_travel_010.00mm.csv").string(),
                                                MeasurementKind::kCircumferentialStrain);
  EXPECT_EQ(circ.y[1], 0.03);
  write_file(dir / "strains_travel_010.00mm_x.csv",  // a 3D run's profile along one line
             "# punch_travel_mm=10, line=x\n"
             "r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,"
             "eps_effective,contact\n"
             "0.5,0.6,10,0.8,0.05,0.04,-0.09,0.09,1\n1.5,1.7,9.9,0.81,0.05,0.03,-0.08,0.08,1\n");
  EXPECT_EQ(read_measurement_csv((dir / "strains_travel_010.00mm_x.csv").string(),
                                 MeasurementKind::kThicknessStrain)
                .travel_mm,
            10.0);
}

TEST(Measurement, ColumnMappingRenamesAndIgnoresTheRest) {
  const fs::path dir = scratch_dir();
  write_file(
      dir / "lab.csv",
      "# source: lab\n# units: mm, kN\nTime,Travel,Force,Temp\n0.1,1,2.5,20\n0.2,2,3.5,21\n");
  const Measurement m =
      read_measurement_csv((dir / "lab.csv").string(), MeasurementKind::kLoadTravel,
                           {{"punch_travel_mm", "Travel"}, {"punch_force_kN", "Force"}});
  EXPECT_EQ(m.x[1], 2.0);
  EXPECT_EQ(m.y[1], 3500.0);
  try {
    read_measurement_csv((dir / "lab.csv").string(), MeasurementKind::kLoadTravel,
                         {{"punch_travel_mm", "Travel"}, {"punch_force_kN", "Forse"}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lab.csv:3: data.columns maps punch_force_kN to 'Forse', "
                                         "which is not in the header (Time, Travel, Force, Temp)"),
              std::string::npos)
        << e.what();
  }
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
