// Loads a bundled scene with overrides and runs it (shared by the system tests).
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "run/simulate.h"
#include "scene/load_scene.h"
#include "scene/scene_table.h"

namespace vs::test {

// std::getline without a trailing '\r' (the stored reference CSVs have CRLF ends).
inline bool getline_crlf(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

inline std::string scene_path(const std::string& name) {
  return std::string(VS_SOURCE_DIR) + "/data/scenes/" + name;
}

inline Scene load_with(const std::string& name,
                       const std::vector<std::pair<std::string, std::string>>& set) {
  const std::string path = scene_path(name);
  toml::table t = read_scene_table(path);
  for (const auto& [k, v] : set) set_scene_value_from_text(t, k, v);
  return scene_from_table(t, path, std::filesystem::path(path).parent_path().string());
}

// Peak punch force over the steps.
inline double peak_force(const RunResult& r) {
  double f = 0.0;
  for (const auto& s : r.steps) f = std::max(f, s.punch_force_N);
  return f;
}

// Index of the thinnest element of a profile.
inline std::size_t thinnest(const Profile& p) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < p.thickness_mm.size(); ++i) {
    if (p.thickness_mm[i] < p.thickness_mm[k]) k = i;
  }
  return k;
}

}  // namespace vs::test
