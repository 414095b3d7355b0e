#include "measurement.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "core/error.h"
#include "scene/text_checks.h"

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

// Rows of the headerless cup-profile form: comma-separated (spaces around allowed) or, without a
// comma, separated by spaces.
std::vector<std::string> split_fields(const std::string& line) {
  if (line.find(',') != std::string::npos) return split_commas(line);
  std::vector<std::string> cells;
  std::size_t start = line.find_first_not_of(" \t");
  while (start != std::string::npos) {
    const auto end = line.find_first_of(" \t", start);
    cells.push_back(line.substr(start, end - start));
    start = line.find_first_not_of(" \t", end);
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
    case MeasurementKind::kCupHeightProfile:
      return {{"cup_height_mm", 1.0}};
  }
  return {};
}

struct Columns {
  int abscissa = -1;
  int ordinate = -1;
  int sigma = -1;
  double ordinate_factor = 1.0;
  std::string ordinate_name;
  std::size_t count = 0;  // cells per row
};

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// `ignore_others`: columns that are not needed are skipped (vshell outputs, mapped columns).
Columns parse_header(const std::vector<std::string>& names, MeasurementKind kind,
                     const std::string& where, bool ignore_others) {
  Columns columns;
  columns.count = names.size();
  const auto ordinates = accepted_ordinates(kind);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int index = static_cast<int>(i);
    const std::string& name = names[i];
    bool known = false;
    bool repeated = false;
    if (name == abscissa_name(kind)) {
      known = true;
      repeated = columns.abscissa >= 0;
      columns.abscissa = index;
    } else if (name == "sigma") {
      known = true;
      repeated = columns.sigma >= 0;
      columns.sigma = index;
    } else {
      for (const auto& [ordinate, factor] : ordinates) {
        if (name != ordinate) continue;
        known = true;
        repeated = columns.ordinate >= 0;
        columns.ordinate = index;
        columns.ordinate_factor = factor;
        columns.ordinate_name = ordinate;
      }
    }
    if (repeated || (!known && !ignore_others)) {
      std::string allowed = abscissa_name(kind);
      for (const auto& ordinate : ordinates) allowed += ", " + ordinate.first;
      throw InputError(fmt::format(
          "{}: {} column '{}'{} for {} data (allowed: {}, sigma; or map the file's columns "
          "with data.columns)",
          where, repeated ? "repeated" : "unknown", show_invisible(name), invisible_note(name),
          to_string(kind), allowed));
    }
  }
  if (columns.abscissa < 0 || columns.ordinate < 0) {
    throw InputError(fmt::format("{}: {} data needs columns {} and {}; the header has {}", where,
                                 to_string(kind), abscissa_name(kind), ordinates.front().first,
                                 show_invisible(join(names))));
  }
  return columns;
}

// The header names with the mapping applied: {known, header in file} renames that column.
std::vector<std::string> apply_mapping(const std::vector<std::string>& header,
                                       const MeasurementColumns& mapping, MeasurementKind kind,
                                       const std::string& where) {
  std::vector<std::string> names = header;
  std::vector<std::string> known = {abscissa_name(kind), "sigma"};
  for (const auto& ordinate : accepted_ordinates(kind)) known.push_back(ordinate.first);
  for (const auto& [to, from] : mapping) {
    if (std::find(known.begin(), known.end(), to) == known.end()) {
      throw InputError(fmt::format("{}: data.columns maps '{}', which is not a {} column ({})",
                                   where, to, to_string(kind), join(known)));
    }
    const auto it = std::find(header.begin(), header.end(), from);
    if (it == header.end()) {
      throw InputError(
          fmt::format("{}: data.columns maps {} to '{}', which is not in the header ({})", where,
                      to, from, show_invisible(join(header))));
    }
    names[static_cast<std::size_t>(it - header.begin())] = to;
  }
  return names;
}

// Units as written on the "# units:" line: comma-separated, "(remarks)" removed.
std::vector<std::string> parse_units(const std::string& text) {
  std::string plain;
  int depth = 0;
  for (char c : text) {
    if (c == '(') ++depth;
    if (depth == 0) plain += c;
    if (c == ')' && depth > 0) --depth;
  }
  std::vector<std::string> units;
  for (const std::string& u : split_commas(plain)) {
    if (!u.empty()) units.push_back(u);
  }
  return units;
}

// The "# units:" line must name only known units and include the unit of each column used.
void check_units(const std::string& text, const Columns& columns, const std::string& where) {
  static const std::vector<std::string> kKnown = {"mm",  "N", "kN",   "1",  "-",
                                                  "MPa", "s", "mm/s", "deg"};
  const std::vector<std::string> units = parse_units(text);
  for (const std::string& u : units) {
    if (std::find(kKnown.begin(), kKnown.end(), u) == kKnown.end()) {
      throw InputError(fmt::format("{}: unknown unit '{}'{} on the units line (known: {})", where,
                                   show_invisible(u), invisible_note(u), join(kKnown)));
    }
  }
  auto has = [&](std::initializer_list<const char*> any) {
    for (const char* u : any) {
      if (std::find(units.begin(), units.end(), u) != units.end()) return true;
    }
    return false;
  };
  const std::string& y = columns.ordinate_name;
  const bool force_N = y == "punch_force_N";
  const bool force_kN = y == "punch_force_kN";
  const bool height = y == "cup_height_mm";
  const char* y_unit = force_N ? "N" : force_kN ? "kN" : height ? "mm" : "1 (or -)";
  const bool y_ok = force_N    ? has({"N"})
                    : force_kN ? has({"kN"})
                    : height   ? has({"mm"})
                               : has({"1", "-"});
  const char* x_unit = height ? "deg" : "mm";
  if (!has({x_unit}) || !y_ok) {
    throw InputError(fmt::format(
        "{}: units '{}' do not match the columns: the abscissa is in {} and {} in {} (the units "
        "line names the unit of each column)",
        where, text, x_unit, y, y_unit));
  }
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
    case MeasurementKind::kCupHeightProfile:
      return "cup_height_profile";
  }
  return "?";
}

MeasurementKind measurement_kind_from_string(const std::string& name, const std::string& context) {
  for (auto kind : {MeasurementKind::kLoadTravel, MeasurementKind::kThicknessStrain,
                    MeasurementKind::kCircumferentialStrain, MeasurementKind::kCupHeightProfile}) {
    if (to_string(kind) == name) return kind;
  }
  throw InputError(fmt::format(
      "{}: unknown data kind '{}' (load_travel, thickness_strain, circumferential_strain, "
      "cup_height_profile)",
      context, name));
}

std::string abscissa_name(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return "punch_travel_mm";
    case MeasurementKind::kCupHeightProfile:
      return "angle_from_rd_deg";
    default:
      return "r0_mm";
  }
}

std::string ordinate_name(MeasurementKind kind) { return accepted_ordinates(kind).front().first; }

bool is_strain_profile(MeasurementKind kind) {
  return kind == MeasurementKind::kThicknessStrain ||
         kind == MeasurementKind::kCircumferentialStrain;
}

std::string ordinate_unit(MeasurementKind kind) {
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return "N";
    case MeasurementKind::kCupHeightProfile:
      return "mm";
    default:
      return "1";
  }
}

Measurement read_measurement_csv(const std::string& path, MeasurementKind kind,
                                 const MeasurementColumns& mapping) {
  MeasurementReadOptions options;
  options.columns = mapping;
  return read_measurement_file(path, kind, options);
}

Measurement read_measurement_file(const std::string& path, MeasurementKind kind,
                                  const MeasurementReadOptions& options) {
  const MeasurementColumns& mapping = options.columns;
  check_text_input_file(path, "measurement file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open measurement file", path));

  Measurement m;
  m.kind = kind;
  m.file = path;
  std::optional<Columns> columns;
  bool vshell_output = false;  // load_travel.csv or strains_travel_<T>mm.csv as written
  bool headerless = false;     // the 2-column cup-profile form (angle, height)
  std::string units_text;
  int units_line = 0;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string where = fmt::format("{}:{}", path, line_number);
    const std::string text = trim(line_number == 1 ? std::string(strip_utf8_bom(line)) : line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      // Provenance is only what precedes the header; later comments are ignored.
      if (columns) continue;
      const std::string body = trim(text.substr(1));
      constexpr std::string_view kTravel = "punch_travel_mm=";  // vshell strains files
      if (body.rfind(kTravel, 0) == 0) {
        // "# punch_travel_mm=10" (axisymmetric) or "# punch_travel_mm=10, line=x" (3D lines).
        const std::string value = body.substr(kTravel.size());
        const auto travel = parse_number(trim(value.substr(0, value.find(','))));
        if (!travel || !(*travel > 0.0) || !std::isfinite(*travel)) {
          throw InputError(fmt::format("{}: '{}' is not a punch travel", where, body));
        }
        m.travel_mm = *travel;
        vshell_output = true;
        continue;
      }
      const auto colon = body.find(':');
      if (colon != std::string::npos) {
        m.provenance.emplace_back(trim(body.substr(0, colon)), trim(body.substr(colon + 1)));
        if (m.provenance.back().first == "units") {
          units_text = m.provenance.back().second;
          units_line = line_number;
        }
      }
      continue;
    }
    auto cells = headerless ? split_fields(text) : split_commas(text);
    if (!columns && kind == MeasurementKind::kCupHeightProfile && mapping.empty()) {
      // The headerless form: the first row holds two numbers; it is read as a row below.
      const auto fields = split_fields(text);
      const bool numbers = std::all_of(fields.begin(), fields.end(), [](const std::string& f) {
        return parse_number(f).has_value();
      });
      if (numbers && fields.size() != 2) {
        throw InputError(
            fmt::format("{}: a headerless cup profile has 2 numbers per row (angle_from_rd_deg, "
                        "cup_height_mm), found {}",
                        where, fields.size()));
      }
      if (numbers) {
        headerless = true;
        cells = fields;
        columns = Columns{0, 1, -1, 1.0, ordinate_name(kind), 2};
        if (units_line > 0) {
          check_units(units_text, *columns, fmt::format("{}:{}", path, units_line));
        }
      }
    }
    if (!columns) {
      // vshell's load_travel.csv starts step,time_s,punch_travel_mm,...
      vshell_output = vshell_output || (cells.size() > 3 && cells[0] == "step" &&
                                        cells[1] == "time_s" && cells[2] == "punch_travel_mm");
      const auto names = mapping.empty() ? cells : apply_mapping(cells, mapping, kind, where);
      columns = parse_header(names, kind, where, vshell_output || !mapping.empty());
      // Units against the columns, as soon as both are known (a missing line: below).
      if (!vshell_output && units_line > 0) {
        check_units(units_text, *columns, fmt::format("{}:{}", path, units_line));
      }
      continue;
    }
    if (cells.size() != columns->count) {
      throw InputError(fmt::format("{}: expected {} comma-separated values, found {}{}", where,
                                   columns->count, cells.size(), invisible_note(text)));
    }
    auto value_at = [&](int index) {
      const std::string& cell = cells[static_cast<std::size_t>(index)];
      const auto value = parse_number(cell);
      if (!value) {
        throw InputError(fmt::format("{}: '{}' is not a number{}", where, show_invisible(cell),
                                     invisible_note(cell)));
      }
      if (!std::isfinite(*value)) {
        throw InputError(fmt::format("{}: '{}' is not finite", where, cell));
      }
      return *value;
    };
    const double x = value_at(columns->abscissa);
    if (!m.x.empty() && !(x > m.x.back())) {
      throw InputError(fmt::format("{}: {} = {} does not increase (previous {})", where,
                                   abscissa_name(kind), x, m.x.back()));
    }
    if (kind == MeasurementKind::kCupHeightProfile &&
        (x < 0.0 || x > 360.0 || (!m.x.empty() && !(x - m.x.front() < 360.0)))) {
      throw InputError(fmt::format(
          "{}: angle_from_rd_deg = {} must lie in [0, 360] and less than 360 deg after the first "
          "angle {} (no angle twice modulo 360)",
          where, x, m.x.empty() ? x : m.x.front()));
    }
    m.x.push_back(x);
    m.y.push_back(value_at(columns->ordinate) * columns->ordinate_factor);
    if (columns->sigma >= 0) {
      const double sigma = value_at(columns->sigma);
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
  if (!options.source.empty()) {
    if (has_key("source")) {
      throw InputError(fmt::format(
          "{}: the file has a '# source:' line and data.source gives one too: state it once",
          path));
    }
    m.provenance.emplace(m.provenance.begin(), "source", options.source);
  }
  if (headerless && !has_key("units")) {
    m.provenance.emplace_back("units", "deg, mm (headerless angle_from_rd_deg, cup_height_mm)");
  }
  if (vshell_output) {
    if (!has_key("source")) m.provenance.emplace_back("source", "vshell run output " + path);
    if (!has_key("units")) {
      m.provenance.emplace_back("units", kind == MeasurementKind::kCupHeightProfile
                                             ? "deg, mm (vshell output)"
                                             : "mm, N, 1 (vshell output)");
    }
  } else if (!has_key("source") || !has_key("units")) {
    throw InputError(fmt::format(
        "{}: provenance lines '# source: ...' and '# units: ...' are required before the header{}",
        path,
        kind == MeasurementKind::kCupHeightProfile
            ? " (a headerless angle, height file may give the source as data.source instead)"
            : ""));
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
