#include "scene_binding.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "inverse_test_support.h"
#include "scene/scene_table.h"

namespace vs {
namespace {

using namespace vs::testing;

TEST(SceneBinding, WritesParametersToleranceOverridesAndDataTravels) {
  const fs::path dir = scratch_dir();
  const fs::path path = write_scene(dir);
  ForwardSettings settings;
  settings.tolerance = 1e-10;
  settings.overrides = {{"blank.elements", "12"}};
  SceneBinding binding(read_scene_table(path.string()), path.string(), dir.string(), settings,
                       {20.0, 10.0, 30.0});
  const auto reasons = binding.attach({param("tool.punch.friction", 0.1, 0, 1, 0.1),
                                       param("material.r_value", 1.0, 0.5, 3, 1),
                                       param("tool.holder.friction", 0.1, 0, 1, 0.1)});
  EXPECT_EQ(reasons[0], "");
  EXPECT_NE(reasons[2], "");  // no holder in this scene
  EXPECT_FALSE(binding.applies(2));
  const Scene scene = binding.bind({0.25, 1.7, 0.3});
  EXPECT_EQ(scene.tools[0].friction, 0.25);
  EXPECT_EQ(scene.material.r_value, 1.7);
  EXPECT_EQ(scene.numerics.tolerance, 1e-10);
  EXPECT_EQ(scene.blank.elements, 12);
  EXPECT_FALSE(scene.output.history);
  EXPECT_EQ(scene.process.output_travels_mm, (std::vector<double>{10.0, 20.0, 30.0}));
  EXPECT_THROW(binding.bind({-1.0, 1.0, 0.0}), InputError);  // friction < 0
}

}  // namespace
}  // namespace vs
