#include "calibration_config.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <system_error>

#include "core/error.h"
#include "scene/toml_guard.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

// Reads one TOML table, checking types, and rejects keys nobody asked for.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string file, std::string section)
      : table_(table), file_(std::move(file)), section_(std::move(section)) {}

  std::string where(const toml::node& node) const {
    return fmt::format("{}:{}", file_, node.source().begin.line);
  }
  std::string where() const { return where(table_); }
  std::string where_key(const std::string& key) const {
    const toml::node* node = table_.get(key);
    return fmt::format("{}: key '{}{}'", node ? where(*node) : where(), prefix(), key);
  }

  std::optional<double> number(const std::string& key) {
    const toml::node* node = take(key);
    if (!node) return std::nullopt;
    if (!node->is_number()) fail_type(key, "a number");
    return node->value<double>();
  }
  std::optional<long long> integer(const std::string& key) {
    const toml::node* node = take(key);
    if (!node) return std::nullopt;
    if (!node->is_integer()) fail_type(key, "an integer");
    return node->value<long long>();
  }
  std::optional<std::string> string(const std::string& key) {
    const toml::node* node = take(key);
    if (!node) return std::nullopt;
    if (!node->is_string()) fail_type(key, "a string");
    return node->value<std::string>();
  }
  std::optional<bool> boolean(const std::string& key) {
    const toml::node* node = take(key);
    if (!node) return std::nullopt;
    if (!node->is_boolean()) fail_type(key, "true or false");
    return node->value<bool>();
  }
  const toml::table* table(const std::string& key) {
    const toml::node* node = take(key);
    if (!node) return nullptr;
    if (!node->is_table()) fail_type(key, "a table");
    return node->as_table();
  }
  // Marks a key as known without reading it (handled elsewhere).
  const toml::node* take(const std::string& key) {
    used_.insert(key);
    return table_.get(key);
  }

  // Every key not taken is an error, listing the allowed ones.
  void finish() const {
    for (const auto& [key, node] : table_) {
      const std::string name(key.str());
      if (used_.count(name)) continue;
      std::string allowed;
      for (const auto& k : used_) allowed += (allowed.empty() ? "" : ", ") + k;
      throw InputError(fmt::format("{}: unknown key '{}{}' (allowed: {})", where(node), prefix(),
                                   name, allowed));
    }
  }

 private:
  std::string prefix() const { return section_.empty() ? "" : section_ + "."; }
  [[noreturn]] void fail_type(const std::string& key, const char* expected) const {
    throw InputError(fmt::format("{}: must be {}", where_key(key), expected));
  }

  const toml::table& table_;
  std::string file_;
  std::string section_;
  std::set<std::string> used_;
};

std::string resolve(const std::string& base_dir, const std::string& file) {
  const fs::path p(file);
  return (p.is_absolute() ? p : fs::path(base_dir) / p).lexically_normal().string();
}

// Array of tables under `key` ([[parameter]]), each checked to be a table.
std::vector<const toml::table*> table_array(TableReader& reader, const std::string& key) {
  std::vector<const toml::table*> tables;
  const toml::node* node = reader.take(key);
  if (!node) return tables;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables()) {
    throw InputError(
        fmt::format("{}: must be an array of tables ([[{}]])", reader.where_key(key), key));
  }
  for (const auto& element : *array) tables.push_back(element.as_table());
  return tables;
}

std::vector<SceneEntry> read_scenes(TableReader& top, const std::string& file,
                                    const std::string& base_dir) {
  std::vector<SceneEntry> scenes;
  const toml::node* node = top.take("scene");
  if (!node)
    throw InputError(fmt::format("{}: key 'scene' (the base scene file) is missing", file));
  if (node->is_string()) {
    scenes.push_back({"scene", resolve(base_dir, *node->value<std::string>()), top.where(*node)});
    return scenes;
  }
  for (const toml::table* t : table_array(top, "scene")) {
    TableReader reader(*t, file, "scene");
    SceneEntry entry;
    entry.where = reader.where();
    const auto name = reader.string("name");
    const auto scene_file = reader.string("file");
    reader.finish();
    if (!name || !scene_file) {
      throw InputError(fmt::format("{}: [[scene]] needs name and file", entry.where));
    }
    entry.name = *name;
    entry.path = resolve(base_dir, *scene_file);
    scenes.push_back(entry);
  }
  return scenes;
}

ParameterSpec read_parameter(const toml::table& t, const std::string& file) {
  TableReader reader(t, file, "parameter");
  ParameterSpec p;
  p.where = reader.where();
  const auto address = reader.string("address");
  if (!address) throw InputError(fmt::format("{}: [[parameter]] needs an address", p.where));
  p.address = *address;
  // A missing initial value is taken from the scene later; NaN marks it until then, so a NaN
  // written in the file must not reach it.
  const auto initial = reader.number("initial");
  if (initial && !std::isfinite(*initial)) {
    throw InputError(
        fmt::format("{}: must be a finite number, got {} (omit it to start from "
                    "the scene's value)",
                    reader.where_key("initial"), *initial));
  }
  p.initial = initial.value_or(std::nan(""));
  for (const char* bound : {"lower", "upper"}) {
    const auto value = reader.number(bound);
    if (value && std::isnan(*value)) {
      throw InputError(fmt::format("{}: must be a number or +-inf, got nan (omit it for no bound)",
                                   reader.where_key(bound)));
    }
    if (value) (std::string(bound) == "lower" ? p.lower : p.upper) = *value;
  }
  const auto scale = reader.number("scale");  // absent: derived from the initial value later
  if (scale && !(std::isfinite(*scale) && *scale > 0.0)) {
    throw InputError(fmt::format("{}: must be finite and > 0, got {} (omit it for |initial|)",
                                 reader.where_key("scale"), *scale));
  }
  p.scale = scale.value_or(0.0);
  p.fixed = reader.boolean("fixed").value_or(false);
  reader.finish();
  return p;
}

DataSpec read_data(const toml::table& t, const std::string& file, const std::string& base_dir) {
  TableReader reader(t, file, "data");
  DataSpec d;
  d.where = reader.where();
  const auto kind_name = reader.string("kind");
  const auto data_file = reader.string("file");
  if (!kind_name || !data_file) {
    throw InputError(fmt::format("{}: [[data]] needs kind and file", d.where));
  }
  const MeasurementKind kind = measurement_kind_from_string(*kind_name, reader.where_key("kind"));
  d.sigma = reader.number("sigma").value_or(0.0);
  d.weight = reader.number("weight").value_or(0.0);
  const auto travel = reader.number("travel_mm");
  const auto name = reader.string("name");
  d.scene = reader.string("scene").value_or("");
  reader.finish();

  d.measurement = read_measurement_csv(resolve(base_dir, *data_file), kind);
  d.measurement.name = name.value_or(fs::path(*data_file).stem().string());
  if (kind == MeasurementKind::kLoadTravel && travel) {
    throw InputError(fmt::format("{}: travel_mm applies to profiles, not to load_travel data",
                                 reader.where_key("travel_mm")));
  }
  if (kind != MeasurementKind::kLoadTravel) {
    if (!travel) {
      throw InputError(fmt::format("{}: {} data needs travel_mm (the punch travel of the profile)",
                                   d.where, *kind_name));
    }
    d.measurement.travel_mm = *travel;
  }
  return d;
}

void read_optimizer(const toml::table* t, const std::string& file, OptimizerSettings& o) {
  if (!t) return;
  TableReader r(*t, file, "optimizer");
  if (const auto method = r.string("method")) {
    if (*method == "levenberg_marquardt") {
      o.method = OptimizerMethod::kLevenbergMarquardt;
    } else if (*method == "global_then_local") {
      o.method = OptimizerMethod::kGlobalThenLocal;
    } else {
      throw InputError(fmt::format("{}: '{}' (levenberg_marquardt, global_then_local)",
                                   r.where_key("method"), *method));
    }
  }
  auto& ls = o.least_squares;
  ls.max_iterations = static_cast<int>(r.integer("max_iterations").value_or(ls.max_iterations));
  ls.function_tolerance = r.number("function_tolerance").value_or(ls.function_tolerance);
  ls.gradient_tolerance = r.number("gradient_tolerance").value_or(ls.gradient_tolerance);
  ls.parameter_tolerance = r.number("parameter_tolerance").value_or(ls.parameter_tolerance);
  if (const auto fd = r.string("fd")) {
    if (*fd == "central") {
      o.fd.method = FdMethod::kCentral;
    } else if (*fd == "ridders") {
      o.fd.method = FdMethod::kRidders;
    } else {
      throw InputError(fmt::format("{}: '{}' (central, ridders)", r.where_key("fd"), *fd));
    }
  }
  o.fd.relative_step = r.number("relative_step").value_or(o.fd.relative_step);
  o.fd.ridders_levels = static_cast<int>(r.integer("ridders_levels").value_or(o.fd.ridders_levels));
  o.threads = static_cast<int>(r.integer("threads").value_or(o.threads));
  o.global.algorithm = r.string("global_algorithm").value_or(o.global.algorithm);
  const auto seed = r.integer("seed");
  if (seed && *seed < 0) throw InputError(fmt::format("{}: must be >= 0", r.where_key("seed")));
  if (seed) o.global.seed = static_cast<unsigned long>(*seed);
  o.global.max_evaluations =
      static_cast<int>(r.integer("max_evaluations").value_or(o.global.max_evaluations));
  r.finish();
}

void read_uncertainty(const toml::table* t, const std::string& file, UncertaintyOptions& u) {
  if (!t) return;
  TableReader r(*t, file, "uncertainty");
  u.confidence = r.number("confidence").value_or(u.confidence);
  u.scale_by_residual_variance =
      r.boolean("scale_by_residual_variance").value_or(u.scale_by_residual_variance);
  u.rank_tolerance = r.number("rank_tolerance").value_or(u.rank_tolerance);
  u.correlation_threshold = r.number("correlation_threshold").value_or(u.correlation_threshold);
  u.relative_error_threshold =
      r.number("relative_error_threshold").value_or(u.relative_error_threshold);
  r.finish();
}

// [forward.set] values as command-line text: scene_from_table checks them later.
std::string value_text(const toml::node& node, const std::string& where) {
  if (node.is_integer()) return fmt::format("{}", *node.value<long long>());
  if (node.is_floating_point()) return fmt::format("{:.17g}", *node.value<double>());
  if (node.is_boolean()) return *node.value<bool>() ? "true" : "false";
  if (node.is_string()) return *node.value<std::string>();
  throw InputError(fmt::format("{}: must be a number, boolean or string", where));
}

void read_forward(const toml::table* t, const std::string& file, ForwardSettings& f) {
  if (!t) return;
  TableReader r(*t, file, "forward");
  f.tolerance = r.number("tolerance").value_or(f.tolerance);
  if (const toml::table* set = r.table("set")) {
    for (const auto& [key, node] : *set) {
      const std::string address(key.str());
      f.overrides.emplace_back(address,
                               value_text(node, fmt::format("{}:{}: key 'forward.set.{}'", file,
                                                            node.source().begin.line, address)));
    }
  }
  r.finish();
}

}  // namespace

CalibrationConfig load_calibration_config(const std::string& path) {
  const toml::table root = parse_toml_file(path, "calibration config");
  const std::string base_dir = fs::path(path).parent_path().string();
  CalibrationConfig config;
  config.path = path;
  TableReader top(root, path, "");
  config.scenes = read_scenes(top, path, base_dir);
  for (const toml::table* t : table_array(top, "parameter")) {
    config.parameters.push_back(read_parameter(*t, path));
  }
  for (const toml::table* t : table_array(top, "data")) {
    config.data.push_back(read_data(*t, path, base_dir));
  }
  read_optimizer(top.table("optimizer"), path, config.optimizer);
  read_uncertainty(top.table("uncertainty"), path, config.uncertainty);
  read_forward(top.table("forward"), path, config.forward);
  if (const toml::table* output = top.table("output")) {
    TableReader r(*output, path, "output");
    config.output_directory = r.string("directory").value_or(config.output_directory);
    config.plots = r.boolean("plots").value_or(config.plots);
    r.finish();
  }
  top.finish();
  // Initial values and scales that default to the scene are filled in by calibrate(); check
  // the rest now.
  CalibrationConfig check = config;
  for (auto& p : check.parameters) {
    if (std::isnan(p.initial)) {
      p.initial = std::isfinite(p.lower) ? p.lower : std::isfinite(p.upper) ? p.upper : 0.0;
    }
    if (p.scale == 0.0) p.scale = 1.0;
  }
  validate_calibration_config(check);
  return config;
}

void validate_calibration_config(const CalibrationConfig& config) {
  const std::string& file = config.path.empty() ? std::string("calibration") : config.path;
  if (config.scenes.empty()) throw InputError(fmt::format("{}: no scene given", file));
  std::set<std::string> scene_names;
  for (const auto& s : config.scenes) {
    if (!scene_names.insert(s.name).second) {
      throw InputError(fmt::format("{}: scene name '{}' used twice", s.where, s.name));
    }
  }

  if (config.parameters.empty()) throw InputError(fmt::format("{}: no [[parameter]]", file));
  std::set<std::string> addresses;
  int free = 0;
  for (const auto& p : config.parameters) {
    std::string why;
    if (!p.IsValid(&why)) throw InputError(why);
    if (!addresses.insert(p.address).second) {
      throw InputError(fmt::format("{}: parameter {} listed twice", p.where, p.address));
    }
    if (p.fixed) continue;
    ++free;
    if (config.optimizer.method == OptimizerMethod::kGlobalThenLocal &&
        !(std::isfinite(p.lower) && std::isfinite(p.upper))) {
      throw InputError(fmt::format(
          "{}: parameter {}: method global_then_local needs finite lower and upper bounds", p.where,
          p.address));
    }
  }
  if (free == 0) throw InputError(fmt::format("{}: every parameter is fixed", file));

  if (config.data.empty()) throw InputError(fmt::format("{}: no [[data]]", file));
  std::set<std::string> names;
  std::map<std::string, const DataSpec*> files;  // canonical file -> first data set reading it
  std::size_t points = 0;
  for (const auto& d : config.data) {
    std::error_code ec;
    if (fs::is_regular_file(d.measurement.file, ec)) {  // not for data made in code
      std::string key = fs::weakly_canonical(d.measurement.file, ec).string();
      if (ec) key = d.measurement.file;
      const auto [it, inserted] = files.emplace(key, &d);
      if (!inserted) {
        throw InputError(fmt::format(
            "{}: data set '{}' reads {}, which data set '{}' ({}) reads already: its points "
            "would count twice",
            d.where, d.measurement.name, d.measurement.file, it->second->measurement.name,
            it->second->where));
      }
    }
    const Measurement& m = d.measurement;
    if (m.x.empty()) throw InputError(fmt::format("{}: data set '{}' is empty", d.where, m.name));
    if (m.x.size() != m.y.size() ||
        !(m.point_sigma.empty() || m.point_sigma.size() == m.x.size())) {
      throw InputError(
          fmt::format("{}: data set '{}' has columns of different lengths", d.where, m.name));
    }
    points += m.x.size();
    if (m.name.empty() || m.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQR"
                                                   "STUVWXYZ0123456789_-.") != std::string::npos) {
      throw InputError(fmt::format(
          "{}: data set name '{}' must use only letters, digits, _ - . (it names fit_<name>.csv)",
          d.where, m.name));
    }
    if (!names.insert(m.name).second) {
      throw InputError(
          fmt::format("{}: data set name '{}' used twice (set name = ...)", d.where, m.name));
    }
    if (d.sigma < 0.0 || d.weight < 0.0 || !std::isfinite(d.sigma) || !std::isfinite(d.weight)) {
      throw InputError(fmt::format("{}: sigma and weight must be finite and > 0", d.where));
    }
    if (d.sigma > 0.0 && d.weight > 0.0) {
      throw InputError(fmt::format("{}: give sigma or weight, not both", d.where));
    }
    if (d.sigma == 0.0 && d.weight == 0.0 && m.point_sigma.empty()) {
      throw InputError(fmt::format(
          "{}: data set '{}' needs sigma (its standard deviation, in N or strain), weight, or a "
          "sigma column: residuals of different quantities must be scaled to be comparable",
          d.where, m.name));
    }
    if (m.x.front() < 0.0) {
      throw InputError(fmt::format("{}: data set '{}': {} must be >= 0", d.where, m.name,
                                   abscissa_name(m.kind)));
    }
    if (m.kind != MeasurementKind::kLoadTravel && !(m.travel_mm > 0.0)) {
      throw InputError(fmt::format("{}: data set '{}': travel_mm must be > 0", d.where, m.name));
    }
    if (config.scenes.size() > 1 ? !scene_names.count(d.scene)
                                 : !(d.scene.empty() || scene_names.count(d.scene))) {
      throw InputError(
          fmt::format("{}: data set '{}': scene '{}' is not one of the [[scene]] "
                      "names",
                      d.where, m.name, d.scene));
    }
  }
  if (points < static_cast<std::size_t>(free)) {
    throw InputError(
        fmt::format("{}: {} data points cannot determine {} free parameters", file, points, free));
  }

  std::string why;
  if (!config.optimizer.least_squares.IsValid(&why) || !config.optimizer.fd.IsValid(&why) ||
      !config.uncertainty.IsValid(&why) ||
      (config.optimizer.method == OptimizerMethod::kGlobalThenLocal &&
       !config.optimizer.global.IsValid(&why))) {
    throw InputError(fmt::format("{}: {}", file, why));
  }
  if (config.optimizer.threads < 1 || config.optimizer.threads > 256) {
    throw InputError(fmt::format("{}: threads must be in [1, 256]", file));
  }
}

}  // namespace vs
