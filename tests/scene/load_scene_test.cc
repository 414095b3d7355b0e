// Loading valid scenes: defaults, number conversions, sticking friction, bundled scenes and the
// annotated defaults file.
#include "scene/load_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kDie;
using testing::kMinimalScene;
using testing::write_scratch;

const std::string kScenesDir = std::string(VS_SOURCE_DIR) + "/data/scenes";

TEST(LoadScene, AppliesInClassDefaults) {
  const Scene scene = load_scene(write_scratch("scene.toml", kMinimalScene));
  const Scene defaults;
  EXPECT_EQ(scene.title, defaults.title);
  EXPECT_EQ(scene.blank.radius_mm, 59.18);
  EXPECT_EQ(scene.blank.thickness_mm, 0.85);
  EXPECT_EQ(scene.blank.elements, defaults.blank.elements);
  EXPECT_EQ(scene.blank.grading, defaults.blank.grading);
  EXPECT_EQ(scene.blank.edge, defaults.blank.edge);
  EXPECT_EQ(scene.material.r_value, defaults.material.r_value);
  const HardeningSpec& h = scene.material.hardening;
  EXPECT_EQ(h.law, defaults.material.hardening.law);
  EXPECT_EQ(h.K_MPa, defaults.material.hardening.K_MPa);
  EXPECT_EQ(h.eps0, defaults.material.hardening.eps0);
  EXPECT_EQ(h.n, defaults.material.hardening.n);
  EXPECT_EQ(scene.material.rate.law, defaults.material.rate.law);
  EXPECT_EQ(scene.process.punch_travel_mm, defaults.process.punch_travel_mm);
  EXPECT_EQ(scene.process.punch_speed_mm_per_s, defaults.process.punch_speed_mm_per_s);
  EXPECT_TRUE(scene.process.output_travels_mm.empty());
  const NumericsSpec& n = scene.numerics;
  EXPECT_EQ(n.thickness_points, defaults.numerics.thickness_points);
  EXPECT_EQ(n.solver, defaults.numerics.solver);
  EXPECT_EQ(n.tolerance, defaults.numerics.tolerance);
  EXPECT_EQ(n.max_iterations, defaults.numerics.max_iterations);
  EXPECT_EQ(n.step_fraction, defaults.numerics.step_fraction);
  EXPECT_EQ(n.max_travel_increment_mm, defaults.numerics.max_travel_increment_mm);
  EXPECT_EQ(n.max_strain_increment, defaults.numerics.max_strain_increment);
  EXPECT_EQ(n.strain_rate_cutoff, defaults.numerics.strain_rate_cutoff);
  EXPECT_EQ(n.friction_regularisation, defaults.numerics.friction_regularisation);
  EXPECT_EQ(n.max_cutbacks, defaults.numerics.max_cutbacks);
  EXPECT_EQ(scene.output.directory, defaults.output.directory);
  EXPECT_EQ(scene.output.plots, defaults.output.plots);
  EXPECT_EQ(scene.output.history, defaults.output.history);
  ASSERT_EQ(scene.tools.size(), 1u);
  EXPECT_EQ(scene.tools[0].name, "punch");
  EXPECT_EQ(scene.tools[0].kind, ToolKind::kHemisphericalPunch);
  EXPECT_EQ(scene.tools[0].radius_mm, 50.8);
  EXPECT_EQ(scene.tools[0].friction, ToolSpec{}.friction);
  EXPECT_NE(scene.source.find("scene.toml"), std::string::npos);
}

TEST(LoadScene, ReadsEveryVariantAndConvertsIntegersToFloats) {
  const Scene scene = load_scene(write_scratch(
      "scene.toml", "title = \"t\"\n" + kMinimalScene + kDie +
                        "[material]\nr_value = 2\n"
                        "[material.hardening]\nlaw = \"voce\"\nsigma0_MPa = 150\nQ_MPa = 80.5\n"
                        "b = 12\n"
                        "[material.rate]\nlaw = \"power\"\nm = 0.02\nreference_rate_per_s = 0.1\n"
                        "[process]\npunch_travel_mm = 20\noutput_travels_mm = [5, 10.5, 20]\n"
                        "[numerics]\nthickness_points = 7\nsolver = \"picard\"\nmax_cutbacks = 0\n"
                        "[output]\nplots = false\ndirectory = \"runs/a\"\n"));
  EXPECT_EQ(scene.title, "t");
  EXPECT_EQ(scene.material.r_value, 2.0);
  EXPECT_EQ(scene.material.hardening.law, HardeningLaw::kVoce);
  EXPECT_EQ(scene.material.hardening.sigma0_MPa, 150.0);
  EXPECT_EQ(scene.material.hardening.Q_MPa, 80.5);
  EXPECT_EQ(scene.material.hardening.b, 12.0);
  EXPECT_EQ(scene.material.rate.law, RateLaw::kPower);
  EXPECT_EQ(scene.material.rate.m, 0.02);
  EXPECT_EQ(scene.material.rate.reference_rate_per_s, 0.1);
  EXPECT_EQ(scene.process.punch_travel_mm, 20.0);
  EXPECT_EQ(scene.process.output_travels_mm, (std::vector<double>{5.0, 10.5, 20.0}));
  EXPECT_EQ(scene.numerics.thickness_points, 7);
  EXPECT_EQ(scene.numerics.solver, SolverKind::kPicard);
  EXPECT_EQ(scene.numerics.max_cutbacks, 0);
  EXPECT_FALSE(scene.output.plots);
  EXPECT_EQ(scene.output.directory, "runs/a");
  ASSERT_EQ(scene.tools.size(), 2u);
  EXPECT_EQ(scene.tools[1].kind, ToolKind::kDie);
  EXPECT_EQ(scene.tools[1].profile_radius_mm, 6.35);
}

TEST(LoadScene, InfiniteFrictionMeansSticking) {
  for (const std::string value : {"inf", "+inf", "\"sticking\""}) {
    const Scene scene = load_scene(
        write_scratch("scene.toml", kMinimalScene + kDie + "friction = " + value + "\n"));
    EXPECT_TRUE(scene.tools[1].sticking()) << value;
    EXPECT_FALSE(scene.tools[0].sticking()) << value;
  }
}

TEST(LoadScene, EveryBundledSceneLoads) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenesDir)) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    EXPECT_NO_THROW(load_scene(entry.path().string())) << entry.path();
  }
  EXPECT_GE(count, 3);
}

TEST(LoadScene, Example1MatchesTheGhoshHeckerGeometry) {
  const Scene s = load_scene(kScenesDir + "/ex1_hemispherical_stretching.toml");
  EXPECT_EQ(s.blank.radius_mm, 59.18);
  EXPECT_EQ(s.blank.thickness_mm, 0.85);
  EXPECT_EQ(s.blank.edge, EdgeCondition::kPinned);
  EXPECT_EQ(s.material.hardening.K_MPa, 589.0);
  ASSERT_EQ(s.tools.size(), 2u);
  EXPECT_EQ(s.tools[0].radius_mm, 50.8);
  EXPECT_EQ(s.tools[1].radius_mm, 52.83);
  EXPECT_EQ(s.process.output_travels_mm, (std::vector<double>{10.0, 20.0, 30.0}));
}

TEST(LoadScene, Example3IsTheEsaformCup) {
  const Scene s = load_scene(kScenesDir + "/ex3_flat_punch_cup.toml");
  EXPECT_EQ(s.tools[0].kind, ToolKind::kFlatPunch);
  EXPECT_EQ(s.tools[2].kind, ToolKind::kBlankHolder);
  EXPECT_EQ(s.tools[2].force_N, 10000.0);
  EXPECT_EQ(s.material.r_value, 0.41);
  EXPECT_EQ(s.blank.edge, EdgeCondition::kFree);
}

TEST(SceneDefaultsToml, IsValidTomlThatLoadsOnceAPunchIsAdded) {
  const std::string text = scene_defaults_toml();
  EXPECT_NE(text.find("thickness_mm = 1.0"), std::string::npos);
  EXPECT_NE(text.find("# sigma0_MPa = 200.0"), std::string::npos);  // hollomon/voce only
  EXPECT_NE(text.find("# gap_mm = 0.0"), std::string::npos);        // blank_holder only
  // The defaults file has no tools; a scene needs a punch, which must fit the default blank.
  const Scene scene = load_scene(write_scratch(
      "defaults.toml",
      text + "\n[[tool]]\nname = \"punch\"\nkind = \"hemispherical_punch\"\nradius_mm = 40\n"));
  EXPECT_EQ(scene.blank.radius_mm, BlankSpec{}.radius_mm);
  EXPECT_EQ(scene.numerics.tolerance, NumericsSpec{}.tolerance);
}

}  // namespace
}  // namespace vs
