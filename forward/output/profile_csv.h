// Strain distributions along the meridian (one Profile) as CSV: strains_travel_<travel>mm.csv.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

// Stable, sortable name: travel with two decimals, zero-padded to six characters,
// e.g. 10 mm -> "strains_travel_010.00mm.csv", 2.5 mm -> "strains_travel_002.50mm.csv".
std::string strains_file_name(double punch_travel_mm);

// Number of element rows in `profile`: the longest element-field vector (the fields should all
// have that length; a shorter one, from a partial result, is padded with "nan").
std::size_t profile_rows(const Profile& profile);

// The profiles worth writing and plotting, in order: result.profiles without entries whose travel
// repeats an earlier one exactly (the end of the run often coincides with the last requested
// travel). When there are no profiles (a run that failed early), the last history entry.
std::vector<const Profile*> profile_stages(const RunResult& result);

// "# punch_travel_mm=<travel>", then the header
// r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,eps_effective,
// contact, then one row per element.
std::string profile_csv(const Profile& profile);

}  // namespace vs
