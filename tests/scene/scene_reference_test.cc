// docs/scene-reference.md must be the current output of scene_reference_markdown().
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "scene/load_scene.h"
#include "scene/scene_keys.h"

namespace vs {
namespace {

const std::string kReferencePath = std::string(VS_SOURCE_DIR) + "/docs/scene-reference.md";

TEST(SceneReference, DocsFileIsUpToDate) {
  std::ifstream in(kReferencePath);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(text.str() == scene_reference_markdown())
      << kReferencePath << " is stale; regenerate with: build-scene/tests/vs_scene_tests "
      << "--gtest_also_run_disabled_tests --gtest_filter='*RegenerateReference*'";
}

TEST(SceneReference, EveryKeyIsDocumented) {
  const std::string markdown = scene_reference_markdown();
  for (const KeySpec& key : scene_keys()) {
    EXPECT_FALSE(key.doc.empty()) << key.address_in_section();
    EXPECT_NE(markdown.find("| `" + std::string(key.name) + "` |"), std::string::npos)
        << key.address_in_section();
  }
}

// Run explicitly to rewrite the docs file after changing the key registry.
TEST(SceneReference, DISABLED_RegenerateReference) {
  std::ofstream(kReferencePath) << scene_reference_markdown();
}

}  // namespace
}  // namespace vs
