// Run-level forming outputs (issue 16): the forming-limit margin, thinning and the thinnest
// point's full position in run.json and the summary; the 3D ParaView series from zero travel
// with stresses and margins; the noise-like load curve warning. Each run takes well under a
// second.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "forming_util.h"
#include "output/run_summary.h"
#include "output/run_writer.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path write(const Scene& scene, const RunResult& result, const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_run_folder(scene, result, dir.string());
  return dir;
}

// The values of a VTU DataArray, or empty when the file has none of that name.
std::vector<double> vtu_values(const std::string& vtu, const std::string& name) {
  std::vector<double> values;
  const std::size_t at = vtu.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return values;
  const std::size_t begin = vtu.find('>', at) + 1;
  std::istringstream in(vtu.substr(begin, vtu.find("</DataArray>", begin) - begin));
  for (double v; in >> v;) values.push_back(v);
  return values;
}

// scene.toml is the scene as run: run again from the folder, it gives the same files to the bit
// (both geometries; the 3D scene with its geometry defaults, the axisymmetric one with --set
// style edits that the echo must carry). run.json's scene record names the same values.
TEST(FormingOutputs, SceneTomlRunsAgainToTheSameBits) {
  struct Case {
    const char* scene;
    std::vector<std::pair<std::string, std::string>> edits;
  };
  for (const Case& c : {Case{"ex1_hemispherical_stretching.toml",
                             {{"process.punch_travel_mm", "4"},
                              {"process.output_travels_mm", "[2.0, 4.0]"},
                              {"tool.punch.friction", "0.13"},
                              {"material.hardening.n", "0.2"}}},
                        Case{"ex4a_quarter_disc_sticking.toml",
                             {{"blank.divisions", "4"},
                              {"process.punch_travel_mm", "2"},
                              {"process.output_travels_mm", "[2.0]"}}}}) {
    SCOPED_TRACE(c.scene);
    const Scene scene = test::load_with(c.scene, c.edits);
    const RunResult first = simulate(scene);
    ASSERT_TRUE(first.completed()) << first.message;
    const fs::path one = write(scene, first, "echo_first");
    const Scene again = load_scene((one / "scene.toml").string());
    const RunResult second = simulate(again);
    ASSERT_TRUE(second.completed()) << second.message;
    const fs::path two = write(again, second, "echo_second");
    for (const char* file : {"load_travel.csv", "fld_points.csv", "thinnest_point.csv"}) {
      EXPECT_EQ(read(two / file), read(one / file)) << file;
    }
    const auto j = nlohmann::json::parse(read(one / "run.json"));
    EXPECT_EQ(j["scene"]["process"]["punch_travel_mm"], scene.process.punch_travel_mm);
    EXPECT_EQ(j["scene"]["numerics"]["start_refinement"], scene.numerics.start_refinement);
    if (scene.tools.at(0).sticking()) {
      EXPECT_EQ(j["scene"]["tools"][0]["friction"], "sticking");
    } else {
      EXPECT_EQ(j["scene"]["tools"][0]["friction"], scene.tools.at(0).friction);
    }
  }
}

TEST(FormingOutputs, ShellSeriesStartsAtZeroTravelWithStressesAndMargins) {
  const Scene scene = test::load_with("ex4a_quarter_disc_sticking.toml",
                                      {{"blank.divisions", "1"},
                                       {"tool.punch.friction", "0.1"},
                                       {"process.punch_travel_mm", "2"},
                                       {"process.output_travels_mm", "[1]"},
                                       {"numerics.max_travel_increment_per_length", "1"}});
  const RunResult r = simulate(scene);
  ASSERT_TRUE(r.completed()) << r.message;
  ASSERT_TRUE(r.shell);
  EXPECT_EQ(r.shell->initial.punch_travel_mm, 0.0);
  const fs::path dir = write(scene, r, "vs_forming_outputs_3d");
  const std::string pvd = read(dir / "stages.pvd");
  EXPECT_NE(pvd.find("timestep=\"0\""), std::string::npos) << pvd;
  const std::string stage0 = read(dir / "stage_0.vtu");
  const std::string last = read(dir / "stage_2.vtu");
  // Zero travel: the initial blank, no thinning.
  for (double d : vtu_values(stage0, "displacement_mm")) EXPECT_NEAR(d, 0.0, 1e-9);
  for (double t : vtu_values(stage0, "thinning_percent")) EXPECT_NEAR(t, 0.0, 1e-9);
  // Stresses per element, in MPa: at 2 mm the sheet over the punch flows, at most at the flow
  // stress of its strain (Swift 589 (0.0017 + eps)^0.216 < 589 MPa for eps < 1; the rate cut-off
  // only lowers it).
  const std::vector<double> stress = vtu_values(last, "effective_stress_MPa");
  ASSERT_EQ(stress.size(), r.shell->mesh.elements.size());
  double largest = 0.0;
  for (double s : stress) {
    EXPECT_GE(s, 0.0);
    largest = std::max(largest, s);
  }
  EXPECT_GT(largest, 100.0);
  EXPECT_LT(largest, 589.0);
  EXPECT_EQ(vtu_values(stage0, "effective_stress_MPa").size(), stress.size());
  // Margins: the default Keeler-Brazier curve, all safe this early.
  const std::vector<double> zone = vtu_values(last, "flc_zone");
  ASSERT_EQ(zone.size(), stress.size());
  for (double z : zone) EXPECT_EQ(z, 0.0);
  EXPECT_EQ(vtu_values(last, "flc_margin").size(), stress.size());

  // run.json and the summary name the thinnest point by x0 and y0, and the smallest margin.
  std::ifstream in(dir / "run.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const double x0 = j["final_thinnest_x0_mm"], y0 = j["final_thinnest_y0_mm"];
  EXPECT_NEAR(std::hypot(x0, y0), j["final_thinnest_r0_mm"].get<double>(), 1e-9);
  EXPECT_GT(j["forming_limit"]["smallest_margin"].get<double>(), 0.1);
  EXPECT_EQ(j["forming_limit"]["zone"], "safe");
  EXPECT_NEAR(j["final_thinning_percent"].get<double>(),
              100.0 * (1.0 - j["final_min_thickness_mm"].get<double>() / 0.85), 1e-9);
  const std::string report = summary_report(summarize_run(scene, r));
  EXPECT_NE(report.find(fmt::format("x0 {:.3f} mm, y0 {:.3f} mm", x0, y0)), std::string::npos)
      << report;
  EXPECT_NE(report.find("FLC margin"), std::string::npos) << report;
}

TEST(FormingOutputs, NoiseLikeLoadCurveIsWarned) {
  // A sheet 1e-4 times the punch radius thick: the load curve is noise (83 reversals in 137
  // steps at 8 mm, 678 in 1104 at the full 30 mm); the same run at 0.85 mm is smooth. The noise
  // is the explicit (Heun) update's, so the run asks for it: the implicit update at 0.25 element
  // lengths gives the thin sheet a smooth curve (0 reversals in 35 steps at 8 mm).
  for (const char* thickness : {"0.00508", "0.85"}) {
    const Scene scene = test::load_with("ex1_hemispherical_stretching.toml",
                                        {{"blank.thickness_mm", thickness},
                                         {"numerics.time_integration", "heun"},
                                         {"numerics.max_travel_increment_per_length", "0.025"},
                                         {"blank.elements", "24"},
                                         {"process.punch_travel_mm", "8"},
                                         {"process.output_travels_mm", "[4]"}});
    const RunResult r = simulate(scene);
    ASSERT_TRUE(r.completed()) << r.message;
    const fs::path dir = write(scene, r, "vs_forming_outputs_noise");
    std::ifstream in(dir / "run.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    const bool thin = std::string(thickness) == "0.00508";
    EXPECT_EQ(j["load_curve"]["noise_like"].get<bool>(), thin) << j["load_curve"];
    bool warned = false;
    for (const auto& w : j["warnings"]) {
      warned = warned || w.get<std::string>().find("noise-like") != std::string::npos;
    }
    EXPECT_EQ(warned, thin) << j["warnings"];
    // Thinning beside the thickness strain in the profiles.
    const std::string profile = read(dir / "strains_travel_004.00mm.csv");
    EXPECT_NE(profile.find(",eps_thickness,thinning_percent,"), std::string::npos);
  }
}

}  // namespace
}  // namespace vs
