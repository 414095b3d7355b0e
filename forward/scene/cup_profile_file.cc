#include "scene/cup_profile_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "scene/text_checks.h"

namespace vs {

namespace {

constexpr std::string_view kHeaderStart = "angle_from_rd_deg,cup_height_mm";

// The fields of a line split at commas and/or runs of blanks ("1, 2", "1 2", "1,2").
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t end = line.find_first_of(", \t", i);
    const std::size_t stop = end == std::string_view::npos ? line.size() : end;
    out.push_back(line.substr(i, stop - i));
    if (end == std::string_view::npos) break;
    // A separator is one comma with blanks around it, or blanks alone.
    std::size_t j = end;
    while (j < line.size() && (line[j] == ' ' || line[j] == '\t')) ++j;
    if (j < line.size() && line[j] == ',') {
      ++j;
      while (j < line.size() && (line[j] == ' ' || line[j] == '\t')) ++j;
    }
    i = j;
    if (i == line.size()) out.emplace_back();  // trailing separator: an empty last field
  }
  return out;
}

bool parse_number(std::string_view text, double& value) {
  if (text.empty()) return false;
  if (text.front() == '+') text.remove_prefix(1);
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

[[noreturn]] void fail_line(const std::string& path, int line, const std::string& message) {
  throw InputError(fmt::format("{}:{}: {}", path, line, message));
}

std::string without_blanks(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c != ' ' && c != '\t') out += c;
  }
  return out;
}

}  // namespace

CupProfilePoints read_cup_profile_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("cannot open cup profile file '{}'", path));
  CupProfilePoints out;
  std::vector<int> lines;  // line of each point, for the repeated-angle message
  std::size_t columns = 2;
  bool first = true;
  int line_number = 0;
  int last_line = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = trim_blanks(line);
    if (text.empty() || text.front() == '#') continue;
    last_line = line_number;
    if (first && std::isalpha(static_cast<unsigned char>(text.front()))) {
      const std::string header = without_blanks(text);
      if (header.rfind(kHeaderStart, 0) != 0) {
        fail_line(path, line_number,
                  fmt::format("expected a header starting '{}', got '{}'", kHeaderStart, text));
      }
      columns = fields(header).size();
      first = false;
      continue;
    }
    first = false;
    const std::vector<std::string_view> f = fields(text);
    if (f.size() != columns) {
      fail_line(path, line_number,
                fmt::format("expected {} values (angle_deg, height_mm{}), got '{}'", columns,
                            columns > 2 ? ", ..." : "", text));
    }
    double angle = 0.0;
    double height = 0.0;
    if (!parse_number(f[0], angle) || !parse_number(f[1], height)) {
      fail_line(path, line_number, fmt::format("'{}' does not start with two numbers", text));
    }
    if (!std::isfinite(angle) || angle < 0.0 || angle > 360.0) {
      fail_line(path, line_number, fmt::format("angle {} deg is outside [0, 360]", angle));
    }
    if (!std::isfinite(height)) {
      fail_line(path, line_number, fmt::format("height {} mm is not finite", height));
    }
    // A point repeated with its height (modulo 360: 0 and 360 deg closing the curve, quarter
    // profiles joined at 90, 180, 270 deg in the benchmark participants' files) is read once.
    bool repeated = false;
    for (std::size_t k = 0; k < out.angle_deg.size(); ++k) {
      if (std::fmod(out.angle_deg[k], 360.0) != std::fmod(angle, 360.0)) continue;
      if (out.height_mm[k] != height) {
        fail_line(path, line_number,
                  fmt::format("angle {} deg repeats the angle of line {} (modulo 360) with another "
                              "height ({} vs {} mm)",
                              angle, lines[k], height, out.height_mm[k]));
      }
      repeated = true;
    }
    if (repeated) continue;
    out.angle_deg.push_back(angle);
    out.height_mm.push_back(height);
    lines.push_back(line_number);
  }
  if (out.angle_deg.size() < 3) {
    fail_line(path, std::max(last_line, 1),
              fmt::format("a cup profile needs at least 3 points, got {}", out.angle_deg.size()));
  }
  return out;
}

}  // namespace vs
