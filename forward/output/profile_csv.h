// Strain distributions along one line (one Profile) as CSV: strains_travel_<travel>mm.csv for
// the axisymmetric meridian, strains_travel_<travel>mm_<line>.csv for the lines of a 3D blank
// (x, y, diagonal, ...), with the same columns.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

// Stable, sortable name: travel with two decimals, zero-padded to six characters,
// e.g. 10 mm -> "strains_travel_010.00mm.csv", 2.5 mm -> "strains_travel_002.50mm.csv".
// A line other than "meridian" is appended: "strains_travel_010.00mm_x.csv".
std::string strains_file_name(double punch_travel_mm, const std::string& line = "meridian");

// Number of element rows in `profile`: the longest element-field vector (the fields should all
// have that length; a shorter one, from a partial result, is padded with "nan").
std::size_t profile_rows(const Profile& profile);

// The profiles worth writing and plotting, in order: result.profiles without entries whose travel
// and line repeat an earlier one exactly (the end of the run often coincides with the last
// requested travel); with `line` non-empty only that line's. When there are no profiles (a run
// that failed early), the last history entry.
std::vector<const Profile*> profile_stages(const RunResult& result, const std::string& line = "");

// The line that plots show: the first profile's ("meridian", or "x" in 3D).
std::string primary_line(const RunResult& result);

// Thinning in percent, 100 (1 - h/h0), from the thickness strain ln(h/h0) (NaN stays NaN).
double thinning_percent(double eps_thickness);

// "# punch_travel_mm=<travel>" (and ", line=<line>" for a 3D line), then the header
// r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,
// thinning_percent,eps_effective,contact, then one row per element (3D: per node of the line).
std::string profile_csv(const Profile& profile);

}  // namespace vs
