// Checks of a finished run whose results may be numerically meaningless although the run
// completed: a load-travel curve that is noise (e.g. a sheet 1e-4 times the punch radius thick:
// hundreds of slope reversals), and stress resultants that do not carry the punch force through
// the free wall (axisymmetric). The warnings go to run.json and stderr with the run's own.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs {

// Roughness of the punch force over the steps. A force increment smaller than 1e-6 of the
// largest |force| counts as flat (no sign); a reversal is a change of sign between two
// consecutive non-flat increments.
struct LoadCurveNoise {
  int increments = 0;  // non-flat force increments
  int reversals = 0;   // slope reversals among them
  // Root mean square of the second differences F[k+1] - 2 F[k] + F[k-1] over the steps, divided
  // by the largest |force| (0 for fewer than 3 steps or no force).
  double rms_second_difference = 0.0;
  // Noise-like: at least kMinReversals reversals and at least kReversalFraction of the
  // increments reversing. A forming curve rises, peaks and falls; contact events and ironing add
  // a few wiggles. Measured (default numerics): ex1 16 reversals in 1046 increments, ex2 16 in
  // 1228, the ex3 cup 112 in 1584 (7 %, ironing) and 90 in 1604 with the fixed-gap holder,
  // ex4a (3D, sticking, 30 mm) 24 in 501; ex1 with thickness 1e-4 x the punch radius 678 in 1104
  // (61 %).
  bool noise_like = false;
  static constexpr int kMinReversals = 20;
  static constexpr double kReversalFraction = 0.25;
};

LoadCurveNoise load_curve_noise(const std::vector<StepRecord>& steps);

// Equilibrium of the free wall in an axisymmetric profile: the largest relative deviation of the
// vertical force through element-midpoint circles (Profile::vertical_force_N, from the stress
// resultants in the written configuration) from the punch force on the nodes inside each circle,
// over the free (contact-free) stretch of at least 3 elements that carries the largest mean
// |vertical force|: the unsupported wall between punch and die (a free flat bottom carries
// nothing, a stretch beyond the die only part of the load). The elements next to a contact zone
// are skipped (their end node carries a reaction). The punch force on the nodes inside a circle
// is the sum of Profile::punch_force_node_N over them, or the whole `punch_force_N` if that is
// empty: once a cup wall outside the circle is ironed against the punch, the punch acts there too
// (friction). NaN when the profile has no resultants (3D lines), no punch force or no such
// stretch. A converged solve in the configuration it is written in balances to the solver
// tolerance (experiments/03_stability: <= 0.33 % on every bundled and extreme case but one).
double free_wall_equilibrium_error(const Profile& p, double punch_force_N);

// The largest free_wall_equilibrium_error over the run's profiles, each with the step written at
// its travel, and that travel; NaN (and 0) when no profile is measured.
struct FreeWallEquilibrium {
  double error = std::numeric_limits<double>::quiet_NaN();
  double travel_mm = 0.0;
};
FreeWallEquilibrium free_wall_equilibrium(const RunResult& result);

// The warning threshold of free_wall_equilibrium_error (experiments/03_stability's GARBAGE
// verdict). Above it the resultants and the punch force disagree, as in the implicit update's
// weakly damped stiff mode of a membrane-thin sheet (ex1 at h = 1e-4 x the punch radius, 20 mm:
// 4.4 %, with the force itself right: 277.8 N against 277.7 N at a fifth of the step).
inline constexpr double kFreeWallEquilibriumWarning = 0.02;

// One line per suspect feature of `result` (empty when none).
std::vector<std::string> suspect_result_warnings(const RunResult& result);

}  // namespace vs
