// "Nice" axis ticks (steps of 1, 2 or 5 times a power of ten) and their labels, for svg_plot.
#pragma once

#include <string>
#include <vector>

namespace vs {

// The 1-2-5 step closest to (hi - lo) / target_count. Requires hi > lo and target_count >= 1.
double nice_tick_step(double lo, double hi, int target_count);

// Multiples of nice_tick_step(lo, hi, target_count) that lie inside [lo, hi] (a tick within
// 1e-9 step of an end counts as inside). lo == hi or non-finite ends give no ticks.
std::vector<double> nice_ticks(double lo, double hi, int target_count = 6);

// [lo, hi] widened outwards to whole multiples of the nice step, so an auto-ranged axis starts
// and ends on a labelled tick. A degenerate range (lo == hi) is first widened around the value.
struct TickRange {
  double lo = 0.0;
  double hi = 1.0;
};
TickRange nice_range(double lo, double hi, int target_count = 6);

// Label of a tick that is a multiple of `step`: as many decimals as the step needs and no more,
// never "-0"; very large or small magnitudes fall back to exponent notation.
std::string format_tick(double value, double step);

}  // namespace vs
