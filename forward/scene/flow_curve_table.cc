#include "scene/flow_curve_table.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "core/error.h"
#include "scene/text_checks.h"

namespace vs {

namespace {

constexpr std::string_view kHeader = "plastic_strain,stress_MPa";

// The header with the spaces around its fields removed, so "plastic_strain, stress_MPa" passes.
std::string squeeze(std::string_view line) {
  std::string out;
  for (char c : line) {
    if (c != ' ' && c != '\t' && c != '\r') out += c;
  }
  return out;
}

bool parse_number(std::string_view text, double& value) {
  text = trim_blanks(text);
  if (text.empty()) return false;
  if (text.front() == '+') text.remove_prefix(1);
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

[[noreturn]] void fail_line(const std::string& path, int line, const std::string& message) {
  throw InputError(fmt::format("{}:{}: {}", path, line, message));
}

}  // namespace

std::string flow_curve_point_problem(const FlowCurveTable& curve, double strain, double stress) {
  if (!std::isfinite(strain) || !std::isfinite(stress)) {
    return fmt::format("point ({}, {}) is not finite", strain, stress);
  }
  if (curve.strain.empty() && strain != 0.0) {
    return fmt::format("the first plastic strain must be 0, got {}", strain);
  }
  if (!curve.strain.empty() && strain <= curve.strain.back()) {
    return fmt::format("plastic strain {} does not increase (previous {})", strain,
                       curve.strain.back());
  }
  if (stress <= 0.0) return fmt::format("stress {} MPa must be > 0", stress);
  return "";
}

std::string flow_curve_size_problem(const FlowCurveTable& curve) {
  if (curve.strain.size() < 2) {
    return fmt::format("a flow curve needs at least 2 points, got {}", curve.strain.size());
  }
  if (curve.strain.size() > kMaxFlowCurvePoints) {
    return fmt::format("a flow curve may have at most {} points, got {}", kMaxFlowCurvePoints,
                       curve.strain.size());
  }
  return "";
}

FlowCurveTable read_flow_curve_csv(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) check_text_input_file(path, "table file");
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("cannot open table file '{}'", path));
  FlowCurveTable curve;
  bool header_seen = false;
  int line_number = 0;
  int last_line = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = trim_blanks(line);
    if (text.empty() || text.front() == '#') continue;
    last_line = line_number;
    if (!header_seen) {
      if (squeeze(text) != kHeader) {
        fail_line(path, line_number,
                  fmt::format("expected the header '{}', got '{}'", kHeader, text));
      }
      header_seen = true;
      continue;
    }
    const auto comma = text.find(',');
    if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos) {
      fail_line(path, line_number,
                fmt::format("expected 2 comma-separated values, got '{}'", text));
    }
    double strain = 0.0;
    double stress = 0.0;
    if (!parse_number(text.substr(0, comma), strain) ||
        !parse_number(text.substr(comma + 1), stress)) {
      fail_line(path, line_number, fmt::format("'{}' is not a pair of numbers", text));
    }
    const std::string problem = flow_curve_point_problem(curve, strain, stress);
    if (!problem.empty()) fail_line(path, line_number, problem);
    curve.strain.push_back(strain);
    curve.stress_MPa.push_back(stress);
  }
  if (!header_seen) fail_line(path, line_number, fmt::format("no header '{}' found", kHeader));
  const std::string problem = flow_curve_size_problem(curve);
  if (!problem.empty()) fail_line(path, last_line, problem);
  return curve;
}

}  // namespace vs
