// The 3D forming solver against the axisymmetric one on the same data (paper example 4a vs
// example 1): the axisymmetric twin of a shell3d scene, and the deviations of punch force and
// thickness strain at the output travels. Used by tests/shell3d and the benchmark.
#pragma once

#include <string>
#include <vector>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs::shell3d {

// The same scene as an axisymmetric one with `elements` meridian elements (uniform grading).
// Requires a circular blank. Its numerics.max_travel_increment_per_length is at most
// kTwinTravelIncrementPerLength and its numerics.strain_rate_cutoff at most the default (1e-4):
// the reference is run converged in the travel step and at the default cut-off even when the 3D
// scene (or the scene default) relaxes them to save time. Its step grid has the axisymmetric
// defaults (contact events, no graded start), two solves per implicit step and new contacts in the
// first solve (numerics.contact_entry).
Scene axisymmetric_twin(const Scene& shell3d_scene, int elements);

// The twin's travel step, in element lengths: 0.025, the explicit update's stability cap and the
// scene default until Nov 2026. The twin is a reference, so its step is set for convergence, not
// speed: at the scene default (0.25 with the implicit update, a 0.5 mm grid on 2 mm elements)
// the 30- and 40-element twins of ex4a (friction 0.2) differ by 2.6 % in mean force at 1-2 mm,
// against 0.8 % at 0.025 (ExperimentsQuick.Shell3dQuarterDiscFollowsAxisymmetricTwin).
constexpr double kTwinTravelIncrementPerLength = 0.025;

struct TravelComparison {
  double punch_travel_mm = 0.0;
  double force_3d_N = 0.0;
  double force_axisym_N = 0.0;
  double force_deviation = 0.0;  // (3D - axisym) / axisym
  // The same for the mean force over the travel window [travel - window, travel] (work done in
  // the window / window): both solvers add contact-event spikes of a few per cent to the force
  // at any one travel (a node snapping onto the punch; the axisymmetric reference itself moves
  // by 2-3 % between 30 and 40 elements at 5 mm), which the mean filters out.
  double mean_force_3d_N = 0.0;
  double mean_force_axisym_N = 0.0;
  double mean_force_deviation = 0.0;
  // Largest |eps_t,3D - eps_t,axisym| over the nodes of each line (axisym interpolated at the
  // node's initial radius).
  double eps_thickness_deviation_y0 = 0.0;
  double eps_thickness_deviation_x0 = 0.0;
  double eps_thickness_deviation_diagonal = 0.0;
  double max_eps_thickness_deviation() const;
  // Largest |eps_t| of the axisymmetric profile (the scale of a relative thickness-strain
  // deviation).
  double max_abs_eps_thickness_axisym = 0.0;
};

// One entry per travel of scene.process.output_travels_mm that both runs reached.
std::vector<TravelComparison> compare_with_axisymmetric(const Scene& shell3d_scene,
                                                        const RunResult& shell,
                                                        const RunResult& axisym,
                                                        double window_mm = 1.0);

// Mean punch force of the piecewise linear load-travel curve over [a, b] (clipped to the data).
double mean_force(const std::vector<StepRecord>& steps, double a, double b);

}  // namespace vs::shell3d
