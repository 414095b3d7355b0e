// Forming-limit-diagram data: in-plane principal true strains of every element at the final
// state (fld_points.csv, one schema for both geometries) and the strain paths of a few elements
// through the history (strain_paths.csv, axisymmetric runs with output.history). Axisymmetric
// membrane strains have no meridional-circumferential shear, so the principal strains are the
// larger and smaller of the two; 3D ones come from the mid-surface metric at the element centre
// (shell3d/forming/forming_fields.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "output/forming_limit.h"
#include "run/run_result.h"

namespace vs {

struct PrincipalStrains {
  double major = 0.0;
  double minor = 0.0;
};

PrincipalStrains in_plane_principal(double eps_meridional, double eps_circumferential);

// The furthest-travelled state the result holds: the last profile of the first line (the
// meridian; 3D: the line along x) or the last history entry, whichever has the larger punch
// travel (profiles win a tie); nullptr when the result has neither (a run that failed before
// its first step).
const Profile* final_state(const RunResult& result);

// One element at the final state. Axisymmetric: the element of the meridian (x0 = r0, y0 = 0,
// eps_thickness from the thickness, eps_effective at the mid-surface). 3D: the element centre of
// the meshed part (eps_thickness = -(major + minor), the membrane value).
struct FldPoint {
  std::size_t element = 0;
  double x0_mm = 0.0, y0_mm = 0.0, r0_mm = 0.0;  // initial position of the element centre
  double r_mm = 0.0;                             // its current distance from the punch axis
  double eps_major = 0.0, eps_minor = 0.0, eps_thickness = 0.0, eps_effective = 0.0;
  double thinning_percent = 0.0;  // 100 (1 - h/h0) = -100 expm1(eps_thickness)
  // Against the forming-limit curve (apply_forming_limit; NaN / kUnknown without one):
  double flc_eps_major = 0.0;  // major true strain of the FLC at this minor strain
  double flc_margin = 0.0;     // flc_eps_major - eps_major
  FormingZone zone = FormingZone::kUnknown;
};

// Every element at the final state (3D: the last stage of result.shell); empty when the result
// has no state. The FLC fields are unset (NaN, kUnknown) until apply_forming_limit.
std::vector<FldPoint> fld_points(const RunResult& result);
// The points of one axisymmetric state (empty for null).
std::vector<FldPoint> fld_points(const Profile* state);

// Fills the FLC fields of every point from `flc`.
void apply_forming_limit(const FormingLimitCurve& flc, std::vector<FldPoint>* points);

// The point with the smallest FLC margin (the first of equal ones), or nullptr when no point has
// a margin (no curve, no points).
const FldPoint* least_margin_point(const std::vector<FldPoint>& points);

// element,x0_mm,y0_mm,r0_mm,r_mm,eps_major,eps_minor,eps_thickness,thinning_percent,
// eps_effective,flc_eps_major,flc_margin,flc_zone, one row per point (only the header when there
// are none); flc_zone is safe / marginal / failed, or none without a curve.
std::string fld_points_csv(const std::vector<FldPoint>& points);

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
