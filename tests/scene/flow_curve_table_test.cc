// Hardening law "table": inline tables, CSV files (relative to the scene) and their errors.
#include "scene/flow_curve_table.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kMinimalScene;
using testing::scene_error;
using testing::write_scratch;

const std::string kTableLaw = "[material.hardening]\nlaw = \"table\"\n";  // lines 10-11

TEST(FlowCurveTable, InlineTable) {
  const Scene scene = load_scene(write_scratch(
      "scene.toml",
      kMinimalScene + kTableLaw + "table = [[0, 200], [0.1, 300.5]]\ntable_scale = 1.1\n"));
  const HardeningSpec& h = scene.material.hardening;
  EXPECT_EQ(h.law, HardeningLaw::kTable);
  EXPECT_EQ(h.table_strain, (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(h.table_stress_MPa, (std::vector<double>{200.0, 300.5}));
  EXPECT_EQ(h.table_scale, 1.1);
}

TEST(FlowCurveTable, InlineTableErrors) {
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table = [[0, 200], [0.2, 250], [0.1, 300]]\n"),
            "scene.toml:12:32: material.hardening.table[2]: plastic strain 0.1 does not increase "
            "(previous 0.2)");
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table = [[0.01, 200], [0.2, 250]]\n"),
            "scene.toml:12:10: material.hardening.table[0]: the first plastic strain must be 0, "
            "got 0.01");
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table = [[0, 200], [0.2, 0]]\n"),
            "scene.toml:12:20: material.hardening.table[1]: stress 0 MPa must be > 0");
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table = [[0, 200]]\n"),
            "scene.toml:12:9: material.hardening.table: a flow curve needs at least 2 points, "
            "got 1");
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table = [[0, 200, 3]]\n"),
            "scene.toml:12:10: material.hardening.table[0]: expected a pair [strain, stress_MPa]");
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw),
            "scene.toml:11:7: hardening law 'table' needs material.hardening.table or "
            "material.hardening.table_file");
  EXPECT_EQ(
      scene_error(kMinimalScene + kTableLaw + "table = [[0, 1], [1, 2]]\ntable_file = \"c.csv\"\n"),
      "scene.toml:13:14: give material.hardening.table or material.hardening.table_file, "
      "not both");
}

TEST(FlowCurveTable, CsvFileRelativeToTheScene) {
  write_scratch("curve.csv",
                "# AK steel, digitised\n"
                "# units: -, MPa\n"
                "plastic_strain, stress_MPa\n"
                "0,170\n"
                "0.05, 320.5\r\n"
                "\n"
                "0.3,450\n");
  const Scene scene = load_scene(
      write_scratch("scene.toml", kMinimalScene + kTableLaw + "table_file = \"curve.csv\"\n"));
  EXPECT_EQ(scene.material.hardening.table_strain, (std::vector<double>{0.0, 0.05, 0.3}));
  EXPECT_EQ(scene.material.hardening.table_stress_MPa, (std::vector<double>{170, 320.5, 450}));
}

TEST(FlowCurveTable, MalformedCsvNamesFileAndLine) {
  const std::string scene = kMinimalScene + kTableLaw + "table_file = \"curve.csv\"\n";
  const auto error_for = [&scene](const std::string& csv) {
    write_scratch("curve.csv", csv);
    return scene_error(scene);
  };
  EXPECT_EQ(error_for("# c\nstrain,stress\n0,1\n"),
            "curve.csv:2: expected the header 'plastic_strain,stress_MPa', got 'strain,stress'");
  EXPECT_EQ(error_for("plastic_strain,stress_MPa\n0,100\n0.1,abc\n"),
            "curve.csv:3: '0.1,abc' is not a pair of numbers");
  EXPECT_EQ(error_for("plastic_strain,stress_MPa\n0,100\n0.1,200,3\n"),
            "curve.csv:3: expected 2 comma-separated values, got '0.1,200,3'");
  EXPECT_EQ(error_for("plastic_strain,stress_MPa\n0,100\n# gap\n0,200\n"),
            "curve.csv:4: plastic strain 0 does not increase (previous 0)");
  EXPECT_EQ(error_for("plastic_strain,stress_MPa\n0,100\n0.1,-5\n"),
            "curve.csv:3: stress -5 MPa must be > 0");
  EXPECT_EQ(error_for("plastic_strain,stress_MPa\n0,100\n"),
            "curve.csv:2: a flow curve needs at least 2 points, got 1");
  EXPECT_EQ(error_for("# only comments\n"),
            "curve.csv:1: no header 'plastic_strain,stress_MPa' found");
  // At most kMaxFlowCurvePoints (the curve must fit inline in the scene.toml of a run folder).
  std::string many = "plastic_strain,stress_MPa\n";
  for (std::size_t i = 0; i <= kMaxFlowCurvePoints; ++i) many += fmt::format("{},{}\n", i, 100 + i);
  EXPECT_EQ(error_for(many),
            fmt::format("curve.csv:{}: a flow curve may have at most {} points, "
                        "got {}",
                        kMaxFlowCurvePoints + 2, kMaxFlowCurvePoints, kMaxFlowCurvePoints + 1));
}

TEST(FlowCurveTable, MissingCsvIsReportedAtTheSceneKey) {
  EXPECT_EQ(scene_error(kMinimalScene + kTableLaw + "table_file = \"nope.csv\"\n"),
            "scene.toml:12:14: material.hardening.table_file: cannot open table file 'nope.csv'");
}

}  // namespace
}  // namespace vs
