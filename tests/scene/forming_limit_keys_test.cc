// [forming_limit]: the default Keeler-Brazier curve, a user table, and one-line errors for bad
// values (declared in scene_keys.cc like every scene key; read in scene_reader.cc).
#include <gtest/gtest.h>

#include <string>

#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kMinimalScene;
using testing::scene_error;
using testing::write_scratch;

// kMinimalScene is 9 lines, so a section appended to it starts on line 10.

TEST(FormingLimitKeys, DefaultIsKeelerBrazierWithMarginPointOne) {
  const Scene s = load_scene(write_scratch("scene.toml", kMinimalScene));
  EXPECT_EQ(s.forming_limit.model, FormingLimitModel::kKeelerBrazier);
  EXPECT_EQ(s.forming_limit.safety_margin, 0.1);
  EXPECT_TRUE(s.forming_limit.table_minor.empty());
}

TEST(FormingLimitKeys, TableIsReadInOrder) {
  const Scene s = load_scene(write_scratch(
      "scene.toml", kMinimalScene + "[forming_limit]\nmodel = \"table\"\nsafety_margin = 0.08\n"
                                    "points = [[-0.3, 0.6], [0, 0.3], [0.3, 0.45]]\n"));
  EXPECT_EQ(s.forming_limit.model, FormingLimitModel::kTable);
  EXPECT_EQ(s.forming_limit.safety_margin, 0.08);
  EXPECT_EQ(s.forming_limit.table_minor, (std::vector<double>{-0.3, 0.0, 0.3}));
  EXPECT_EQ(s.forming_limit.table_major, (std::vector<double>{0.6, 0.3, 0.45}));
  const Scene none = load_scene(
      write_scratch("scene.toml", kMinimalScene + "[forming_limit]\nmodel = \"none\"\n"));
  EXPECT_EQ(none.forming_limit.model, FormingLimitModel::kNone);
}

TEST(FormingLimitKeys, BadValuesGiveOneLineErrors) {
  const std::string head = kMinimalScene + "[forming_limit]\n";
  EXPECT_EQ(
      scene_error(head + "model = \"keeler_brazier\"\n"),
      "scene.toml:11:9: forming_limit.model = \"keeler_brazier\" is not supported; expected one of "
      "\"keeler-brazier\", \"table\", \"none\" (did you mean \"keeler-brazier\"?)");
  EXPECT_EQ(scene_error(head + "model = \"table\"\n"),
            "scene.toml:10:1: missing required key 'points' in [forming_limit]");
  EXPECT_EQ(scene_error(head + "points = [[0, 0.3], [0.2, 0.4]]\n"),
            "scene.toml:11:1: key 'points' is not used by forming limit model 'keeler-brazier'");
  EXPECT_EQ(scene_error(head + "safety_margin = -0.1\n"),
            "scene.toml:11:17: forming_limit.safety_margin = -0.1 is out of range [0, 1]");
  const std::string table = head + "model = \"table\"\n";
  EXPECT_EQ(scene_error(table + "points = [[0, 0.3]]\n"),
            "scene.toml:12:10: forming_limit.points has 1 points; give 2 to 100");
  EXPECT_EQ(scene_error(table + "points = [[0, 0.3], [0, 0.4]]\n"),
            "scene.toml:12:21: forming_limit.points[1]: minor strain 0 does not increase "
            "(previous point: 0)");
  EXPECT_EQ(scene_error(table + "points = [[-0.2, 0.3], [0.1, -0.4]]\n"),
            "scene.toml:12:24: forming_limit.points[1]: major strain -0.4 is outside (0, 2]");
  EXPECT_EQ(scene_error(table + "points = [[-2, 0.3], [0.1, 0.4]]\n"),
            "scene.toml:12:11: forming_limit.points[0]: minor strain -2 is outside [-1, 1]");
  EXPECT_EQ(scene_error(table + "points = [[0, 0.3], [0.1]]\n"),
            "scene.toml:12:21: forming_limit.points[1]: expected a pair [minor_true_strain, "
            "major_true_strain]");
  EXPECT_EQ(scene_error(table + "points = [[0, 0.3], [0.1, nan]]\n"),
            "scene.toml:12:21: forming_limit.points[1]: major strain nan is outside (0, 2]");
  EXPECT_EQ(scene_error(table + "points = \"x\"\n"),
            "scene.toml:12:10: forming_limit.points: expected [[minor_true_strain, "
            "major_true_strain], ...], got string");
}

}  // namespace
}  // namespace vs
