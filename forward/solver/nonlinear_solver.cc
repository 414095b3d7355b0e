#include "solver/nonlinear_solver.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vs {

namespace {

double relative(double num, double den) { return den > 0.0 ? num / den : num; }

}  // namespace

bool nonlinear_converged(const NonlinearOptions& options, const NonlinearSummary& sum,
                         int iteration) {
  const bool small_update = sum.update_norm <= options.tolerance;
  const bool small_residual =
      options.kind == SolverKind::kPicard || sum.residual_norm <= options.tolerance;
  const bool stagnated =
      sum.update_norm <= 1e-3 * options.tolerance && sum.residual_norm <= 100.0 * options.tolerance;
  return ((small_update && small_residual) || stagnated) && iteration > 1;
}

NonlinearSummary solve_nonlinear(NonlinearProblem& problem, const NonlinearOptions& options,
                                 Eigen::VectorXd* x) {
  NonlinearSummary sum;
  BlockTridiag K;
  Eigen::VectorXd r, dx, trial;
  const bool newton_allowed = options.kind == SolverKind::kNewton;
  // Tangent weight: 0 = direct (secant) iteration, 1 = Newton. Adapted like a trust region: a
  // full step accepted by the line search moves it towards 1, a rejected step back towards 0.
  double theta = 0.0;
  const bool self_starting = problem.self_starting();
  const int picard_before_newton = self_starting ? 0 : options.picard_before_newton;
  const double initial_theta = self_starting ? 1.0 : options.initial_theta;
  if (options.verbose) std::fprintf(stderr, "    iter  theta   |dx|/|x|    |r|/|f|     alpha\n");
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (newton_allowed && it == picard_before_newton + 1) theta = initial_theta;
    double used_theta = theta;
    double p0 = 0.0;
    double scale = problem.evaluate(*x, used_theta, &K, &r, &p0);
    if (!r.allFinite()) {
      sum.message = "residual is not finite";
      return sum;
    }
    sum.residual_norm = relative(r.norm(), scale);
    bool factored = K.factorize();
    if (factored) sum.condition_estimate = std::max(sum.condition_estimate, K.condition_estimate());
    double alpha = 1.0;
    bool accepted = false;
    if (used_theta > 0.0 && factored) {
      dx = -r;
      K.solve_in_place(&dx);
      problem.set_direction(*x, dx);
      // Armijo backtracking on the convex flow potential; in the round-off regime, or when the
      // full step already passes the convergence test below (it ends the solve), accept.
      const double slope = r.dot(dx);
      accepted = slope < 0.0;
      const bool final_step = it > 1 && sum.residual_norm <= options.tolerance &&
                              dx.norm() <= options.tolerance * (*x + dx).norm();
      if (accepted && !final_step && -slope > 1e-13 * std::abs(p0)) {
        while (problem.potential(trial = *x + alpha * dx, alpha) > p0 + 1e-4 * alpha * slope) {
          alpha *= 0.5;
          if (alpha < 1.0 / 16.0) {
            accepted = false;
            break;
          }
        }
      }
      // Any accepted step moves towards Newton (faster for a full step); a rejected one back
      // towards the direct iteration. Measured on ex1 with sticking friction: keeping theta after
      // a damped step stalls at |r|/|f| ~ 0.1, moving it on converges.
      if (accepted) {
        const double keep = alpha == 1.0 ? 0.25 : 0.5;
        theta = theta > 0.98 ? 1.0 : 1.0 - keep * (1.0 - theta);
      } else {
        theta = theta < 0.05 ? 0.0 : 0.25 * theta;
      }
    }
    if (!accepted) {
      // Direct iteration: always SPD and monotone in the potential (Kacanov).
      if (used_theta > 0.0) {
        scale = problem.evaluate(*x, 0.0, &K, &r, &p0);
        sum.residual_norm = relative(r.norm(), scale);
        if (!K.factorize()) {
          sum.message = "secant matrix is not positive definite";
          return sum;
        }
      } else if (!factored) {
        sum.message = "secant matrix is not positive definite";
        return sum;
      }
      used_theta = 0.0;
      alpha = 1.0;
      dx = -r;
      K.solve_in_place(&dx);
      problem.set_direction(*x, dx);
      ++sum.picard_steps;
      if (newton_allowed && it > picard_before_newton && theta == 0.0) {
        theta = 0.1;  // try blending again next iteration
      }
    } else {
      ++sum.newton_steps;
    }
    *x += alpha * dx;
    problem.step_taken(alpha);
    sum.iterations = it;
    sum.update_norm = relative(alpha * dx.norm(), x->norm());
    if (options.verbose) {
      std::fprintf(stderr, "    %4d  %.3f  %.3e   %.3e   %.3f\n", it, used_theta, sum.update_norm,
                   sum.residual_norm, alpha);
    }
    problem.update_lagged(*x);
    if (nonlinear_converged(options, sum, it)) {
      sum.converged = true;
      sum.message = fmt::format("converged in {} iterations", it);
      return sum;
    }
  }
  sum.message = fmt::format("no convergence in {} iterations (|dx|/|x| = {:.2e}, |r|/|f| = {:.2e})",
                            options.max_iterations, sum.update_norm, sum.residual_norm);
  return sum;
}

}  // namespace vs
