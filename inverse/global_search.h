// Global search for poor starting points: NLopt multistart (MLSL with low-discrepancy starts and
// a derivative-free local BOBYQA by default) on the same objective as the least-squares polish,
// with an explicit seed and a hard evaluation limit (global NLopt algorithms stop only on
// maxeval/maxtime). Evaluations are sequential; the polish that follows is parallel.
#pragma once

#include <Eigen/Core>
#include <string>

#include "objective.h"

namespace vs {

struct GlobalSearchOptions {
  // "mlsl_lds" (GN_MLSL_LDS + LN_BOBYQA), "crs2" (GN_CRS2_LM), "direct" (GN_DIRECT_L),
  // "bobyqa" (local LN_BOBYQA only, from the start point).
  std::string algorithm = "mlsl_lds";
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
  std::string result;  // NLopt's return code, e.g. MAXEVAL_REACHED
};

// Every free parameter needs finite bounds. A failed forward evaluation is given a cost of ten
// times the worst successful cost so far (finite: BOBYQA's quadratic models break on HUGE_VAL).
GlobalSearchSummary global_search(Objective& objective, const Eigen::VectorXd& x0,
                                  const GlobalSearchOptions& options);

}  // namespace vs
