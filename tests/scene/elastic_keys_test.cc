// [material.elastic]: isotropic elasticity as a first-order correction (scene_keys.cc), read in
// both geometries, one-line errors for bad moduli.
#include <gtest/gtest.h>

#include <string>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kMinimalScene;
using testing::scene_error;
using testing::write_scratch;

std::string with_elastic(const std::string& keys) {
  return kMinimalScene + "[material.elastic]\n" + keys;
}

TEST(ElasticKeys, DefaultIsRigidPlastic) {
  const Scene s = load_scene(write_scratch("scene.toml", kMinimalScene));
  EXPECT_EQ(s.material.elastic.law, ElasticLaw::kNone);
  EXPECT_FALSE(s.material.elastic.start_on());
  EXPECT_FALSE(s.material.elastic.strains_on());
}

TEST(ElasticKeys, IsotropicIsReadWithBothParts) {
  const Scene s = load_scene(write_scratch(
      "scene.toml",
      with_elastic("law = \"isotropic\"\nE_MPa = 70000\nnu = 0.33\nstart = false\n")));
  EXPECT_EQ(s.material.elastic.law, ElasticLaw::kIsotropic);
  EXPECT_EQ(s.material.elastic.E_MPa, 70000.0);
  EXPECT_EQ(s.material.elastic.nu, 0.33);
  EXPECT_FALSE(s.material.elastic.start_on());
  EXPECT_TRUE(s.material.elastic.strains_on());
  const Scene d = load_scene(write_scratch(
      "scene.toml",
      "geometry = \"shell3d\"\n" + with_elastic("law = \"isotropic\"\nE_MPa = 2e5\nnu = 0\n")));
  EXPECT_TRUE(d.material.elastic.start_on());
  EXPECT_TRUE(d.material.elastic.strains_on());
}

TEST(ElasticKeys, BadModuliAreOneLineErrors) {
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nE_MPa = 0\nnu = 0.3\n")),
            "scene.toml:12:9: material.elastic.E_MPa = 0 is out of range [1000, 10000000] MPa");
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nE_MPa = -5\nnu = 0.3\n")),
            "scene.toml:12:9: material.elastic.E_MPa = -5 is out of range [1000, 10000000] MPa");
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nE_MPa = 1e12\nnu = 0.3\n")),
            "scene.toml:12:9: material.elastic.E_MPa = 1000000000000 is out of range [1000, "
            "10000000] MPa: no sheet material is that stiff, and the step that crosses yield "
            "would overshoot the flow stress by E times its strain increment");
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nE_MPa = 2e5\nnu = 0.5\n")),
            "scene.toml:13:6: material.elastic.nu = 0.5 is out of range (-1, 0.5)");
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nE_MPa = 2e5\nnu = -1\n")),
            "scene.toml:13:6: material.elastic.nu = -1 is out of range (-1, 0.5)");
  EXPECT_EQ(scene_error(with_elastic("law = \"isotropic\"\nnu = 0.3\n")),
            "scene.toml:10:1: missing required key 'E_MPa' in [material.elastic]");
  EXPECT_EQ(scene_error(with_elastic("E_MPa = 2e5\n")),
            "scene.toml:11:1: key 'E_MPa' is not used by elasticity law 'none'");
}

}  // namespace
}  // namespace vs
