// Forming-limit-diagram data: in-plane principal true strains of every element at the final
// state (fld_points.csv) and the strain paths of a few elements through the history
// (strain_paths.csv). Axisymmetric membrane strains have no meridional-circumferential shear, so
// the principal strains are the larger and smaller of the two.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

struct PrincipalStrains {
  double major = 0.0;
  double minor = 0.0;
};

PrincipalStrains in_plane_principal(double eps_meridional, double eps_circumferential);

// The furthest-travelled state the result holds: the last profile or the last history entry,
// whichever has the larger punch travel (profiles win a tie); nullptr when the result has
// neither (a run that failed before its first step).
const Profile* final_state(const RunResult& result);

// element,r0_mm,r_mm,eps_major,eps_minor,eps_thickness for each element of `state`; only the
// header when `state` is null.
std::string fld_points_csv(const Profile* state);

// Elements whose strain paths are worth plotting: the thinnest element of `state` and up to
// `count` - 1 others evenly spaced along the meridian; sorted, without repeats.
std::vector<std::size_t> strain_path_elements(const Profile& state, std::size_t count);

struct StrainPath {
  std::size_t element = 0;
  double r0_mm = 0.0;
  std::vector<int> step;  // step number of each history entry (see strain_paths())
  std::vector<double> punch_travel_mm;
  std::vector<double> eps_major;
  std::vector<double> eps_minor;
};

// Paths of `elements` through result.history (empty paths when there is no history). A history
// entry takes the step number of the StepRecord with the same punch travel, or its position in
// the history when no record matches.
std::vector<StrainPath> strain_paths(const RunResult& result,
                                     const std::vector<std::size_t>& elements);

// step,punch_travel_mm,element,r0_mm,eps_major,eps_minor, one element's path after another.
std::string strain_paths_csv(const std::vector<StrainPath>& paths);

}  // namespace vs
