// The prediction of cup_height_profile data: the cup height of a 3D cup run around its rim, at
// the measured angles from the rolling direction.
//
// The run's final stage gives the rim profile (forward/output/cup_profile.h: every rim node's
// angle from RD and height, a quarter model unfolded to 360 deg). It is read as the periodic
// piecewise-linear function of the angle (the same reading as cup_profile_summary.h): between the
// last rim angle and the first one plus 360 deg the two are joined across 0/360. A measured angle
// is taken modulo 360. A run that is not a completed 3D run, or whose final stage has no rim
// profile (e.g. a clamped edge), gives no prediction and says why in one line.
//
// Shape only (DataSpec::shape_only, the config's data.shape_only): the profile is compared up to
// a constant offset, the weighted least-squares one,
//   c = sum w_i^2 (m_i - s_i) / sum w_i^2,   s_i <- s_i + c,
// so that the residuals w_i (s_i + c - m_i) are those of the fit with a free offset eliminated
// (variable projection): the mean height, which friction and hardening set more than the
// r-values, drops out and only the earing shape (ears, amplitude) is fitted.
#pragma once

#include <vector>

#include "measurement.h"
#include "residual_pipeline.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// The value at `at_deg` of the periodic piecewise-linear function through (angle_deg[i],
// value[i]); `angle_deg` strictly increasing within [0, 360) and at least 2 points (else NaN).
double periodic_interpolate_deg(const std::vector<double>& angle_deg,
                                const std::vector<double>& value, double at_deg);

// The run's final cup profile at measurement.x (angles from RD). `scene` is the scene that was
// run (its blank outline and rolling direction identify the rim).
SimulatedCurve cup_height_curve(const Measurement& measurement, const Scene& scene,
                                const RunResult& run);

// The offset c above (0 when the weights are all zero or the sizes differ).
double shape_offset(const std::vector<double>& simulated, const std::vector<double>& measured,
                    const std::vector<double>& weights);

}  // namespace vs
