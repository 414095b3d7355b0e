#include "scene/key_value.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

#include "scene/did_you_mean.h"

namespace vs {

namespace {

std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{}", x);
}

std::string unit_suffix(const KeySpec& key) {
  return key.unit.empty() ? "" : fmt::format(" {}", key.unit);
}

std::string quoted_list(const std::vector<std::string_view>& choices, bool quote) {
  std::string out;
  for (std::string_view c : choices) {
    if (!out.empty()) out += ", ";
    out += quote ? fmt::format("\"{}\"", c) : std::string(c);
  }
  return out;
}

void check_range(const KeySpec& key, double x, const toml::node& node, const std::string& address,
                 const std::string& source) {
  // A finite Coulomb coefficient far above any sliding contact is a no-slip contact written as a
  // number: the regularised friction law then makes every step stiff and the steps collapse
  // (measured, 3D ex4a n = 4, friction 1e6: 115 steps, 123 cut-backs, 382 s, stopped at 2.8 mm
  // without saying why). The sticking contact treats it exactly.
  if (key.sticking_alias && std::isfinite(x) && x > kMaxCoulombCoefficient) {
    fail_at(source, node.source(),
            fmt::format("{} = {} is above {}: no sliding contact has such a coefficient; use "
                        "\"sticking\" (no slip, treated exactly) instead",
                        address, number_text(x), number_text(kMaxCoulombCoefficient)));
  }
  if (!key.range.contains(x)) {
    const bool beyond_resource_bound =
        key.type != KeyType::kFloatArray && !key.bound_reason.empty() &&
        (key.bound_reason_below ? x < key.range.lo : x > key.range.hi);
    fail_at(source, node.source(),
            fmt::format("{} = {} is out of range {}{}{}", address, number_text(x), key.range.text(),
                        unit_suffix(key),
                        beyond_resource_bound ? ": " + std::string(key.bound_reason) : ""));
  }
}

double read_float(const KeySpec& key, const toml::node& node, const std::string& address,
                  const std::string& source) {
  if (key.sticking_alias && node.is_string()) {
    const std::string& s = node.as_string()->get();
    if (s == "sticking") return std::numeric_limits<double>::infinity();
    fail_at(source, node.source(),
            fmt::format("{} = \"{}\": expected a number, inf or \"sticking\"", address, s));
  }
  const double x = read_number(node, address, source);
  check_range(key, x, node, address, source);
  return x;
}

int read_int(const KeySpec& key, const toml::node& node, const std::string& address,
             const std::string& source) {
  if (!node.is_integer()) {
    fail_at(source, node.source(),
            fmt::format("{}: expected an integer, got {}", address, toml_type_name(node)));
  }
  const std::int64_t i = node.as_integer()->get();
  const double x = static_cast<double>(i);
  check_range(key, x, node, address, source);
  if (i > std::numeric_limits<int>::max() || i < std::numeric_limits<int>::min()) {
    fail_at(source, node.source(), fmt::format("{} = {} is too large", address, i));
  }
  if (!key.choices.empty()) {
    const std::string text = std::to_string(i);
    bool allowed = false;
    for (std::string_view c : key.choices) allowed = allowed || c == text;
    if (!allowed) {
      fail_at(source, node.source(),
              fmt::format("{} = {} is not allowed; expected one of {}", address, i,
                          quoted_list(key.choices, false)));
    }
  }
  return static_cast<int>(i);
}

bool read_bool(const toml::node& node, const std::string& address, const std::string& source) {
  if (!node.is_boolean()) {
    fail_at(source, node.source(),
            fmt::format("{}: expected true or false, got {}", address, toml_type_name(node)));
  }
  return node.as_boolean()->get();
}

std::vector<double> read_float_array(const KeySpec& key, const toml::node& node,
                                     const std::string& address, SceneSourceMap& where) {
  const toml::array* array = node.as_array();
  if (array == nullptr) {
    fail_at(where.source(), node.source(),
            fmt::format("{}: expected an array of numbers, got {}", address, toml_type_name(node)));
  }
  if (key.max_items > 0 && array->size() > key.max_items) {
    fail_at(where.source(), node.source(),
            fmt::format("{} has {} values, more than the {} allowed{}", address, array->size(),
                        key.max_items,
                        key.bound_reason.empty() ? "" : ": " + std::string(key.bound_reason)));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string element_address = fmt::format("{}[{}]", address, i);
    values.push_back(read_float(key, element, element_address, where.source()));
    where.add(element_address, element.source());
  }
  return values;
}

}  // namespace

double read_number(const toml::node& node, const std::string& address, const std::string& source) {
  if (node.is_floating_point()) return node.as_floating_point()->get();
  if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
  fail_at(source, node.source(),
          fmt::format("{}: expected a number, got {}", address, toml_type_name(node)));
}

std::string read_string(const KeySpec& key, const toml::node& node, const std::string& address,
                        const std::string& source) {
  if (!node.is_string()) {
    fail_at(source, node.source(),
            fmt::format("{}: expected a string, got {}", address, toml_type_name(node)));
  }
  const std::string& s = node.as_string()->get();
  if (key.identifier) {
    bool valid = !s.empty();
    for (char c : s) {
      valid = valid && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '_');
    }
    if (!valid) {
      fail_at(
          source, node.source(),
          fmt::format("{} = \"{}\" is not a valid name: use letters, digits and _", address, s));
    }
  }
  return s;
}

std::string read_choice(const KeySpec& key, const toml::node& node, const std::string& address,
                        const std::string& source) {
  const std::string s = read_string(key, node, address, source);
  for (std::string_view c : key.choices) {
    if (c == s) return s;
  }
  const std::string guess = closest_match(s, key.choices);
  fail_at(source, node.source(),
          fmt::format("{} = \"{}\" is not supported; expected {}{}", address, s,
                      key.choices.size() == 1 ? quoted_list(key.choices, true)
                                              : "one of " + quoted_list(key.choices, true),
                      guess.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", guess)));
}

void store_key_value(const KeySpec& key, const toml::node& node, const std::string& address,
                     SceneSourceMap& where, Scene& scene, ToolSpec& tool) {
  where.add(address, node.source());
  const std::string& source = where.source();
  const KeyField& f = key.field;
  switch (key.type) {
    case KeyType::kFloat:
      if (f.number) f.number(scene, tool) = read_float(key, node, address, source);
      return;
    case KeyType::kInt:
      if (f.integer) f.integer(scene, tool) = read_int(key, node, address, source);
      return;
    case KeyType::kBool:
      if (f.flag) f.flag(scene, tool) = read_bool(node, address, source);
      return;
    case KeyType::kString:
      if (f.text) f.text(scene, tool) = read_string(key, node, address, source);
      return;
    case KeyType::kEnum: {
      const std::string s = read_choice(key, node, address, source);
      for (std::size_t i = 0; i < key.choices.size(); ++i) {
        if (key.choices[i] == s && f.set_choice) f.set_choice(scene, tool, static_cast<int>(i));
      }
      return;
    }
    case KeyType::kFloatArray:
      if (f.numbers) f.numbers(scene, tool) = read_float_array(key, node, address, where);
      return;
    case KeyType::kPairArray:
    case KeyType::kStringArray:
    case KeyType::kTable:
      return;
  }
}

}  // namespace vs
