// Measured curves: punch load against punch travel, and strain profiles against initial radius
// at a given travel. Read from CSV files with a provenance header and unit-suffixed columns:
//
//   # source: Woo (1965) Fig. 4, digitised by ...     <- required
//   # units: mm, N                                     <- required
//   # lubricant: polythene                             <- any other "# key: value" is kept
//   punch_travel_mm,punch_force_kN[,sigma]
//   1.0,2.31
//   ...
//
// Columns per kind (any order, nothing else allowed):
//   load_travel             punch_travel_mm, punch_force_N | punch_force_kN   [, sigma]
//   thickness_strain        r0_mm, eps_thickness                             [, sigma]
//   circumferential_strain  r0_mm, eps_circumferential                       [, sigma]
// `sigma` is the per-point standard deviation in the units of the ordinate column as written
// (kN for punch_force_kN); forces are converted to N on reading, sigma with them.
// The units line names the unit of each column (any order, "(remarks)" ignored) and must match
// them: mm for the abscissa, N or kN for forces, 1 or - for strains.
// The reader rejects empty files, non-numeric or non-finite cells (naming file:line), a
// non-increasing abscissa, non-positive sigma, unknown columns, missing provenance lines and
// units that do not match the columns. A UTF-8 byte order mark is skipped; invisible characters
// in a header are named (U+0009 TAB).
//
// vshell's own outputs are read as they are written: load_travel.csv (header starting
// step,time_s,...) and strains_travel_<T>mm.csv (first line "# punch_travel_mm=T", which sets
// travel_mm); they need no provenance, and their other columns are ignored.
//
// A column mapping {NAME, header in the file} (the config's data.columns) renames the file's
// columns to the names above; unmapped columns are then ignored.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vs {

enum class MeasurementKind { kLoadTravel, kThicknessStrain, kCircumferentialStrain };

// "load_travel", "thickness_strain", "circumferential_strain".
std::string to_string(MeasurementKind kind);
// Throws InputError (with `context`) for an unknown name.
MeasurementKind measurement_kind_from_string(const std::string& name, const std::string& context);
// Column names in internal units: {"punch_travel_mm", "punch_force_N"}, {"r0_mm", ...}.
std::string abscissa_name(MeasurementKind kind);
std::string ordinate_name(MeasurementKind kind);

struct Measurement {
  std::string name;  // data-set label used in reports and fit_<name>.csv
  MeasurementKind kind = MeasurementKind::kLoadTravel;
  std::string file;                 // where it came from (for messages and the report)
  double travel_mm = 0.0;           // profiles: the punch travel they were taken at (0: unknown)
  std::vector<double> x;            // punch_travel_mm or r0_mm, strictly increasing
  std::vector<double> y;            // punch_force_N or strain (internal units)
  std::vector<double> point_sigma;  // per-point standard deviation (internal units) or empty
  std::vector<std::pair<std::string, std::string>> provenance;  // "# key: value" lines
};

// Column mapping: {known column name, header in the file}.
using MeasurementColumns = std::vector<std::pair<std::string, std::string>>;

// Reads and checks a measurement CSV (see the file comment). Throws InputError.
Measurement read_measurement_csv(const std::string& path, MeasurementKind kind,
                                 const MeasurementColumns& columns = {});

// Writes a measurement in the format read_measurement_csv accepts (forces in N). `provenance`
// must contain "source" and "units" entries; written first, in the given order.
void write_measurement_csv(const Measurement& measurement, const std::string& path);

}  // namespace vs
