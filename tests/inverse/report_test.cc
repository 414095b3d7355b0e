#include "report.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "calibrate.h"
#include "inverse_test_support.h"

namespace vs {
namespace {

using namespace vs::testing;

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool has_null(const nlohmann::json& j) {
  if (j.is_null()) return true;
  for (const auto& item : j) {
    if ((item.is_structured() || item.is_null()) && has_null(item)) return true;
  }
  return false;
}

TEST(Report, WritesJsonEvaluationsFitsAndPlots) {
  const fs::path dir = scratch_dir();
  write_scene(dir);
  write_file(dir / "load.csv",
             "# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n5,3000\n10,6000\n"
             "15,8500\n20,10000\n");
  write_file(dir / "calibrate.toml", R"(scene = "scene.toml"
[[parameter]]
address = "material.hardening.K_MPa"
lower = 10
upper = 5000
[[parameter]]
address = "tool.die.friction"
lower = 0
upper = 1
[[data]]
kind = "load_travel"
file = "load.csv"
sigma = 100
)");
  const auto config = load_calibration_config((dir / "calibrate.toml").string());
  CalibrationOptions options;
  options.output_directory = (dir / "out").string();
  const auto result = calibrate(config, options, StretchingFake{});

  const auto json = nlohmann::json::parse(read_all(dir / "out" / "calibration.json"));
  EXPECT_EQ(json["parameters"].size(), 2u);
  EXPECT_EQ(json["parameters"][0]["address"], "material.hardening.K_MPa");
  EXPECT_EQ(json["parameters"][0]["unit"], "MPa");
  // Die friction: not determined, so no standard error (never null: no nulls anywhere).
  EXPECT_FALSE(json["parameters"][1].contains("std_error"));
  EXPECT_FALSE(has_null(json));
  EXPECT_EQ(json["uncertainty"]["matrix_parameters"],
            nlohmann::json::array({"material.hardening.K_MPa"}));
  EXPECT_FALSE(json["parameters"][1]["determined"].get<bool>());
  EXPECT_FALSE(json["uncertainty"]["statements"].empty());
  EXPECT_EQ(json["forward_runs"], result.forward_runs);
  EXPECT_EQ(json["data_sets"][0]["name"], "load");
  EXPECT_EQ(json["termination"], to_string(result.termination));

  const std::string log = read_all(dir / "out" / "evaluations.csv");
  EXPECT_EQ(log.rfind("index,status,cost,wall_time_s,material.hardening.K_MPa,tool.die.friction,"
                      "message\n",
                      0),
            0u);
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'),
            static_cast<long>(result.evaluations.size()) + 1);
  const std::string fit = read_all(dir / "out" / "fit_load.csv");
  EXPECT_NE(fit.find("punch_travel_mm,punch_force_N_measured,punch_force_N_simulated"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "fit_load.svg"));
  EXPECT_TRUE(fs::exists(dir / "out" / "cost.svg"));
  EXPECT_NE(result.brief_report().find("poorly determined"), std::string::npos);
}

}  // namespace
}  // namespace vs
