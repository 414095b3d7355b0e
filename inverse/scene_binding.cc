#include "scene_binding.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/load_scene.h"
#include "scene/scene_keys.h"
#include "scene/scene_table.h"

namespace vs {
namespace {

// Sorted union of the scene's own output travels and the data travels, without near-duplicates
// (a data travel of 20 and a scene travel of 20.0 are one stop). Travels beyond the total punch
// travel are dropped: the scene's own ones may have been cut by an override (a shorter
// calibration run), and data that need more travel are reported by calibrate() in plain words.
std::vector<double> merged_travels(const toml::table& table, const std::vector<double>& extra) {
  const double total = get_scene_number(table, "process.punch_travel_mm");
  std::vector<double> travels = extra;
  if (const auto* process = table["process"].as_table()) {
    if (const auto* existing = (*process)["output_travels_mm"].as_array()) {
      for (const auto& node : *existing) {
        if (auto value = node.value<double>()) travels.push_back(*value);
      }
    }
  }
  std::sort(travels.begin(), travels.end());
  std::vector<double> unique;
  for (double t : travels) {
    if (t > total) continue;
    if (unique.empty() || std::abs(t - unique.back()) > 1e-9 * std::max(1.0, std::abs(t))) {
      unique.push_back(t);
    }
  }
  return unique;
}

}  // namespace

SceneBinding::SceneBinding(toml::table table, std::string source, std::string base_dir,
                           const ForwardSettings& settings,
                           const std::vector<double>& data_travels_mm)
    : table_(std::move(table)), source_(std::move(source)), base_dir_(std::move(base_dir)) {
  for (const auto& [address, text] : settings.overrides) {
    set_scene_value_from_text(table_, address, text);
  }
  if (settings.tolerance > 0.0) set_scene_number(table_, "numerics.tolerance", settings.tolerance);
  // Hundreds of runs: keep neither the per-step fields nor plots, only what residuals need.
  set_scene_value_from_text(table_, "output.history", "false");
  set_scene_value_from_text(table_, "output.plots", "false");
  const auto travels = merged_travels(table_, data_travels_mm);
  if (!travels.empty()) {
    toml::array array;
    for (double t : travels) array.push_back(t);
    if (!table_["process"].is_table()) table_.insert_or_assign("process", toml::table{});
    table_["process"].as_table()->insert_or_assign("output_travels_mm", std::move(array));
  }
  base_scene();  // validate now: every configuration error before any forward run
}

std::vector<std::string> SceneBinding::attach(const std::vector<ParameterSpec>& parameters) {
  addresses_.clear();
  applies_.clear();
  std::vector<std::string> reasons;
  for (const auto& p : parameters) {
    addresses_.push_back(p.address);
    try {
      get_scene_number(table_, p.address);
      applies_.push_back(true);
      reasons.emplace_back();
    } catch (const InputError& e) {
      applies_.push_back(false);
      reasons.emplace_back(e.what());
    }
  }
  return reasons;
}

Scene SceneBinding::bind(const std::vector<double>& values) const {
  toml::table table = table_;
  for (std::size_t i = 0; i < addresses_.size(); ++i) {
    if (applies_[i]) set_scene_number(table, addresses_[i], values.at(i));
  }
  return scene_from_table(table, source_, base_dir_);
}

double SceneBinding::value_of(const std::string& address) const {
  return get_scene_number(table_, address);
}

bool SceneBinding::is_integer(const std::string& address) const {
  return scene_address_key(table_, address).type == KeyType::kInt;
}

Scene SceneBinding::base_scene() const { return scene_from_table(table_, source_, base_dir_); }

}  // namespace vs
