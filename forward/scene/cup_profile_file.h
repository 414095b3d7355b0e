// A measured (or earlier computed) cup-height profile around the circumference: angle from the
// rolling direction against cup height, for output.measured_cup_profile. The strict reader of its
// text file lives here so that a bad file is refused when the scene is loaded, before any run.
#pragma once

#include <string>
#include <vector>

namespace vs {

struct CupProfilePoints {
  std::vector<double> angle_deg;  // angle from the rolling direction, [0, 360], file order
  std::vector<double> height_mm;  // cup height at that angle
};

// Reads `path`: '#' comment lines and blank lines are skipped; each other line holds an angle
// [deg] and a height [mm] separated by a comma and/or spaces (the ESAFORM 2021 file
// "0.480331, 34.515"). A first line starting with a letter is a header; it must start with
// "angle_from_rd_deg,cup_height_mm" and may name more columns (a run's cup_profile.csv), which
// every row must then have and which are ignored. Angles lie in [0, 360] and do not repeat modulo
// 360 with another height; a point repeated with the same height (0 and 360 deg closing the curve,
// quarters joined at 90 deg, as in the benchmark participants' files) is read once; at least 3
// points. Any malformed line raises InputError "FILE:LINE: message".
CupProfilePoints read_cup_profile_file(const std::string& path);

}  // namespace vs
