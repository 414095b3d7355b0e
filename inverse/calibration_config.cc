#include "calibration_config.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "calibration_keys.h"
#include "core/error.h"
#include "scene/did_you_mean.h"
#include "scene/scene_diagnostics.h"
#include "scene/text_checks.h"
#include "scene/toml_guard.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{}", x);
}

// Reads one TOML table against the declared keys of its section (calibration_keys.cc): types,
// ranges and choices are checked here, and keys that are not declared are errors with a
// did-you-mean. `subsections` are tables the caller reads itself (the top level's [optimizer]...).
class TableReader {
 public:
  TableReader(const toml::table& table, std::string file, std::string section,
              std::vector<std::string_view> subsections = {})
      : table_(table),
        file_(std::move(file)),
        section_(std::move(section)),
        subsections_(std::move(subsections)) {}

  std::string where(const toml::node& node) const {
    return fmt::format("{}:{}", file_, node.source().begin.line);
  }
  std::string where() const { return where(table_); }
  std::string where_key(const std::string& key) const {
    const toml::node* node = table_.get(key);
    return fmt::format("{}: key '{}{}'", node ? where(*node) : where(), prefix(), key);
  }

  std::optional<double> number(const std::string& key) {
    const toml::node* node = take(key, KeyType::kFloat);
    if (!node) return std::nullopt;
    if (!node->is_number()) fail_type(key, "a number", *node);
    const double x = *node->value<double>();
    if (std::isnan(x))
      throw InputError(fmt::format("{}: must be a number, got nan", where_key(key)));
    check_range(key, x);
    return x;
  }
  std::optional<long long> integer(const std::string& key) {
    const toml::node* node = take(key, KeyType::kInt);
    if (!node) return std::nullopt;
    if (!node->is_integer()) fail_type(key, "an integer", *node);
    const auto i = *node->value<long long>();
    check_range(key, static_cast<double>(i));
    return i;
  }
  std::optional<std::string> string(const std::string& key) {
    const toml::node* node = take(key, KeyType::kString);
    if (!node) return std::nullopt;
    if (!node->is_string()) fail_type(key, "a string", *node);
    return node->value<std::string>();
  }
  // An enum key: one of the declared choices.
  std::optional<std::string> choice(const std::string& key) {
    const toml::node* node = take(key, KeyType::kEnum);
    if (!node) return std::nullopt;
    if (!node->is_string()) fail_type(key, "a string", *node);
    const std::string value = *node->value<std::string>();
    const KeySpec& spec = declared(key);
    for (std::string_view c : spec.choices) {
      if (c == value) return value;
    }
    std::string allowed;
    for (std::string_view c : spec.choices)
      allowed += (allowed.empty() ? "" : ", ") + std::string(c);
    const std::string guess = closest_match(value, spec.choices);
    throw InputError(fmt::format("{}: '{}' is not one of {}{}", where_key(key), value, allowed,
                                 guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
  }
  // An array of strings.
  std::optional<std::vector<std::string>> strings(const std::string& key) {
    const toml::node* node = take(key, KeyType::kStringArray);
    if (!node) return std::nullopt;
    const toml::array* a = node->as_array();
    if (!a) fail_type(key, "an array of strings", *node);
    std::vector<std::string> out;
    for (const toml::node& item : *a) {
      if (!item.is_string()) fail_type(key, "an array of strings", *node);
      out.push_back(*item.value<std::string>());
    }
    return out;
  }
  std::optional<bool> boolean(const std::string& key) {
    const toml::node* node = take(key, KeyType::kBool);
    if (!node) return std::nullopt;
    if (!node->is_boolean()) fail_type(key, "true or false", *node);
    return node->value<bool>();
  }
  // A table-valued key ([forward.set], data columns) or, with `subsection`, a section table.
  const toml::table* table(const std::string& key) {
    const bool subsection =
        std::find(subsections_.begin(), subsections_.end(), key) != subsections_.end();
    const toml::node* node = subsection ? take(key) : take(key, KeyType::kTable);
    if (!node) return nullptr;
    if (!node->is_table()) fail_type(key, "a table", *node);
    return node->as_table();
  }
  // A key read without a type check (its reader checks it): a declared key or a subsection.
  const toml::node* take(const std::string& key) {
    const bool subsection =
        std::find(subsections_.begin(), subsections_.end(), key) != subsections_.end();
    if (!subsection) declared(key);
    used_.insert(key);
    return table_.get(key);
  }

  // Every key not taken is an error, suggesting the closest declared one.
  void finish() const {
    for (const auto& [key, node] : table_) {
      const std::string name(key.str());
      if (used_.count(name)) continue;
      std::vector<std::string_view> candidates = subsections_;
      for (const KeySpec& k : calibration_keys()) {
        if (k.section == section_) candidates.push_back(k.name);
      }
      const std::string guess = closest_match(name, candidates);
      std::string allowed;
      for (std::string_view c : candidates)
        allowed += (allowed.empty() ? "" : ", ") + std::string(c);
      throw InputError(fmt::format(
          "{}: unknown key '{}{}' ({})", where(node), prefix(), show_invisible(name),
          guess.empty() ? "allowed: " + allowed : fmt::format("did you mean '{}'?", guess)));
    }
  }

 private:
  std::string prefix() const { return section_.empty() ? "" : section_ + "."; }

  const KeySpec& declared(const std::string& key) const {
    const KeySpec* spec = find_calibration_key(section_, key);
    if (spec == nullptr) {
      throw std::logic_error(fmt::format("calibration key '{}{}' is not declared", prefix(), key));
    }
    return *spec;
  }

  const toml::node* take(const std::string& key, KeyType type) {
    if (declared(key).type != type) {
      throw std::logic_error(
          fmt::format("calibration key '{}{}' read as another type", prefix(), key));
    }
    used_.insert(key);
    return table_.get(key);
  }

  void check_range(const std::string& key, double x) const {
    const KeySpec& spec = declared(key);
    if (spec.range.contains(x)) return;
    const bool beyond_resource_bound =
        !spec.bound_reason.empty() &&
        (spec.bound_reason_below ? x < spec.range.lo : x > spec.range.hi);
    throw InputError(fmt::format(
        "{}: {} is out of range {}{}", where_key(key), number_text(x), spec.range.text(),
        beyond_resource_bound ? ": " + std::string(spec.bound_reason) : ""));
  }

  [[noreturn]] void fail_type(const std::string& key, const char* expected,
                              const toml::node& node) const {
    throw InputError(
        fmt::format("{}: must be {}, got {}", where_key(key), expected, toml_type_name(node)));
  }

  const toml::table& table_;
  std::string file_;
  std::string section_;
  std::vector<std::string_view> subsections_;
  std::set<std::string> used_;
};

// The data set of this name, or null.
const DataSpec* find_data_set(const std::vector<DataSpec>& data, const std::string& name) {
  const auto d = std::find_if(data.begin(), data.end(),
                              [&name](const DataSpec& x) { return x.measurement.name == name; });
  return d == data.end() ? nullptr : &*d;
}

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
  p.lower = reader.number("lower").value_or(p.lower);  // NaN is out of the declared range
  p.upper = reader.number("upper").value_or(p.upper);
  p.scale = reader.number("scale").value_or(0.0);  // 0: derived from the initial value later
  p.fixed = reader.boolean("fixed").value_or(false);
  reader.finish();  // a misspelt key first: "adress" is more useful than "needs an address"
  if (!address) throw InputError(fmt::format("{}: [[parameter]] needs an address", p.where));
  p.address = *address;
  return p;
}

DataSpec read_data(const toml::table& t, const std::string& file, const std::string& base_dir) {
  TableReader reader(t, file, "data");
  DataSpec d;
  d.where = reader.where();
  const auto kind_name = reader.choice("kind");
  const auto data_file = reader.string("file");
  d.sigma = reader.number("sigma").value_or(0.0);
  d.weight = reader.number("weight").value_or(0.0);
  d.relative_sigma = reader.number("relative_sigma").value_or(d.relative_sigma);
  const auto travel = reader.number("travel_mm");
  const auto name = reader.string("name");
  d.scene = reader.string("scene").value_or("");
  const auto source = reader.string("source");
  const auto shape_only = reader.boolean("shape_only");
  MeasurementColumns columns;
  if (const toml::table* mapping = reader.table("columns")) {
    for (const auto& [key, node] : *mapping) {
      if (!node.is_string()) {
        throw InputError(
            fmt::format("{}:{}: key 'data.columns.{}': must be a string (the "
                        "column's header in the file), got {}",
                        file, node.source().begin.line, key.str(), toml_type_name(node)));
      }
      columns.emplace_back(std::string(key.str()), *node.value<std::string>());
    }
    if (columns.empty()) {
      throw InputError(
          fmt::format("{}: must map at least one column", reader.where_key("columns")));
    }
  }
  reader.finish();
  if (!kind_name || !data_file) {
    throw InputError(fmt::format("{}: [[data]] needs kind and file", d.where));
  }
  const MeasurementKind kind = measurement_kind_from_string(*kind_name, reader.where_key("kind"));

  if (source && source->find_first_not_of(" \t") == std::string::npos) {
    throw InputError(fmt::format("{}: must not be empty", reader.where_key("source")));
  }
  if (shape_only && kind != MeasurementKind::kCupHeightProfile) {
    throw InputError(fmt::format("{}: shape_only applies to cup_height_profile data, not to {}",
                                 reader.where_key("shape_only"), *kind_name));
  }
  d.shape_only = shape_only.value_or(false);
  try {
    MeasurementReadOptions read_options;
    read_options.columns = columns;
    read_options.source = source.value_or("");
    d.measurement = read_measurement_file(resolve(base_dir, *data_file), kind, read_options);
  } catch (const InputError& e) {
    if (columns.empty()) throw;
    throw InputError(
        fmt::format("{} (columns mapped at {})", e.what(), reader.where_key("columns")));
  }
  d.measurement.name = name.value_or(fs::path(*data_file).stem().string());
  if (!is_strain_profile(kind) && travel) {
    throw InputError(fmt::format("{}: travel_mm applies to strain profiles, not to {} data{}",
                                 reader.where_key("travel_mm"), *kind_name,
                                 kind == MeasurementKind::kCupHeightProfile
                                     ? " (compared with the run's final rim profile)"
                                     : ""));
  }
  if (is_strain_profile(kind)) {
    const double in_file = d.measurement.travel_mm;  // vshell strains files state it
    if (travel && in_file > 0.0 && std::abs(*travel - in_file) > 1e-6 * std::max(1.0, in_file)) {
      throw InputError(fmt::format("{}: travel_mm = {} but {} was written at {} mm",
                                   reader.where_key("travel_mm"), *travel, d.measurement.file,
                                   in_file));
    }
    if (!travel && !(in_file > 0.0)) {
      throw InputError(fmt::format("{}: {} data needs travel_mm (the punch travel of the profile)",
                                   d.where, *kind_name));
    }
    if (travel) d.measurement.travel_mm = *travel;
  }
  return d;
}

void read_optimizer(const toml::table* t, const std::string& file, OptimizerSettings& o) {
  if (!t) return;
  TableReader r(*t, file, "optimizer");
  if (const auto method = r.choice("method")) {
    o.method = *method == "global_then_local" ? OptimizerMethod::kGlobalThenLocal
                                              : OptimizerMethod::kLevenbergMarquardt;
  }
  auto& ls = o.least_squares;
  ls.max_iterations = static_cast<int>(r.integer("max_iterations").value_or(ls.max_iterations));
  ls.function_tolerance = r.number("function_tolerance").value_or(ls.function_tolerance);
  ls.gradient_tolerance = r.number("gradient_tolerance").value_or(ls.gradient_tolerance);
  ls.parameter_tolerance = r.number("parameter_tolerance").value_or(ls.parameter_tolerance);
  if (const auto fd = r.choice("fd")) {
    o.fd.method = *fd == "ridders" ? FdMethod::kRidders : FdMethod::kCentral;
  }
  o.fd.relative_step = r.number("relative_step").value_or(o.fd.relative_step);
  o.fd.ridders_levels = static_cast<int>(r.integer("ridders_levels").value_or(o.fd.ridders_levels));
  o.noise_floor_factor = r.number("noise_floor_factor").value_or(o.noise_floor_factor);
  ls.active_set = r.boolean("active_set").value_or(ls.active_set);
  o.threads = static_cast<int>(r.integer("threads").value_or(o.threads));
  o.global.algorithm = r.choice("global_algorithm").value_or(o.global.algorithm);
  if (const auto seed = r.integer("seed")) o.global.seed = static_cast<unsigned long>(*seed);
  o.global.max_evaluations =
      static_cast<int>(r.integer("max_evaluations").value_or(o.global.max_evaluations));
  o.global.grid_points = static_cast<int>(r.integer("grid_points").value_or(o.global.grid_points));
  o.global.grid_half_width = r.number("grid_half_width").value_or(o.global.grid_half_width);
  o.global.surface_rounds =
      static_cast<int>(r.integer("surface_rounds").value_or(o.global.surface_rounds));
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
  u.lack_of_fit.significance =
      r.number("lack_of_fit_significance").value_or(u.lack_of_fit.significance);
  u.lack_of_fit.min_rms = r.number("lack_of_fit_min_rms").value_or(u.lack_of_fit.min_rms);
  u.lack_of_fit.min_resolutions =
      r.number("lack_of_fit_min_resolutions").value_or(u.lack_of_fit.min_resolutions);
  r.finish();
}

// [forward.set] values as command-line text: scene_from_table checks them later.
std::string value_text(const toml::node& node, const std::string& where) {
  if (node.is_integer()) return fmt::format("{}", *node.value<long long>());
  if (node.is_floating_point()) return fmt::format("{}", *node.value<double>());
  if (node.is_boolean()) return *node.value<bool>() ? "true" : "false";
  if (node.is_string()) return *node.value<std::string>();
  throw InputError(fmt::format("{}: must be a number, boolean or string", where));
}

// A table of scene edits ([forward.set], model_form.set) as (address, value text) pairs.
std::vector<std::pair<std::string, std::string>> scene_edits(const toml::table& set,
                                                             const std::string& file,
                                                             const std::string& key_prefix) {
  std::vector<std::pair<std::string, std::string>> edits;
  for (const auto& [key, node] : set) {
    const std::string address(key.str());
    edits.emplace_back(
        address, value_text(node, fmt::format("{}:{}: key '{}.{}'", file, node.source().begin.line,
                                              key_prefix, address)));
  }
  return edits;
}

void read_forward(const toml::table* t, const std::string& file, ForwardSettings& f) {
  if (!t) return;
  TableReader r(*t, file, "forward");
  f.tolerance = r.number("tolerance").value_or(f.tolerance);
  if (const toml::table* set = r.table("set")) {
    for (auto& edit : scene_edits(*set, file, "forward.set")) f.overrides.push_back(edit);
  }
  r.finish();
}

ModelFormSpec read_model_form(const toml::table& t, const std::string& file) {
  TableReader r(t, file, "model_form");
  ModelFormSpec form;
  form.where = r.where();
  const auto name = r.string("name");
  const toml::table* set = r.table("set");
  const auto drop = r.strings("drop_data");
  form.discrepancy = r.strings("discrepancy");
  r.finish();
  if (!name) throw InputError(fmt::format("{}: [[model_form]] needs a name", form.where));
  if ((!set || set->empty()) && (!drop || drop->empty()) && !form.discrepancy) {
    throw InputError(fmt::format(
        "{}: [[model_form]] '{}' needs set = {{ \"address\" = value, ... }} (the scene edits of "
        "the alternative model), drop_data = [\"data set\", ...] (the data it leaves out) or "
        "discrepancy = [\"source\", ...] (the discrepancy sources it keeps)",
        form.where, *name));
  }
  form.name = *name;
  if (set) form.overrides = scene_edits(*set, file, "model_form.set");
  if (drop) form.drop_data = *drop;
  return form;
}

// [[discrepancy]]: the reference files are read with the kinds of the data sets they cover.
DiscrepancySpec read_discrepancy(const toml::table& t, const std::string& file,
                                 const std::string& base_dir, const std::vector<DataSpec>& data) {
  TableReader r(t, file, "discrepancy");
  DiscrepancySpec spec;
  spec.where = r.where();
  const auto name = r.string("name");
  const toml::table* set = r.table("set");
  const toml::table* files = r.table("files");
  r.finish();
  if (!name || name->empty()) {
    throw InputError(fmt::format("{}: [[discrepancy]] needs a name", spec.where));
  }
  spec.name = *name;
  if (!set || set->empty()) {
    throw InputError(fmt::format(
        "{}: [[discrepancy]] '{}' needs set = {{ \"address\" = value, ... }}: the parameters "
        "(every free one) the reference was computed at",
        spec.where, spec.name));
  }
  spec.set = scene_edits(*set, file, "discrepancy.set");
  if (!files || files->empty()) {
    throw InputError(fmt::format(
        "{}: [[discrepancy]] '{}' needs files = {{ <data set name> = \"reference.csv\", ... }}",
        spec.where, spec.name));
  }
  for (const auto& [key, node] : *files) {
    const std::string data_name(key.str());
    const std::string where =
        fmt::format("{}:{}: key 'discrepancy.files.{}'", file, node.source().begin.line, data_name);
    if (!node.is_string()) {
      throw InputError(fmt::format("{}: must be a string (the reference's file), got {}", where,
                                   toml_type_name(node)));
    }
    const DataSpec* d = find_data_set(data, data_name);
    if (d == nullptr) {
      std::string known;
      for (const DataSpec& x : data) known += (known.empty() ? "" : ", ") + x.measurement.name;
      throw InputError(fmt::format("{}: '{}' is not a data set of this config (data sets: {})",
                                   where, data_name, known));
    }
    Measurement reference = read_measurement_file(resolve(base_dir, *node.value<std::string>()),
                                                  d->measurement.kind, {});
    if (is_strain_profile(reference.kind) && reference.travel_mm > 0.0 &&
        std::abs(reference.travel_mm - d->measurement.travel_mm) >
            1e-6 * std::max(1.0, d->measurement.travel_mm)) {
      throw InputError(fmt::format(
          "{}: {} is a profile at {} mm of punch travel, data set '{}' one at {} mm", where,
          reference.file, reference.travel_mm, data_name, d->measurement.travel_mm));
    }
    reference.name = data_name;
    reference.travel_mm = d->measurement.travel_mm;
    spec.references.emplace_back(data_name, std::move(reference));
  }
  return spec;
}

}  // namespace

CalibrationConfig load_calibration_config(const std::string& path) {
  const toml::table root = parse_toml_file(path, "calibration config");
  const std::string base_dir = fs::path(path).parent_path().string();
  CalibrationConfig config;
  config.path = path;
  TableReader top(root, path, "",
                  {"parameter", "data", "optimizer", "uncertainty", "model_form", "discrepancy",
                   "forward", "output"});
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
  for (const toml::table* t : table_array(top, "model_form")) {
    config.model_forms.push_back(read_model_form(*t, path));
  }
  for (const toml::table* t : table_array(top, "discrepancy")) {
    config.discrepancies.push_back(read_discrepancy(*t, path, base_dir, config.data));
  }
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

DataSigma data_set_sigma(const DataSpec& d) {
  const Measurement& m = d.measurement;
  const std::string unit = m.kind == MeasurementKind::kLoadTravel         ? " N"
                           : m.kind == MeasurementKind::kCupHeightProfile ? " mm"
                                                                          : "";
  if (!m.point_sigma.empty()) return {0.0, "sigma per point (the file's sigma column)"};
  if (d.sigma > 0.0) return {d.sigma, fmt::format("sigma = {:.4g}{} (given)", d.sigma, unit)};
  if (d.weight > 0.0) return {0.0, fmt::format("weight = {:.4g} (given)", d.weight)};
  double range = 0.0;
  if (!m.y.empty()) {
    const auto [lo, hi] = std::minmax_element(m.y.begin(), m.y.end());
    range = *hi - *lo;
  }
  if (!(range > 0.0) || !std::isfinite(range)) {
    throw InputError(fmt::format(
        "{}: data set '{}' gives no sigma, weight or sigma column, and its measured values do "
        "not vary, so the default sigma (relative_sigma x their range) would be 0: set sigma "
        "(its standard deviation, in N, strain or mm) or weight",
        d.where, m.name));
  }
  const double sigma = d.relative_sigma * range;
  return {sigma, fmt::format("sigma = {:.4g}{} (default: {:g} % of the measured range {:.4g}{}; "
                             "set sigma to state it)",
                             sigma, unit, 100.0 * d.relative_sigma, range, unit)};
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
  if (config.optimizer.method == OptimizerMethod::kGlobalThenLocal &&
      config.optimizer.global.algorithm == "surface") {
    const long needed = surface_evaluations(config.optimizer.global, free);
    if (needed > config.optimizer.global.max_evaluations) {
      const int rounds = config.optimizer.global.surface_rounds;
      throw InputError(fmt::format(
          "{}: global_algorithm \"surface\" needs {}grid_points^{} + 1{} = {} evaluations, more "
          "than max_evaluations = {}",
          file, rounds > 1 ? fmt::format("{} (", rounds) : "", free, rounds > 1 ? ")" : "", needed,
          config.optimizer.global.max_evaluations));
    }
  }

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
    data_set_sigma(d);  // a relative default needs a curve that varies
    if (m.x.front() < 0.0) {
      throw InputError(fmt::format("{}: data set '{}': {} must be >= 0", d.where, m.name,
                                   abscissa_name(m.kind)));
    }
    if (is_strain_profile(m.kind) && !(m.travel_mm > 0.0)) {
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
  std::set<std::string> form_names;
  for (const auto& form : config.model_forms) {
    if (!form_names.insert(form.name).second) {
      throw InputError(fmt::format("{}: model_form name '{}' used twice", form.where, form.name));
    }
    if (form.overrides.empty() && form.drop_data.empty() && !form.discrepancy) {
      throw InputError(
          fmt::format("{}: model_form '{}' has no scene edits (set), drops no data and keeps every "
                      "discrepancy source",
                      form.where, form.name));
    }
    for (const std::string& source : form.discrepancy.value_or(std::vector<std::string>{})) {
      const bool known = std::any_of(config.discrepancies.begin(), config.discrepancies.end(),
                                     [&](const DiscrepancySpec& x) { return x.name == source; });
      if (!known) {
        throw InputError(fmt::format(
            "{}: model_form '{}': discrepancy names '{}', which is not a [[discrepancy]] of "
            "this config",
            form.where, form.name, source));
      }
    }
    // The data the alternative drops must exist, and what it keeps still determine the free
    // parameters (free >= 1, so keeping nothing fails too).
    for (const std::string& name : form.drop_data) {
      if (find_data_set(config.data, name) == nullptr) {
        throw InputError(
            fmt::format("{}: model_form '{}': drop_data names '{}', which is not a "
                        "data set of this config",
                        form.where, form.name, name));
      }
    }
    std::size_t kept = 0;
    for (const DataSpec& d : config.data) {
      if (!form.drops(d.measurement.name)) kept += d.measurement.x.size();
    }
    if (kept < static_cast<std::size_t>(free)) {
      throw InputError(
          fmt::format("{}: model_form '{}': the data it keeps ({} points) cannot "
                      "determine {} free parameters",
                      form.where, form.name, kept, free));
    }
  }
  std::set<std::string> source_names;
  for (const DiscrepancySpec& source : config.discrepancies) {
    if (!source_names.insert(source.name).second) {
      throw InputError(
          fmt::format("{}: discrepancy name '{}' used twice", source.where, source.name));
    }
    // The forward model is run at the reference's parameters: each free one must be given, as a
    // number.
    std::vector<std::string> missing;
    for (const ParameterSpec& p : config.parameters) {
      const auto entry = std::find_if(source.set.begin(), source.set.end(),
                                      [&p](const auto& edit) { return edit.first == p.address; });
      if (entry == source.set.end()) {
        if (!p.fixed) missing.push_back(p.address);
        continue;
      }
      char* end = nullptr;
      const double value = std::strtod(entry->second.c_str(), &end);
      if (end == entry->second.c_str() || *end != '\0' || !std::isfinite(value)) {
        throw InputError(fmt::format("{}: discrepancy '{}': set {} = {} must be a number",
                                     source.where, source.name, p.address, entry->second));
      }
    }
    if (!missing.empty()) {
      std::string list;
      for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
      throw InputError(fmt::format(
          "{}: discrepancy '{}': set must give every free parameter at the value the reference "
          "was computed with (missing: {})",
          source.where, source.name, list));
    }
    // The reference must span the data it corrects (no extrapolation).
    for (const auto& [data_name, reference] : source.references) {
      const DataSpec* d = find_data_set(config.data, data_name);
      if (d == nullptr) {
        throw InputError(fmt::format("{}: discrepancy '{}': '{}' is not a data set of this config",
                                     source.where, source.name, data_name));
      }
      const Measurement& m = d->measurement;
      const double slack = 1e-9 * std::max(1.0, std::abs(m.x.back()));
      if (reference.x.front() > m.x.front() + slack || reference.x.back() < m.x.back() - slack) {
        throw InputError(fmt::format(
            "{}: discrepancy '{}': {} spans {} = {} to {}, but data set '{}' needs {} to {} (a "
            "reference is interpolated, never extrapolated)",
            source.where, source.name, reference.file, abscissa_name(m.kind), reference.x.front(),
            reference.x.back(), data_name, m.x.front(), m.x.back()));
      }
    }
  }
  if (!(config.optimizer.noise_floor_factor >= 0.0) ||
      !std::isfinite(config.optimizer.noise_floor_factor)) {
    throw InputError(fmt::format("{}: noise_floor_factor must be finite and >= 0", file));
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
