// Options of a forward run (both geometries): callbacks and diagnostics that do not change the
// answer. The numerics that do are scene keys (numerics.*).
#pragma once

#include <functional>

#include "run/run_result.h"
#include "stepping/step_driver_options.h"

namespace vs {

struct RunOptions {
  // Called after every converged step (progress line, streaming writers). May be empty.
  std::function<void(const StepRecord&)> on_step;
  // Print the nonlinear iteration table to stderr.
  bool verbose = false;
  // Axisymmetric runs: Coulomb friction from the current normal reactions, with their derivative
  // in Newton's matrix (true), or from the reactions lagged by one iteration and relaxed (false;
  // the formulation before Nov 2026, kept for comparison). Both converge to the same solution;
  // the first needs 2-3x fewer iterations with friction and falls back to the second for a solve
  // it cannot converge (RunResult::friction_fallbacks). The 3D solver always lags them.
  bool consistent_friction = true;
  // 3D runs: a Newton matrix of at least this many unknowns is first solved by conjugate
  // gradients preconditioned with the factorisation of an earlier one (NewtonOptions::
  // krylov_max_iterations, solver/newton.h), and factorised only when that does not converge.
  // The answer is the same to the nonlinear tolerance, not to round-off (the inexact steps take
  // another path). Measured on ex4a (friction 0.2, implicit, 10 mm, quiet 2-core machine): 4 085
  // unknowns (8 divisions) 5.04 -> 4.31 s, 9 005 (12) 26.7 -> 15.6 s; smaller meshes run in a
  // few seconds either way and keep the exact Newton path, on which two equal descriptions of a
  // law give the same run to round-off (tests/shell3d/planar_anisotropy_test.cc). INT_MAX: never.
  int krylov_min_unknowns = 4000;
  // 3D runs: the conjugate gradients of the Krylov steps precondition with, and the chord steps
  // solve with, a single-precision copy of the held CHOLMOD factorisation
  // (linalg/supernodal_factor.h) rather than the double one. A Newton step on a matrix
  // just factorised solves in double precision either way.
  bool single_precision_preconditioner = true;
  // 3D runs: every numeric factorisation after the first of an analysis on two threads
  // (linalg/supernodal_cholesky.h) rather than by CHOLMOD on one. Same answers to round-off; the
  // run has the same bits for any number of threads either way.
  bool parallel_factorisation = true;
  // The step driver's constants (stepping/step_driver_options.h); a run with invalid ones fails
  // at once with the reason.
  StepDriverOptions driver;
};

}  // namespace vs
