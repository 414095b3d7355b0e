#include "measurement.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>

#include "core/error.h"

namespace vs {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

// The whole cell must be a number: "1.5x" or "" are errors, not 1.5 or 0.
std::optional<double> parse_number(const std::string& cell) {
  double value = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, value);
  if (ec != std::errc() || ptr != end || cell.empty()) return std::nullopt;
  return value;
}

// Ordinate column names accepted for a kind, with the factor to internal units.
std::vector<std::pair<std::string, double>> accepted_ordinates(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return {{"punch_force_N", 1.0}, {"punch_force_kN", 1000.0}};
    case MeasurementKind::kThicknessStrain:
      return {{"eps_thickness", 1.0}};
    case MeasurementKind::kCircumferentialStrain:
      return {{"eps_circumferential", 1.0}};
  }
  return {};
}

struct Columns {
  int abscissa = -1;
  int ordinate = -1;
  int sigma = -1;
  double ordinate_factor = 1.0;
};

Columns parse_header(const std::vector<std::string>& names, MeasurementKind kind,
                     const std::string& where) {
  Columns columns;
  const auto ordinates = accepted_ordinates(kind);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int index = static_cast<int>(i);
    const std::string& name = names[i];
    bool known = false;
    if (name == abscissa_name(kind)) {
      known = columns.abscissa < 0;
      columns.abscissa = index;
    } else if (name == "sigma") {
      known = columns.sigma < 0;
      columns.sigma = index;
    } else {
      for (const auto& [ordinate, factor] : ordinates) {
        if (name != ordinate) continue;
        known = columns.ordinate < 0;
        columns.ordinate = index;
        columns.ordinate_factor = factor;
      }
    }
    if (!known) {
      std::string allowed = abscissa_name(kind);
      for (const auto& ordinate : ordinates) allowed += ", " + ordinate.first;
      throw InputError(
          fmt::format("{}: unknown or repeated column '{}' for {} data (allowed: {}, "
                      "sigma)",
                      where, name, to_string(kind), allowed));
    }
  }
  if (columns.abscissa < 0 || columns.ordinate < 0) {
    throw InputError(fmt::format("{}: {} data needs columns {} and {}", where, to_string(kind),
                                 abscissa_name(kind), ordinates.front().first));
  }
  return columns;
}

}  // namespace

std::string to_string(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return "load_travel";
    case MeasurementKind::kThicknessStrain:
      return "thickness_strain";
    case MeasurementKind::kCircumferentialStrain:
      return "circumferential_strain";
  }
  return "?";
}

MeasurementKind measurement_kind_from_string(const std::string& name, const std::string& context) {
  for (auto kind : {MeasurementKind::kLoadTravel, MeasurementKind::kThicknessStrain,
                    MeasurementKind::kCircumferentialStrain}) {
    if (to_string(kind) == name) return kind;
  }
  throw InputError(fmt::format(
      "{}: unknown data kind '{}' (load_travel, thickness_strain, circumferential_strain)", context,
      name));
}

std::string abscissa_name(MeasurementKind kind) {
  return kind == MeasurementKind::kLoadTravel ? "punch_travel_mm" : "r0_mm";
}

std::string ordinate_name(MeasurementKind kind) { return accepted_ordinates(kind).front().first; }

Measurement read_measurement_csv(const std::string& path, MeasurementKind kind) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open measurement file", path));

  Measurement m;
  m.kind = kind;
  m.file = path;
  std::optional<Columns> columns;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string where = fmt::format("{}:{}", path, line_number);
    const std::string text = trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      // Provenance is only what precedes the header; later comments are ignored.
      if (columns) continue;
      const std::string body = trim(text.substr(1));
      const auto colon = body.find(':');
      if (colon != std::string::npos) {
        m.provenance.emplace_back(trim(body.substr(0, colon)), trim(body.substr(colon + 1)));
      }
      continue;
    }
    const auto cells = split_commas(text);
    if (!columns) {
      columns = parse_header(cells, kind, where);
      continue;
    }
    if (cells.size() != 1 + (columns->sigma >= 0 ? 2u : 1u)) {
      throw InputError(fmt::format("{}: expected {} comma-separated values, found {}", where,
                                   columns->sigma >= 0 ? 3 : 2, cells.size()));
    }
    double values[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto value = parse_number(cells[i]);
      if (!value) throw InputError(fmt::format("{}: '{}' is not a number", where, cells[i]));
      if (!std::isfinite(*value)) {
        throw InputError(fmt::format("{}: '{}' is not finite", where, cells[i]));
      }
      values[i] = *value;
    }
    const double x = values[columns->abscissa];
    if (!m.x.empty() && !(x > m.x.back())) {
      throw InputError(fmt::format("{}: {} = {} does not increase (previous {})", where,
                                   abscissa_name(kind), x, m.x.back()));
    }
    m.x.push_back(x);
    m.y.push_back(values[columns->ordinate] * columns->ordinate_factor);
    if (columns->sigma >= 0) {
      const double sigma = values[columns->sigma];
      if (!(sigma > 0.0)) throw InputError(fmt::format("{}: sigma must be > 0", where));
      m.point_sigma.push_back(sigma * columns->ordinate_factor);
    }
  }

  auto has_key = [&](const std::string& key) {
    for (const auto& entry : m.provenance) {
      if (entry.first == key) return true;
    }
    return false;
  };
  if (!has_key("source") || !has_key("units")) {
    throw InputError(fmt::format(
        "{}: provenance lines '# source: ...' and '# units: ...' are required before the header",
        path));
  }
  if (!columns) throw InputError(fmt::format("{}: no header line", path));
  if (m.x.empty()) throw InputError(fmt::format("{}: no data rows", path));
  return m;
}

void write_measurement_csv(const Measurement& m, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write measurement file", path));
  for (const auto& [key, value] : m.provenance) out << "# " << key << ": " << value << '\n';
  out << abscissa_name(m.kind) << ',' << ordinate_name(m.kind);
  if (!m.point_sigma.empty()) out << ",sigma";
  out << '\n';
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    // 17 significant digits: a written and re-read file gives back the same doubles.
    out << fmt::format("{:.17g},{:.17g}", m.x[i], m.y[i]);
    if (!m.point_sigma.empty()) out << fmt::format(",{:.17g}", m.point_sigma[i]);
    out << '\n';
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

}  // namespace vs
