// Summary of a cup-height (earing) profile around the circumference, the same for a computed
// profile (cup_profile.h) and a measured one (scene/cup_profile_file.h), so that the two are
// compared number for number.
//
// The profile is read as the periodic piecewise-linear function through the points (angle from
// the rolling direction taken modulo 360 deg, in increasing order, the last point joined to the
// first across 360 deg):
//   mean       the mean of that function over 360 deg (trapezoids, i.e. weighted by angle: uneven
//              spacing does not bias it);
//   min, max   its extremes (at points, since it is piecewise linear); amplitude = max - min;
//   ears       its local maxima: a point higher than the previous point and than the next point
//              of a different height (a run of equal heights counts once); valleys likewise.
//              Each is refined by the parabola through the point and its two neighbours: vertex
//              x* = (a0 + a1) / 2 - d01 / (2 c), with d01 = (h1 - h0) / (a1 - a0) and
//              c = (d12 - d01) / (a2 - a0) the second divided difference (exact for a profile
//              that is quadratic near the extremum); a run of equal heights reports its middle.
//              An extremum counts only if its prominence reaches Options::min_prominence_mm: an
//              ear's height above the higher of the lowest points met walking either way round
//              to a higher point (the highest ear: above the lowest point; of equal heights the
//              first in angle counts as higher); a valley likewise.
#pragma once

#include <vector>

namespace vs {

struct ProfileExtremum {
  double angle_deg = 0.0;  // from the rolling direction, [0, 360)
  double height_mm = 0.0;  // the parabola's value there
};

struct CupProfileSummary {
  int points = 0;
  // NaN without points.
  double mean_height_mm = 0.0;
  double min_height_mm = 0.0;
  double max_height_mm = 0.0;
  double amplitude_mm = 0.0;             // max - min
  std::vector<ProfileExtremum> ears;     // local maxima, by increasing angle
  std::vector<ProfileExtremum> valleys;  // local minima, by increasing angle
};

struct CupProfileSummaryOptions {
  // Smallest prominence of an ear or valley [mm]. 10 um by default: below the resolution of the
  // digitised measured profile (ESAFORM 2021, heights to 0.001 mm read off a figure) and above the
  // mesh noise of the rim height of an isotropic cup (0.007 mm on the 3D example 2 at 4
  // divisions, experiments/10_earing), so that noise does not make ears. 0 keeps every one.
  double min_prominence_mm = 0.01;
};

// `angle_deg` (any order, any real angle: taken modulo 360) and `height_mm` of equal length.
// Points beyond the shorter of the two are ignored. Equal angles modulo 360 keep their order.
CupProfileSummary summarize_cup_profile(const std::vector<double>& angle_deg,
                                        const std::vector<double>& height_mm,
                                        const CupProfileSummaryOptions& options = {});

// Circular distance between two angles [deg], in [0, 180].
double angle_distance_deg(double a_deg, double b_deg);

// The largest, over the `reference` extrema, of the circular distance to the nearest of `found`
// [deg]: how far the found ears are from the reference ears (NaN if either list is empty).
double max_extremum_offset_deg(const std::vector<ProfileExtremum>& found,
                               const std::vector<ProfileExtremum>& reference);

}  // namespace vs
