// Global search for poor starting points: NLopt multistart (MLSL with low-discrepancy starts and
// a derivative-free local BOBYQA by default) on the same objective as the least-squares polish,
// with an explicit seed and a hard evaluation limit (global NLopt algorithms stop only on
// maxeval/maxtime). NLopt's evaluations are sequential; the polish that follows is parallel.
//
// "surface" is for a forward model that is not smooth at the level a local search resolves (a
// 3D cup whose contact events jitter its outputs, experiments/10_earing): the cost on a grid of
// grid_points per free parameter around the start (+- grid_half_width scales, clipped to the
// bounds; evaluated in parallel batches), a least-squares quadratic through the grid's costs in
// the grid's own coordinates u in [-1, 1]^n,
//   c(u) = c0 + g.u + 1/2 u^T H u,
// and its minimum u* = -H^-1 g (clipped to the grid box) evaluated as the answer. The quadratic
// averages the noise over the grid instead of following it into a dip; when H is not positive
// definite (no bowl on the grid) the best grid point is the answer. surface_rms is the costs'
// rms scatter about the quadratic (noise plus the quadratic's own misfit), a measure of how
// rough the cost is. With surface_rounds > 1 the search zooms: each next round is the same grid
// centred on the previous round's answer with half its half width (a grid too wide for the
// cost's curvature puts the quadratic's minimum off; the next, narrower grid corrects it, while
// still averaging over the noise as long as the grid spans more than the noise's scale). The
// answer is the last round's.
#pragma once

#include <Eigen/Core>
#include <string>

#include "objective.h"

namespace vs {

struct GlobalSearchOptions {
  // "mlsl_lds" (GN_MLSL_LDS + LN_BOBYQA), "crs2" (GN_CRS2_LM), "direct" (GN_DIRECT_L),
  // "bobyqa" (local LN_BOBYQA only, from the start point), "surface" (the response surface
  // above: surface_rounds (grid_points^n + 1) evaluations, which must fit into max_evaluations).
  std::string algorithm = "mlsl_lds";
  int grid_points = 5;           // per free parameter (surface)
  double grid_half_width = 1.0;  // the grid's half width in parameter scales (surface)
  int surface_rounds = 1;        // zoom rounds, each at half the previous half width (surface)
  // nlopt_srand(seed) before every search: the randomised algorithms become deterministic.
  unsigned long seed = 1;
  int max_evaluations = 200;  // forward evaluations (points), the only stopping rule that counts
  double local_relative_x_tolerance = 1e-3;  // the local searches stay loose; Ceres polishes

  bool IsValid(std::string* why) const;
};

struct GlobalSearchSummary {
  Eigen::VectorXd x;  // best point found (own units)
  double cost = 0.0;  // its 0.5 |r|^2
  int evaluations = 0;
  int failed_evaluations = 0;
  std::string result;        // NLopt's return code, e.g. MAXEVAL_REACHED; surface: SURFACE_MINIMUM
                             // or BEST_GRID_POINT (why)
  double surface_rms = 0.0;  // surface: rms of the grid costs about the quadratic
};

// The number of evaluations "surface" makes for `free_parameters`: surface_rounds (grid_points^n +
// 1).
long surface_evaluations(const GlobalSearchOptions& options, int free_parameters);

// Every free parameter needs finite bounds. A failed forward evaluation is given a cost of ten
// times the worst successful cost so far (finite: BOBYQA's quadratic models break on HUGE_VAL).
GlobalSearchSummary global_search(Objective& objective, const Eigen::VectorXd& x0,
                                  const GlobalSearchOptions& options);

}  // namespace vs
