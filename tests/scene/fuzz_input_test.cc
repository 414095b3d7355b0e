// Generated malformed scene inputs: whatever the text, load_scene either loads it or throws
// InputError with a one-line message; never another exception, never a signal (a crash would
// kill this test binary). Each generated test is bounded in time (about a second).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scene/fuzz_mutate.h"
#include "scene/scene_keys.h"
#include "scene/scene_table.h"
#include "scene/toml_guard.h"
#include "scene_test_util.h"

namespace vs {
namespace {

using testing::kMinimalScene;
using testing::repeat;
using testing::scene_error;
using testing::write_scratch;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every way to nest TOML, at `depth` levels.
std::vector<std::pair<std::string, std::string>> nested_cases(int depth) {
  const std::string dotted = "a" + repeat(".a", depth - 1);
  return {
      {"dotted key", dotted + " = 1\n"},
      {"table header", "[" + dotted + "]\nx = 1\n"},
      {"array-of-tables header", "[[" + dotted + "]]\nx = 1\n"},
      {"arrays", "x = " + repeat("[", depth) + repeat("]", depth) + "\n"},
      {"inline tables", "x = " + repeat("{a = ", depth) + "1" + repeat("}", depth) + "\n"},
      {"mixed", "[" + repeat("a.", depth / 3) + "b]\n" + repeat("c.", depth / 3) + "d = " +
                    repeat("[{e = ", depth / 6 + 1) + "1" + repeat("}]", depth / 6 + 1) + "\n"},
      {"quoted dotted key", "\"a\"" + repeat(".'a'", depth - 1) + " = 1\n"},
  };
}

void expect_one_line_input_error(const std::string& message, const std::string& label) {
  EXPECT_NE(message, "loaded") << label;
  EXPECT_EQ(message.find('\n'), std::string::npos) << label << ": " << message;
  EXPECT_LT(message.size(), 400u) << label << ": " << message;
}

TEST(FuzzInput, DeepNestingIsAnErrorNamingTheLineNotACrash) {
  for (int depth : {kMaxTomlNesting + 1, 1000, 50000}) {
    for (const auto& [label, text] : nested_cases(depth)) {
      const std::string message = scene_error(kMinimalScene + "# comment\n" + text);
      expect_one_line_input_error(message, label);
      const std::string line = label == "mixed" && depth / 3 + 1 <= 64 ? "12" : "11";
      EXPECT_EQ(message.rfind("scene.toml:" + line + ": nested deeper than 64 levels", 0), 0u)
          << label << " at depth " << depth << ": " << message.substr(0, 200);
    }
  }
}

TEST(FuzzInput, NestingWithinTheBoundReachesTheSceneChecks) {
  for (const auto& [label, text] : nested_cases(kMaxTomlNesting - 4)) {
    const std::string message = scene_error(kMinimalScene + text);
    expect_one_line_input_error(message, label);
    EXPECT_EQ(message.find("nested deeper"), std::string::npos) << label << ": " << message;
  }
}

TEST(FuzzInput, BracketsAndDotsInStringsAndCommentsDoNotCount) {
  const std::string deep = repeat("[a.", 200);
  EXPECT_EQ(scene_error(kMinimalScene + "# " + deep + "\n[output]\ndirectory = \"" + deep + "\"\n"),
            "loaded");
  EXPECT_EQ(scene_error("title = '''\n" + deep + "\n'''\n" + kMinimalScene), "loaded");
  EXPECT_EQ(scene_error("title = \"\\\"" + deep + "\"\n" + kMinimalScene), "loaded");
}

TEST(FuzzInput, OversizedAndBinaryFilesAreRefused) {
  const std::string big = write_scratch("big.toml", std::string(kMaxTomlBytes + 1, '#'));
  try {
    load_scene(big);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than the 16 MiB"), std::string::npos) << e.what();
  }
  const std::string message = scene_error(kMinimalScene + std::string("title = \"a\0b\"\n", 14));
  EXPECT_EQ(message, "scene.toml:10: NUL byte (U+0000): this is not a text file");
  EXPECT_EQ(scene_error("").find("scene.toml"), 0u);
}

TEST(FuzzInput, SetOverridesAreGuardedToo) {
  toml::table table = read_scene_table(write_scratch("scene.toml", kMinimalScene));
  EXPECT_THROW(set_scene_value_from_text(table, "blank.radius_mm", repeat("[", 100000)),
               InputError);
  EXPECT_THROW(
      set_scene_value_from_text(table, "blank.radius_mm", "1\n" + repeat("a.", 100000) + "b = 1"),
      InputError);
}

TEST(FuzzInput, MutatedBundledScenesLoadOrGiveOneLine) {
  std::vector<std::string> scenes;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(VS_SOURCE_DIR) + "/data/scenes")) {
    if (entry.path().extension() == ".toml") scenes.push_back(read_file(entry.path().string()));
  }
  ASSERT_FALSE(scenes.empty());
  std::mt19937 rng(20261122);
  const auto start = std::chrono::steady_clock::now();
  int cases = 0, errors = 0;
  while (cases < 3000 &&
         std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1500)) {
    const std::string text =
        testing::mutate_toml(scenes[static_cast<std::size_t>(cases) % scenes.size()], rng);
    ++cases;
    std::string message;
    try {
      message = scene_error(text);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << cases << ": " << typeid(e).name() << ": " << e.what()
                    << "\n--- input ---\n"
                    << text;
      continue;
    }
    if (message == "loaded") continue;
    ++errors;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "case " << cases << ": " << message;
    EXPECT_EQ(message.rfind("scene.toml", 0), 0u) << "case " << cases << ": " << message;
  }
  EXPECT_GT(cases, 100);
  EXPECT_GT(errors, cases / 4);
}

}  // namespace
}  // namespace vs

namespace vs {
namespace {

// The section text that sets `key` to `value` on top of kMinimalScene (tool keys on the punch).
std::string with_value(const KeySpec& key, const std::string& value) {
  if (key.section == "tool") {
    return testing::kMinimalScene.substr(0, testing::kMinimalScene.size() - 1) +
           fmt::format("{} = {}\n", key.name, value);
  }
  if (key.section.empty())
    return fmt::format("{} = {}\n", key.name, value) + testing::kMinimalScene;
  return testing::kMinimalScene + fmt::format("[{}]\n{} = {}\n", key.section, key.name, value);
}

TEST(FuzzInput, ExtremeValuesOfEveryNumericKeyGiveOneLine) {
  const std::vector<std::string> extremes = {
      "0",          "-1",      "1e308", "-1e308",     "1e-308",
      "nan",        "inf",     "-inf",  "2147483648", "9223372036854775807",
      "1000000000", "[1e308]", "[]"};
  int errors = 0;
  for (const KeySpec& key : scene_keys()) {
    if (key.type != KeyType::kFloat && key.type != KeyType::kInt &&
        key.type != KeyType::kFloatArray) {
      continue;
    }
    for (const std::string& value : extremes) {
      const std::string message = testing::scene_error(with_value(key, value));
      if (message == "loaded") continue;
      ++errors;
      EXPECT_EQ(message.find('\n'), std::string::npos)
          << key.address_in_section() << " = " << value;
      EXPECT_EQ(message.rfind("scene.toml", 0), 0u) << message;
    }
  }
  EXPECT_GT(errors, 100);
}

// Sizes that used to pass `vshell check` and then exhaust memory or run for hours.
TEST(FuzzInput, AbsurdSizesAndStepCountsAreRefusedWithTheReason) {
  const std::string travel1000 = [] {
    std::string list = "[";
    for (int i = 1; i <= 1000; ++i) list += fmt::format("{}{}", i > 1 ? ", " : "", 0.01 * i);
    return list + "]";
  }();
  const struct {
    std::string text;
    std::string expected;
  } cases[] = {
      {"[blank]\nelements = 1000000000\n", "grow with the square of the element count"},
      {"[numerics]\nstep_fraction = 1e-4\n", "ln(1/f)/f steps per contact event"},
      {"[numerics]\nmax_strain_increment = 1e-9\n", "take millions of steps"},
      {"[numerics]\nmax_iterations = 100000000\n", "1000 iterations will not"},
      {"[process]\npunch_travel_mm = 30\noutput_travels_mm = " + travel1000 + "\n",
       "1000 values, more than the 500 allowed"},
      {"[numerics]\nmax_travel_increment_mm = 1e-9\n", "more than the 1e+06 a run may take"},
      {"[numerics]\nmax_travel_increment_per_length = 1e-7\n",
       "more than the 1e+06 a run may take"},
      {"[process]\npunch_travel_mm = 1e6\n", "shorten process.punch_travel_mm"},
      {"[blank]\nelements = 2000\n[process]\npunch_travel_mm = 100\n[numerics]\n"
       "max_travel_increment_per_length = 0.025\n",
       "more than the 1e+08 allowed for axisymmetric runs"},
      {"friction = 1e6\n", "use \"sticking\""},  // continues the punch's [[tool]] table
  };
  for (const auto& c : cases) {
    const std::string message = testing::scene_error(
        std::string("[blank]\nradius_mm = 59.18\nthickness_mm = 0.85\n") +
        (c.text.rfind("[blank]", 0) == 0 ? c.text.substr(8) : "") +
        "[[tool]]\nname = \"punch\"\nkind = \"hemispherical_punch\"\nradius_mm = 50.8\n" +
        (c.text.rfind("[blank]", 0) == 0 ? "" : c.text));
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace vs
