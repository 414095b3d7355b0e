// [material.anisotropy]: the planar yield functions of the 3D shell (scene_keys.cc), their data
// per model, and one-line errors for what does not fit (scene_reader.cc, scene_checks.cc).
#include <gtest/gtest.h>

#include <string>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kMinimalScene;
using testing::scene_error;
using testing::write_scratch;

std::string shell3d_scene(const std::string& anisotropy) {
  return "geometry = \"shell3d\"\n" + kMinimalScene + "[material.anisotropy]\n" + anisotropy;
}

TEST(AnisotropyKeys, DefaultIsNormalAnisotropy) {
  const Scene s = load_scene(write_scratch("scene.toml", kMinimalScene));
  EXPECT_EQ(s.material.anisotropy.model, AnisotropyModel::kNormal);
  EXPECT_FALSE(s.material.anisotropy.planar());
}

TEST(AnisotropyKeys, Hill48AndYld2000AreRead) {
  const Scene h = load_scene(write_scratch(
      "scene.toml", shell3d_scene("model = \"hill48_r\"\nr0 = 0.5\nr45 = 0.25\nr90 = 0.6\n"
                                  "rolling_direction_deg = 90\n")));
  EXPECT_EQ(h.material.anisotropy.model, AnisotropyModel::kHill48R);
  EXPECT_EQ(h.material.anisotropy.r45, 0.25);
  EXPECT_EQ(h.material.anisotropy.rolling_direction_deg, 90.0);
  const Scene y = load_scene(write_scratch(
      "scene.toml",
      shell3d_scene("model = \"yld2000\"\nr0 = 0.5\nr45 = 0.25\nr90 = 0.6\nr_b = 1.0\n"
                    "sigma45_ratio = 0.95\nsigma90_ratio = 0.97\nsigma_b_ratio = 1.0\n"
                    "exponent = 8\n")));
  EXPECT_EQ(y.material.anisotropy.model, AnisotropyModel::kYld2000);
  EXPECT_EQ(y.material.anisotropy.exponent, 8.0);
  EXPECT_EQ(y.material.anisotropy.sigma90_ratio, 0.97);
}

TEST(AnisotropyKeys, BadInputGivesOneLineErrors) {
  EXPECT_EQ(scene_error(shell3d_scene("model = \"hill48_r\"\nr0 = 0.5\nr90 = 0.6\n")),
            "scene.toml:11:1: missing required key 'r45' in [material.anisotropy]");
  EXPECT_EQ(scene_error(shell3d_scene("model = \"hill48_r\"\nr0 = 0.5\nr45 = 0.3\nr90 = 0.6\n"
                                      "exponent = 8\n")),
            "scene.toml:16:1: key 'exponent' is not used by anisotropy model 'hill48_r'");
  EXPECT_EQ(
      scene_error(shell3d_scene("model = \"hill48\"\n")),
      "scene.toml:12:9: material.anisotropy.model = \"hill48\" is not supported; expected one of "
      "\"normal\", \"hill48_r\", \"hill48_stress\", \"yld2000\" (did you mean \"hill48_r\"?)");
  EXPECT_EQ(scene_error(shell3d_scene("model = \"hill48_r\"\nr0 = -0.5\nr45 = 0.3\nr90 = 0.6\n")),
            "scene.toml:13:6: material.anisotropy.r0 = -0.5 is out of range [0.05, 20]");
  EXPECT_EQ(
      scene_error(shell3d_scene("model = \"hill48_r\"\nr0 = 0.5\nr45 = 0.3\nr90 = 0.6\n"
                                "rolling_direction_deg = 30\n")),
      "scene.toml:16:25: material.anisotropy.rolling_direction_deg = 30: a quarter blank "
      "(blank.symmetry = \"quarter\") mirrors the sheet about x = 0 and y = 0, which needs RD "
      "along x or y (0, 90, 180 or -90 deg); use blank.symmetry = \"full\" for another angle");
  EXPECT_EQ(scene_error("geometry = \"shell3d\"\n" + kMinimalScene +
                        "[material]\nr_value = 0.5\n[material.anisotropy]\nmodel = \"hill48_r\"\n"
                        "r0 = 0.5\nr45 = 0.3\nr90 = 0.6\n"),
            "scene.toml:12:11: material.r_value is the normal-anisotropy R; with a planar "
            "material.anisotropy.model the r-values go in [material.anisotropy]");
  EXPECT_EQ(
      scene_error(kMinimalScene + "[material.anisotropy]\nmodel = \"hill48_r\"\n"
                                  "r0 = 0.5\nr45 = 0.3\nr90 = 0.6\n"),
      "scene.toml:11:1: key 'material.anisotropy.model' is only used by geometry = \"shell3d\"");
}

}  // namespace
}  // namespace vs
