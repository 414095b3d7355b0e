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
//   cup_height_profile      angle_from_rd_deg, cup_height_mm                 [, sigma]
// `sigma` is the per-point standard deviation in the units of the ordinate column as written
// (kN for punch_force_kN); forces are converted to N on reading, sigma with them.
// The units line names the unit of each column (any order, "(remarks)" ignored) and must match
// them: mm for the abscissa (deg for angles), N or kN for forces, 1 or - for strains, mm for
// cup heights.
//
// cup_height_profile: the cup height (earing profile) against the angle from the rolling
// direction, angles in [0, 360] increasing and spanning less than 360 deg (no angle repeated
// modulo 360). Besides the form above it has a HEADERLESS 2-column form, that of the ESAFORM 2021
// file (AA6016_Experiment_Fig91_CupProfile_angle.txt: "0.480331, 34.515"): when the first line
// that is not a comment holds two numbers, every row is "angle_from_rd_deg, cup_height_mm" in
// deg and mm (separated by a comma and/or spaces). Its provenance is then either "# source:"
// lines in the file or MeasurementReadOptions::source (the config's data.source); the units
// line is optional (the form fixes them) but checked when present.
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

enum class MeasurementKind {
  kLoadTravel,
  kThicknessStrain,
  kCircumferentialStrain,
  kCupHeightProfile,
};

// "load_travel", "thickness_strain", "circumferential_strain", "cup_height_profile".
std::string to_string(MeasurementKind kind);
// Throws InputError (with `context`) for an unknown name.
MeasurementKind measurement_kind_from_string(const std::string& name, const std::string& context);
// Column names in internal units: {"punch_travel_mm", "punch_force_N"}, {"r0_mm", ...},
// {"angle_from_rd_deg", "cup_height_mm"}.
std::string abscissa_name(MeasurementKind kind);
std::string ordinate_name(MeasurementKind kind);
// Strain profiles along a line at a punch travel (thickness_strain, circumferential_strain):
// the kinds that need travel_mm.
bool is_strain_profile(MeasurementKind kind);
// Unit of the ordinate in internal units: "N", "1" or "mm".
std::string ordinate_unit(MeasurementKind kind);

struct Measurement {
  std::string name;  // data-set label used in reports and fit_<name>.csv
  MeasurementKind kind = MeasurementKind::kLoadTravel;
  std::string file;        // where it came from (for messages and the report)
  double travel_mm = 0.0;  // strain profiles: the punch travel they were taken at (0: unknown)
  std::vector<double> x;   // punch_travel_mm, r0_mm or angle_from_rd_deg, strictly increasing
  std::vector<double> y;   // punch_force_N, strain or cup_height_mm (internal units)
  std::vector<double> point_sigma;  // per-point standard deviation (internal units) or empty
  std::vector<std::pair<std::string, std::string>> provenance;  // "# key: value" lines
};

// Column mapping: {known column name, header in the file}.
using MeasurementColumns = std::vector<std::pair<std::string, std::string>>;

struct MeasurementReadOptions {
  MeasurementColumns columns;  // data.columns
  // data.source: the provenance "source" of a file that has no "# source:" line (e.g. the
  // headerless ESAFORM profile, whose provenance is its folder's README). A file that has one
  // too is an error (one source, stated once).
  std::string source;
};

// Reads and checks a measurement file (see the file comment). Throws InputError.
Measurement read_measurement_file(const std::string& path, MeasurementKind kind,
                                  const MeasurementReadOptions& options);
// The same with a column mapping only.
Measurement read_measurement_csv(const std::string& path, MeasurementKind kind,
                                 const MeasurementColumns& columns = {});

// Writes a measurement in the format read_measurement_csv accepts (forces in N). `provenance`
// must contain "source" and "units" entries; written first, in the given order.
void write_measurement_csv(const Measurement& measurement, const std::string& path);

}  // namespace vs
