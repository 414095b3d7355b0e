#include "scene/scene_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include "core/error.h"
#include "scene/cup_profile_file.h"
#include "scene/did_you_mean.h"
#include "scene/flow_curve_table.h"
#include "scene/key_value.h"
#include "scene/scene_keys.h"

namespace vs {

namespace {

struct Entry {
  const toml::key* key;
  const toml::node* node;
};

// Keys in the order they appear in the file, so the first error reported is the first one a
// reader meets (toml::table itself is ordered by name).
std::vector<Entry> entries_in_file_order(const toml::table& table) {
  std::vector<Entry> entries;
  for (auto&& [key, node] : table) entries.push_back({&key, &node});
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    const auto& ra = a.key->source().begin;
    const auto& rb = b.key->source().begin;
    return ra.line != rb.line ? ra.line < rb.line : ra.column < rb.column;
  });
  return entries;
}

std::string join(const std::string& prefix, std::string_view name) {
  return prefix.empty() ? std::string(name) : fmt::format("{}.{}", prefix, name);
}

// The enum text of a key's default ("swift").
std::string default_choice(const KeySpec& key) {
  Scene scene;
  ToolSpec tool;
  return std::string(key.choices.at(static_cast<std::size_t>(key.field.get_choice(scene, tool))));
}

// "(it belongs in [material])" when a misplaced key exists in exactly another section.
std::string belongs_elsewhere(std::string_view name, std::string_view section) {
  for (const KeySpec& k : scene_keys()) {
    if (k.name != name || k.section == section) continue;
    for (const SectionSpec& s : scene_sections()) {
      if (s.name == k.section) return fmt::format(" (it belongs in {})", s.header);
    }
  }
  return "";
}

class SceneReader {
 public:
  SceneReader(const std::string& base_dir, SceneSourceMap& where)
      : base_dir_(base_dir), where_(where) {}

  Scene read(const toml::table& root) {
    read_keys(root, "", "at top level", "", no_tool_, kTopSections);
    for (const Entry& e : entries_in_file_order(root)) {
      const std::string name(e.key->str());
      where_.add(name, e.key->source());
      if (name == "tool") {
        read_tools(*e.node);
      } else if (name == "material") {
        read_material(as_table(*e.node, name));
      } else if (name == "forming_limit") {
        read_forming_limit(as_table(*e.node, name));
      } else if (name != "title" && name != "geometry") {
        read_keys(as_table(*e.node, name), name, fmt::format("in [{}]", name), name, no_tool_, {});
      }
    }
    read_measured_cup_profile(root);
    return scene_;
  }

 private:
  static inline const std::vector<std::string_view> kTopSections = {
      "blank", "material", "tool", "process", "numerics", "forming_limit", "output"};

  const toml::table& as_table(const toml::node& node, const std::string& address) const {
    if (!node.is_table()) {
      fail_at(where_.source(), node.source(),
              fmt::format("{}: expected a table, got {}", address, toml_type_name(node)));
    }
    return *node.as_table();
  }

  // Reads every key of one section. `in_label` places the section in messages ("in [blank]",
  // "in [[tool]] 'punch'"); `prefix` is the address prefix; `subsections` are tables the
  // caller reads itself.
  void read_keys(const toml::table& table, std::string_view section, const std::string& in_label,
                 const std::string& prefix, ToolSpec& tool,
                 const std::vector<std::string_view>& subsections) {
    const VariantSelector* selector = find_selector(section);
    std::string variant;
    if (selector != nullptr) {
      const KeySpec& key = *find_key(section, selector->key);
      if (const toml::node* node = table.get(selector->key)) {
        variant = read_choice(key, *node, join(prefix, key.name), where_.source());
      } else if (key.required) {
        fail_at(where_.source(), table.source(),
                fmt::format("missing required key '{}' {}", key.name, in_label));
      } else {
        variant = default_choice(key);
      }
    }
    for (const Entry& e : entries_in_file_order(table)) {
      const std::string_view name = e.key->str();
      if (std::find(subsections.begin(), subsections.end(), name) != subsections.end()) continue;
      const KeySpec* key = find_key(section, name);
      if (key == nullptr) unknown_key(*e.key, section, in_label, subsections);
      if (selector != nullptr && !key_applies(*key, variant)) {
        fail_at(where_.source(), e.key->source(),
                fmt::format("key '{}' is not used by {} '{}'{}", name, selector->label, variant,
                            section == "tool" ? " " + in_label : ""));
      }
      store_key_value(*key, *e.node, join(prefix, name), where_, scene_, tool);
    }
    for (const KeySpec& key : scene_keys()) {
      if (key.section == section && key.required && key_applies(key, variant) &&
          !table.contains(key.name)) {
        fail_at(where_.source(), table.source(),
                fmt::format("missing required key '{}' {}", key.name, in_label));
      }
    }
  }

  [[noreturn]] void unknown_key(const toml::key& key, std::string_view section,
                                const std::string& in_label,
                                const std::vector<std::string_view>& subsections) const {
    std::vector<std::string_view> candidates = subsections;
    for (const KeySpec& k : scene_keys()) {
      if (k.section == section) candidates.push_back(k.name);
    }
    const std::string guess = closest_match(key.str(), candidates);
    const std::string hint = guess.empty() ? belongs_elsewhere(key.str(), section)
                                           : fmt::format(" (did you mean '{}'?)", guess);
    fail_at(where_.source(), key.source(),
            fmt::format("unknown key '{}' {}{}", key.str(), in_label, hint));
  }

  void read_material(const toml::table& material) {
    read_keys(material, "material", "in [material]", "material", no_tool_,
              {"hardening", "rate", "anisotropy", "elastic"});
    if (const toml::node* node = material.get("hardening")) {
      const toml::table& hardening = as_table(*node, "material.hardening");
      where_.add("material.hardening", hardening.source());
      read_keys(hardening, "material.hardening", "in [material.hardening]", "material.hardening",
                no_tool_, {});
      if (scene_.material.hardening.law == HardeningLaw::kTable) read_flow_table(hardening);
    }
    if (const toml::node* node = material.get("rate")) {
      const toml::table& rate = as_table(*node, "material.rate");
      where_.add("material.rate", rate.source());
      read_keys(rate, "material.rate", "in [material.rate]", "material.rate", no_tool_, {});
    }
    if (const toml::node* node = material.get("elastic")) {
      const toml::table& elastic = as_table(*node, "material.elastic");
      where_.add("material.elastic", elastic.source());
      read_keys(elastic, "material.elastic", "in [material.elastic]", "material.elastic", no_tool_,
                {});
    }
    if (const toml::node* node = material.get("anisotropy")) {
      const toml::table& anisotropy = as_table(*node, "material.anisotropy");
      where_.add("material.anisotropy", anisotropy.source());
      read_keys(anisotropy, "material.anisotropy", "in [material.anisotropy]",
                "material.anisotropy", no_tool_, {});
      if (scene_.material.anisotropy.planar() && material.contains("r_value")) {
        fail_at(where_.source(), material.get("r_value")->source(),
                "material.r_value is the normal-anisotropy R; with a planar "
                "material.anisotropy.model the r-values go in [material.anisotropy]");
      }
    }
  }

  void read_flow_table(const toml::table& hardening) {
    const toml::node* inline_table = hardening.get("table");
    const toml::node* file = hardening.get("table_file");
    if (inline_table != nullptr && file != nullptr) {
      fail_at(where_.source(), file->source(),
              "give material.hardening.table or material.hardening.table_file, not both");
    }
    if (inline_table == nullptr && file == nullptr) {
      fail_at(where_.source(), hardening.get("law")->source(),
              "hardening law 'table' needs material.hardening.table or "
              "material.hardening.table_file");
    }
    const FlowCurveTable curve =
        inline_table != nullptr ? read_inline_curve(*inline_table) : read_curve_file(*file);
    scene_.material.hardening.table_strain = curve.strain;
    scene_.material.hardening.table_stress_MPa = curve.stress_MPa;
  }

  FlowCurveTable read_inline_curve(const toml::node& node) const {
    const std::string address = "material.hardening.table";
    const toml::array* rows = node.as_array();
    if (rows == nullptr) {
      fail_at(where_.source(), node.source(),
              fmt::format("{}: expected [[strain, stress_MPa], ...], got {}", address,
                          toml_type_name(node)));
    }
    FlowCurveTable curve;
    for (std::size_t i = 0; i < rows->size(); ++i) {
      const toml::node& row = *rows->get(i);
      const std::string row_address = fmt::format("{}[{}]", address, i);
      const toml::array* pair = row.as_array();
      if (pair == nullptr || pair->size() != 2) {
        fail_at(where_.source(), row.source(),
                fmt::format("{}: expected a pair [strain, stress_MPa]", row_address));
      }
      const double strain = read_number(*pair->get(0), row_address, where_.source());
      const double stress = read_number(*pair->get(1), row_address, where_.source());
      const std::string problem = flow_curve_point_problem(curve, strain, stress);
      if (!problem.empty()) {
        fail_at(where_.source(), row.source(), fmt::format("{}: {}", row_address, problem));
      }
      curve.strain.push_back(strain);
      curve.stress_MPa.push_back(stress);
    }
    const std::string problem = flow_curve_size_problem(curve);
    if (!problem.empty()) {
      fail_at(where_.source(), node.source(), fmt::format("{}: {}", address, problem));
    }
    return curve;
  }

  void read_forming_limit(const toml::table& table) {
    read_keys(table, "forming_limit", "in [forming_limit]", "forming_limit", no_tool_, {});
    if (scene_.forming_limit.model != FormingLimitModel::kTable) return;
    const std::string address = "forming_limit.points";
    const toml::node& node = *table.get("points");  // required: read_keys checked it is there
    const toml::array* rows = node.as_array();
    if (rows == nullptr) {
      fail_at(where_.source(), node.source(),
              fmt::format("{}: expected [[minor_true_strain, major_true_strain], ...], got {}",
                          address, toml_type_name(node)));
    }
    constexpr std::size_t kMaxPoints = 100;
    if (rows->size() < 2 || rows->size() > kMaxPoints) {
      fail_at(where_.source(), node.source(),
              fmt::format("{} has {} points; give 2 to {}", address, rows->size(), kMaxPoints));
    }
    FormingLimitSpec& flc = scene_.forming_limit;
    for (std::size_t i = 0; i < rows->size(); ++i) {
      const toml::node& row = *rows->get(i);
      const std::string row_address = fmt::format("{}[{}]", address, i);
      const toml::array* pair = row.as_array();
      if (pair == nullptr || pair->size() != 2) {
        fail_at(
            where_.source(), row.source(),
            fmt::format("{}: expected a pair [minor_true_strain, major_true_strain]", row_address));
      }
      const double minor = read_number(*pair->get(0), row_address, where_.source());
      const double major = read_number(*pair->get(1), row_address, where_.source());
      std::string problem;
      if (!(minor >= -1.0 && minor <= 1.0)) {
        problem = fmt::format("minor strain {} is outside [-1, 1]", minor);
      } else if (!(major > 0.0 && major <= 2.0)) {
        problem = fmt::format("major strain {} is outside (0, 2]", major);
      } else if (!flc.table_minor.empty() && !(minor > flc.table_minor.back())) {
        problem = fmt::format("minor strain {} does not increase (previous point: {})", minor,
                              flc.table_minor.back());
      }
      if (!problem.empty()) {
        fail_at(where_.source(), row.source(), fmt::format("{}: {}", row_address, problem));
      }
      flc.table_minor.push_back(minor);
      flc.table_major.push_back(major);
    }
  }

  FlowCurveTable read_curve_file(const toml::node& node) const {
    const std::string address = "material.hardening.table_file";
    const std::string name =
        read_string(*find_key("material.hardening", "table_file"), node, address, where_.source());
    std::filesystem::path path(name);
    if (path.is_relative() && !base_dir_.empty()) path = std::filesystem::path(base_dir_) / path;
    if (!std::filesystem::is_regular_file(path)) {
      fail_at(where_.source(), node.source(),
              fmt::format("{}: cannot open table file '{}'", address, path.string()));
    }
    return read_flow_curve_csv(path.string());
  }

  // output.measured_cup_profile: resolved relative to the scene file and read now, so that a bad
  // file is refused before the run (read_cup_profile_file names its line).
  void read_measured_cup_profile(const toml::table& root) {
    OutputSpec& out = scene_.output;
    if (out.measured_cup_profile.empty()) return;
    const toml::table* output = root.get_as<toml::table>("output");
    const toml::node* node = output != nullptr ? output->get("measured_cup_profile") : nullptr;
    std::filesystem::path path(out.measured_cup_profile);
    if (path.is_relative() && !base_dir_.empty()) path = std::filesystem::path(base_dir_) / path;
    if (!std::filesystem::is_regular_file(path)) {
      const std::string message = fmt::format(
          "output.measured_cup_profile: cannot open cup profile file '{}'", path.string());
      if (node != nullptr) fail_at(where_.source(), node->source(), message);
      throw InputError(fmt::format("{}: {}", where_.source(), message));
    }
    out.measured_cup_profile = path.string();
    const CupProfilePoints points = read_cup_profile_file(out.measured_cup_profile);
    out.measured_cup_angle_deg = points.angle_deg;
    out.measured_cup_height_mm = points.height_mm;
  }

  void read_tools(const toml::node& node) {
    const toml::array* tools = node.as_array();
    if (tools == nullptr || !tools->is_array_of_tables()) {
      fail_at(where_.source(), node.source(),
              fmt::format("tool: expected an array of tables ([[tool]]), got {}",
                          toml_type_name(node)));
    }
    std::map<std::string, toml::source_region> first_seen;
    for (std::size_t i = 0; i < tools->size(); ++i) {
      const toml::table& table = *tools->get(i)->as_table();
      const std::string number_label = fmt::format("in [[tool]] #{}", i + 1);
      const toml::node* name_node = table.get("name");
      if (name_node == nullptr) {
        fail_at(where_.source(), table.source(),
                fmt::format("missing required key 'name' {}", number_label));
      }
      const std::string name = read_string(*find_key("tool", "name"), *name_node,
                                           fmt::format("tool #{} name", i + 1), where_.source());
      if (const auto it = first_seen.find(name); it != first_seen.end()) {
        fail_at(where_.source(), name_node->source(),
                fmt::format("duplicate tool name '{}' (first used at {})", name,
                            source_location(where_.source(), it->second)));
      }
      first_seen[name] = name_node->source();
      const std::string prefix = "tool." + name;
      where_.add(prefix, table.source());
      ToolSpec tool;
      read_keys(table, "tool", fmt::format("in [[tool]] '{}'", name), prefix, tool, {});
      scene_.tools.push_back(tool);
    }
  }

  const std::string& base_dir_;
  SceneSourceMap& where_;
  Scene scene_;
  ToolSpec no_tool_;  // target for [[tool]] accessors outside a tool: never used
};

}  // namespace

Scene read_scene_sections(const toml::table& root, const std::string& base_dir,
                          SceneSourceMap& where) {
  return SceneReader(base_dir, where).read(root);
}

}  // namespace vs
