// One writer for both geometries (issue 13): an axisymmetric and a 3D run write the same file
// names, the same CSV header columns and the same run.json keys; only the 3D run adds its
// ParaView series and names its profiles after the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "forming_util.h"
#include "output/run_writer.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

// The header line of a CSV (the first line not starting with '#').
std::string header(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') return line;
  }
  return "";
}

std::set<std::string> json_keys(const fs::path& file) {
  std::ifstream in(file);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::set<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.insert(key);
  return keys;
}

fs::path write(const Scene& scene, const std::string& name, RunResult* result) {
  *result = simulate(scene);
  EXPECT_TRUE(result->completed()) << result->message;
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_run_folder(scene, *result, dir.string());
  return dir;
}

TEST(RunFolder, BothGeometriesWriteTheSameFilesAndColumns) {
  RunResult axi, shell;
  const fs::path a = write(test::load_with("ex1_hemispherical_stretching.toml",
                                           {{"blank.elements", "12"},
                                            {"process.punch_travel_mm", "2"},
                                            {"process.output_travels_mm", "[1, 2]"}}),
                           "vs_run_folder_axisym", &axi);
  const fs::path s = write(test::load_with("ex4a_quarter_disc_sticking.toml",
                                           {{"blank.divisions", "1"},
                                            {"tool.punch.friction", "0.1"},
                                            {"process.punch_travel_mm", "2"},
                                            {"process.output_travels_mm", "[1, 2]"},
                                            {"numerics.max_travel_increment_per_length", "1"}}),
                           "vs_run_folder_shell3d", &shell);
  EXPECT_EQ(axi.geometry, Geometry::kAxisymmetric);
  EXPECT_EQ(shell.geometry, Geometry::kShell3d);
  for (const char* f : {"load_travel.csv", "thinnest_point.csv", "fld_points.csv",
                        "strain_paths.csv", "run.json", "load_travel.svg", "thickness_strain.svg",
                        "strains.svg", "deformed_stages.svg", "fld.svg"}) {
    EXPECT_TRUE(fs::exists(a / f)) << "axisymmetric " << f;
    EXPECT_TRUE(fs::exists(s / f)) << "3D " << f;
  }
  for (const char* f :
       {"load_travel.csv", "thinnest_point.csv", "fld_points.csv", "strain_paths.csv"}) {
    EXPECT_EQ(header(a / f), header(s / f)) << f;
  }
  // Profiles: the meridian in one geometry, the lines x, y, diagonal in the other, same columns.
  for (const char* travel : {"001.00", "002.00"}) {
    const fs::path meridian = a / (std::string("strains_travel_") + travel + "mm.csv");
    ASSERT_TRUE(fs::exists(meridian)) << meridian;
    for (const char* line : {"x", "y", "diagonal"}) {
      const fs::path p = s / (std::string("strains_travel_") + travel + "mm_" + line + ".csv");
      ASSERT_TRUE(fs::exists(p)) << p;
      EXPECT_EQ(header(p), header(meridian)) << p;
    }
  }
  // Only the 3D run has the ParaView series.
  EXPECT_TRUE(fs::exists(s / "stages.pvd"));
  EXPECT_TRUE(fs::exists(s / "stage_0.vtu"));
  EXPECT_FALSE(fs::exists(a / "stages.pvd"));
  EXPECT_EQ(json_keys(a / "run.json"), json_keys(s / "run.json"));
}

}  // namespace
}  // namespace vs
