// Scene integration of the 3D forming solver: geometry-specific keys, bundled scenes, dispatch.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.h"
#include "mesh/forming_mesh.h"
#include "model/forming_model.h"
#include "output/run_writer.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"
#include "stepping/step_driver.h"

namespace vs::shell3d {
namespace {

std::string scene_path(const std::string& name) {
  return std::string(VS_SOURCE_DIR) + "/data/scenes/" + name;
}

std::string write_scene(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "vs_shell3d_scene_tests";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

const char* const kTools = R"(
[[tool]]
name = "punch"
kind = "hemispherical_punch"
radius_mm = 40.0
)";

std::string load_error(const std::string& name, const std::string& text) {
  try {
    load_scene(write_scene(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FormingScene, BundledShellScenesLoad) {
  const Scene a = load_scene(scene_path("ex4a_quarter_disc_sticking.toml"));
  EXPECT_EQ(a.geometry, Geometry::kShell3d);
  EXPECT_EQ(a.blank.shape, BlankShape::kCircle);
  EXPECT_TRUE(a.tools.at(0).sticking());
  const Scene b = load_scene(scene_path("ex4b_square_clamped.toml"));
  EXPECT_EQ(b.blank.shape, BlankShape::kSquare);
  EXPECT_EQ(b.blank.edge, EdgeCondition::kClamped);
  // Example 4a has the data of example 1 (punch, sheet, material, travel).
  const Scene ex1 = load_scene(scene_path("ex1_hemispherical_stretching.toml"));
  EXPECT_EQ(a.blank.radius_mm, ex1.blank.radius_mm);
  EXPECT_EQ(a.blank.thickness_mm, ex1.blank.thickness_mm);
  EXPECT_EQ(a.tools.at(0).radius_mm, ex1.tools.at(0).radius_mm);
  EXPECT_EQ(a.material.hardening.K_MPa, ex1.material.hardening.K_MPa);
  EXPECT_EQ(a.process.punch_travel_mm, ex1.process.punch_travel_mm);
  // The 3D deep drawing has the data of example 2 (tools, holder, sheet, material).
  const Scene d = load_scene(scene_path("ex2_quarter_disc_deep_drawing_3d.toml"));
  const Scene ex2 = load_scene(scene_path("ex2_hemispherical_deep_drawing.toml"));
  EXPECT_EQ(d.geometry, Geometry::kShell3d);
  EXPECT_EQ(d.blank.edge, EdgeCondition::kFree);
  EXPECT_EQ(d.blank.radius_mm, ex2.blank.radius_mm);
  EXPECT_EQ(d.blank.thickness_mm, ex2.blank.thickness_mm);
  EXPECT_EQ(d.material.hardening.K_MPa, ex2.material.hardening.K_MPa);
  ASSERT_EQ(d.tools.size(), ex2.tools.size());
  for (std::size_t t = 0; t < d.tools.size(); ++t) {
    EXPECT_EQ(d.tools[t].kind, ex2.tools[t].kind);
    EXPECT_EQ(d.tools[t].radius_mm, ex2.tools[t].radius_mm);
    EXPECT_EQ(d.tools[t].profile_radius_mm, ex2.tools[t].profile_radius_mm);
    EXPECT_EQ(d.tools[t].friction, ex2.tools[t].friction);
    EXPECT_EQ(d.tools[t].force_N, ex2.tools[t].force_N);
  }
}

TEST(FormingScene, GeometrySpecificKeysAreRejectedInTheOtherGeometry) {
  const std::string axi = load_error("axi.toml", "[blank]\ndivisions = 4\n" + std::string(kTools));
  EXPECT_NE(axi.find("axi.toml:2:1: key 'blank.divisions' is only used by geometry = \"shell3d\""),
            std::string::npos)
      << axi;
  const std::string rule =
      load_error("rule.toml", "[numerics]\nelement_rule = \"mitc9\"\n" + std::string(kTools));
  EXPECT_NE(rule.find("key 'numerics.element_rule' is only used by geometry = \"shell3d\""),
            std::string::npos)
      << rule;
  const std::string shell = load_error(
      "shell.toml", "geometry = \"shell3d\"\n[blank]\nelements = 20\n" + std::string(kTools));
  EXPECT_NE(shell.find("shell.toml:3:1: key 'blank.elements' is only used by geometry = "
                       "\"axisymmetric\""),
            std::string::npos)
      << shell;
  // Without geometry-specific keys both load.
  EXPECT_EQ(load_error("ok.toml", std::string("geometry = \"shell3d\"\n") + kTools), "");
  EXPECT_EQ(load_error("ok2.toml", std::string(kTools)), "");
}

// Each geometry's driver refuses the other's scenes (vs::simulate picks the right one).
TEST(FormingScene, SolversRefuseTheOtherGeometry) {
  Scene s = load_scene(scene_path("ex4a_quarter_disc_sticking.toml"));
  EXPECT_THROW(simulate_axisymmetric(s), InputError);
  const Scene axi = load_scene(scene_path("ex1_hemispherical_stretching.toml"));
  EXPECT_THROW(simulate_shell3d(axi), InputError);
}

// A die and a blank holder: the force holder and the fixed-gap holder both load in 3D (with a
// free, drawn-in edge); a holder with both or neither of force_N and gap_mm is refused.
const char* const kDieAndHolder = R"(
[blank]
edge = "free"
[[tool]]
name = "die"
kind = "die"
radius_mm = 42.0
profile_radius_mm = 4.0
[[tool]]
name = "holder"
kind = "blank_holder"
)";

TEST(FormingScene, ForceAndFixedGapBlankHoldersLoad) {
  const std::string head = std::string("geometry = \"shell3d\"\n") + kTools + kDieAndHolder;
  const std::string force_path = write_scene("holder_force.toml", head + "force_N = 1000.0\n");
  const Scene s = load_scene(force_path);
  EXPECT_EQ(s.geometry, Geometry::kShell3d);
  EXPECT_EQ(s.blank.edge, EdgeCondition::kFree);
  ASSERT_EQ(s.tools.size(), 3u);
  EXPECT_EQ(s.tools[2].force_N, 1000.0);
  FormingModel model(s);
  EXPECT_TRUE(model.has_holder());
  EXPECT_FALSE(model.fixed_gap_holder());
  EXPECT_GE(model.die_index(), 0);
  EXPECT_EQ(load_error("holder_gap.toml", head + "gap_mm = 1.04\n"), "");
  const Scene g = load_scene(write_scene("holder_gap.toml", head + "gap_mm = 1.04\n"));
  FormingModel gap_model(g);
  EXPECT_FALSE(gap_model.has_holder());
  EXPECT_TRUE(gap_model.fixed_gap_holder());
  EXPECT_EQ(gap_model.holder_gap_mm(), 1.04);
  EXPECT_EQ(gap_model.holder_index(), 2);
  // Scenes built in code past the checks: the model refuses both or neither.
  Scene both = g;
  both.tools[2].force_N = 1000.0;
  EXPECT_THROW(FormingModel{both}, InputError);
  Scene neither = g;
  neither.tools[2].gap_mm = 0.0;
  EXPECT_THROW(FormingModel{neither}, InputError);
}

TEST(FormingScene, MeshesHaveTheSymmetryAndEdgeSets) {
  Scene s = load_scene(scene_path("ex4a_quarter_disc_sticking.toml"));
  s.blank.divisions = 3;
  const ShellMesh disc = forming_mesh(s);
  EXPECT_EQ(disc.num_elements(), 27);
  EXPECT_EQ(disc.set("x0").size(), 13u);  // 2 n elements along each symmetry line, 9-node
  EXPECT_EQ(disc.set("diagonal").size(), 13u);
  EXPECT_EQ(disc.set("edge").size(), disc.set("rim").size());
  s.blank.shape = BlankShape::kSquare;
  const ShellMesh square = forming_mesh(s);
  EXPECT_EQ(square.num_elements(), 9);
  EXPECT_EQ(square.set("edge").size(), 13u);  // two edges of 7 nodes sharing the corner
  EXPECT_EQ(square.set("diagonal").size(), 7u);
}

// blank.radial_divisions m refines the ring of a circular blank: n^2 + 2 n m elements per
// quarter, 2 (n + m) elements along each symmetry line, the rim unchanged (2 n elements); the
// ring's radial node spacing on x = 0 is (r - r/2) / (2 m). The full blank is four quarters.
// Not set, it is divisions (the meshes of before); on a square blank, or out of range, an error.
TEST(FormingScene, RadialDivisionsRefineTheRingOfACircle) {
  const std::string head = "geometry = \"shell3d\"\n" + std::string(kTools) +
                           "[blank]\nradius_mm = 50.0\ndivisions = 3\n";
  const Scene plain = load_scene(write_scene("plain.toml", head));
  EXPECT_EQ(plain.blank.ring_divisions(), 3);
  EXPECT_EQ(forming_mesh(plain).num_elements(), 27);
  Scene s = load_scene(write_scene("ring.toml", head + "radial_divisions = 7\n"));
  EXPECT_EQ(s.blank.ring_divisions(), 7);
  const ShellMesh disc = forming_mesh(s);
  EXPECT_EQ(disc.num_elements(), 3 * 3 + 2 * 3 * 7);
  EXPECT_EQ(disc.set("x0").size(), 2u * (3 + 7) + 1u);
  EXPECT_EQ(disc.set("rim").size(), 2u * (2 * 3) + 1u);
  std::vector<double> y;
  for (int i : disc.set("x0")) y.push_back(disc.nodes[i].y());
  std::sort(y.begin(), y.end());
  for (std::size_t k = y.size() - 2 * 7; k + 1 < y.size(); ++k)
    EXPECT_NEAR(y[k + 1] - y[k], 25.0 / 14.0, 1e-9) << k;
  EXPECT_NEAR(y.back(), 50.0, 1e-12);
  s.blank.symmetry = BlankSymmetry::kFull;
  EXPECT_EQ(forming_mesh(s).num_elements(), 4 * (3 * 3 + 2 * 3 * 7));
  const std::string square =
      load_error("square.toml", head + "shape = \"square\"\nradial_divisions = 7\n");
  EXPECT_NE(square.find("blank.radial_divisions = 7 applies to a circular blank"),
            std::string::npos)
      << square;
  EXPECT_NE(load_error("zero.toml", head + "radial_divisions = 0\n").find("radial_divisions"),
            std::string::npos);
  const std::string axi =
      load_error("axi_ring.toml", "[blank]\nradial_divisions = 4\n" + std::string(kTools));
  EXPECT_NE(axi.find("key 'blank.radial_divisions' is only used by geometry = \"shell3d\""),
            std::string::npos)
      << axi;
}

// numerics.implicit_solves left to the model's size (the default of a shell3d scene with the
// implicit update): two velocity solves per step below kOneSolveMinUnknowns unknowns, one from
// there. The run says which (RunResult::built), and its scene.toml holds the count as run, so
// that it runs again the same. ex4a has 4 085 unknowns at 8 divisions, 29 705 at 22 and 32 435
// at 23.
TEST(FormingScene, VelocitySolvesPerStepFollowTheModelSize) {
  NumericsSpec by_size;
  by_size.implicit_solves = kImplicitSolvesBySize;
  EXPECT_EQ(implicit_solves_for(by_size, kOneSolveMinUnknowns - 1), 2);
  EXPECT_EQ(implicit_solves_for(by_size, kOneSolveMinUnknowns), 1);
  NumericsSpec given;
  for (int n : {1, 2, 3}) {
    given.implicit_solves = n;
    EXPECT_EQ(implicit_solves_for(given, 10), n);
    EXPECT_EQ(implicit_solves_for(given, 10 * kOneSolveMinUnknowns), n);
  }
  given.implicit_solves = 3;
  given.time_integration = TimeIntegration::kImplicit;
  EXPECT_EQ(time_integration_line(given, false),
            "time integration: implicit (theta 0.5), 3 velocity solves per step");
  given.time_integration = TimeIntegration::kHeun;
  EXPECT_EQ(time_integration_line(given, false).rfind("time integration: Heun", 0), 0u);
  given.time_integration = TimeIntegration::kEuler;
  EXPECT_EQ(time_integration_line(given, false).rfind("time integration: Euler", 0), 0u);

  Scene scene = load_scene(scene_path("ex4a_quarter_disc_sticking.toml"));
  ASSERT_EQ(scene.numerics.implicit_solves, kImplicitSolvesBySize);
  scene.process.punch_travel_mm = 0.02;
  scene.process.output_travels_mm = {0.02};
  scene.output.plots = false;
  for (const auto& [divisions, solves] : {std::pair{8, 2}, std::pair{23, 1}}) {
    scene.blank.divisions = divisions;
    const RunResult r = simulate(scene);
    ASSERT_TRUE(r.completed()) << r.message;
    EXPECT_EQ(r.dofs >= kOneSolveMinUnknowns, solves == 1) << r.dofs;
    EXPECT_EQ(r.implicit_solves, solves);
    EXPECT_EQ(r.implicit_solve_iterations.size(), static_cast<std::size_t>(solves));
    const std::string line = fmt::format("{} velocity solve{} per step (by the model's size",
                                         solves, solves == 1 ? "" : "s");
    EXPECT_TRUE(std::any_of(r.built.begin(), r.built.end(), [&](const std::string& b) {
      return b.rfind("time integration: implicit", 0) == 0 && b.find(line) != std::string::npos;
    })) << line;
    const auto dir = std::filesystem::temp_directory_path() / "vs_shell3d_scene_tests" /
                     fmt::format("solves_{}", divisions);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    write_run_folder(scene, r, dir.string());
    std::stringstream echo;
    echo << std::ifstream(dir / "scene.toml").rdbuf();
    EXPECT_NE(echo.str().find(fmt::format("\nimplicit_solves = {}\n", solves)), std::string::npos);
    EXPECT_EQ(load_scene((dir / "scene.toml").string()).numerics.implicit_solves, solves);
  }
}

}  // namespace
}  // namespace vs::shell3d
