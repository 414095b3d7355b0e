// The fixed travel grid on which steps end, shared by the axisymmetric and the 3D step drivers:
// steps land on multiples of the travel increment and on the output travels, so the step
// sequence (and the outputs) move continuously with the material and friction parameters.
#pragma once

#include <vector>

namespace vs {

// Sorted, duplicate-free step targets: multiples of increment_mm below total_mm, the output
// travels, and total_mm itself [mm]; with start_levels L > 0 the first L increments split into
// 2^L, 2^(L-1), ..., 2 equal parts (a graded start, independent of the parameters like the rest).
std::vector<double> travel_grid(double total_mm, double increment_mm,
                                const std::vector<double>& outputs_mm, int start_levels = 0);

// Time step from travel_mm to the next grid target at punch speed speed_mm_per_s, divided into
// equal sub-steps so that no step exceeds max_strain_increment at the largest point strain rate
// max_rate (<= 0: no strain cap) [s]; +inf past the last target.
double step_to_next_target(const std::vector<double>& targets, double travel_mm,
                           double speed_mm_per_s, double max_strain_increment, double max_rate);

}  // namespace vs
