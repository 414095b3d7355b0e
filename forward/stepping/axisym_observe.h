// Snapshots of the model state for outputs: element-midpoint strain profiles and step scalars.
#pragma once

#include "model/axisym_model.h"
#include "run/run_result.h"

namespace vs {

// `resultants` (N_s, N_t, M_s, M_t, Q per element) may be empty (then the force columns are);
// so may `punch_node_force` (axial punch force per node).
Profile make_profile(const AxisymModel& model, const AxisymState& s, double punch_travel_mm,
                     const std::vector<Vec5>& resultants,
                     const std::vector<double>& punch_node_force = {});

// Geometric scalars of a step record (thinnest point, volume, draw-in); the caller fills the
// solver statistics and the force.
void fill_geometry(const AxisymModel& model, const AxisymState& s, StepRecord* rec);

}  // namespace vs
