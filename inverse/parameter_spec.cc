#include "parameter_spec.h"

#include <fmt/format.h>

#include <cmath>

namespace vs {

bool ParameterSpec::IsValid(std::string* why) const {
  auto fail = [&](const std::string& message) {
    if (why) *why = fmt::format("{}: parameter {}: {}", where, address, message);
    return false;
  };
  if (!(scale > 0.0) || !std::isfinite(scale)) return fail("scale must be finite and > 0");
  if (!std::isfinite(initial)) return fail("initial value must be finite");
  if (std::isnan(lower) || std::isnan(upper)) return fail("bounds must not be NaN");
  if (!(lower <= initial && initial <= upper)) {
    return fail(fmt::format("bounds [{}, {}] exclude the initial value {}", lower, upper, initial));
  }
  if (!fixed && !(lower < upper)) return fail("a free parameter needs lower < upper");
  return true;
}

std::string unit_of_address(const std::string& address) {
  const auto dot = address.rfind('.');
  const std::string key = dot == std::string::npos ? address : address.substr(dot + 1);
  for (const char* suffix : {"_per_s", "_mm3", "_MPa", "_mm", "_N", "_s"}) {
    const std::string s(suffix);
    if (key.size() > s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0) {
      return s == "_per_s" ? "1/s" : s.substr(1);
    }
  }
  return "1";
}

std::vector<int> free_parameter_indices(const std::vector<ParameterSpec>& specs) {
  std::vector<int> indices;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (!specs[i].fixed) indices.push_back(static_cast<int>(i));
  }
  return indices;
}

}  // namespace vs
