// Per-step CSV tables: load_travel.csv (every StepRecord field) and thinnest_point.csv. The row
// formatter is shared with LoadTravelStream so the streamed file and the one written after the
// run are byte-identical.
#pragma once

#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

// "step,time_s,punch_travel_mm,...,rim_draw_in_mm" (no newline).
const std::string& load_travel_csv_header();

// One load_travel.csv row for `record` (no newline), numbers as format_number().
std::string load_travel_csv_row(const StepRecord& record);

// Header and one row per step, each line ending in "\n".
std::string load_travel_csv(const std::vector<StepRecord>& steps);

// punch_travel_mm,min_thickness_mm,thinning_percent,thinnest_r0_mm,thinnest_r_mm per step;
// thinning_percent = 100 (1 - min_thickness_mm / initial_thickness_mm).
std::string thinnest_point_csv(const std::vector<StepRecord>& steps, double initial_thickness_mm);

}  // namespace vs
