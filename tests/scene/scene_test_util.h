// Helpers for the scene tests: scratch files in a per-test folder and the one-line message of a
// scene that fails to load, with the scratch path shortened to the bare file name.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "scene/load_scene.h"

namespace vs::testing {

// A fresh folder per test, so tests can run in parallel processes.
inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      (std::string("vs_scene_tests_") + info->test_suite_name() + "_" + info->name());
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes `text` to scratch_dir()/name and returns the full path.
inline std::string write_scratch(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratch_dir() / name;
  std::ofstream(path) << text;
  return path.string();
}

// Loads `text` as scene.toml and returns the InputError message with the scratch folder
// removed ("scene.toml:5:16: ..."), or "loaded" if the scene is valid.
inline std::string scene_error(const std::string& text) {
  const std::string path = write_scratch("scene.toml", text);
  try {
    load_scene(path);
  } catch (const InputError& e) {
    std::string message = e.what();
    const std::string folder = scratch_dir().string() + "/";
    for (auto at = message.find(folder); at != std::string::npos; at = message.find(folder)) {
      message.erase(at, folder.size());
    }
    return message;
  }
  return "loaded";
}

// A valid minimal scene: blank and punch only (9 lines). Tests append sections to it.
inline const std::string kMinimalScene =
    "[blank]\n"
    "radius_mm = 59.18\n"
    "thickness_mm = 0.85\n"
    "\n"
    "[[tool]]\n"
    "name = \"punch\"\n"
    "kind = \"hemispherical_punch\"\n"
    "radius_mm = 50.8\n"
    "\n";

// A die that fits kMinimalScene (lines 10-14 when appended to it).
inline const std::string kDie =
    "[[tool]]\n"
    "name = \"die\"\n"
    "kind = \"die\"\n"
    "radius_mm = 52.83\n"
    "profile_radius_mm = 6.35\n";

}  // namespace vs::testing
