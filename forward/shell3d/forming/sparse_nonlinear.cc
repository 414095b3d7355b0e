#include "shell3d/forming/sparse_nonlinear.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace vs::shell3d {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
double relative(double num, double den) { return den > 0.0 ? num / den : num; }

}  // namespace

NonlinearSummary solve_sparse_nonlinear(SparseNonlinearProblem& problem,
                                        const NonlinearOptions& options, SparseSpdSolver* solver,
                                        Eigen::VectorXd* x, SparseSolveTimings* timings) {
  NonlinearSummary sum;
  Eigen::VectorXd r;
  double p0 = 0.0;
  const bool newton_allowed = options.kind == vs::SolverKind::kNewton;
  auto evaluate = [&](double theta) {
    const auto t0 = Clock::now();
    const double scale = problem.evaluate(*x, theta, &r, &p0);
    timings->assembly_s += since(t0);
    return scale;
  };
  auto potential = [&](const Eigen::VectorXd& y) {
    const auto t0 = Clock::now();
    const double p = problem.potential(y);
    timings->assembly_s += since(t0);
    return p;
  };
  auto factorize = [&]() {
    const auto t0 = Clock::now();
    if (solver->analyses() == 0) solver->analyze(problem.matrix());
    const bool ok = solver->factorize(problem.matrix());
    ++timings->factorisations;
    timings->factorisation_s += since(t0);
    return ok;
  };
  auto solve = [&]() {
    const auto t0 = Clock::now();
    Eigen::VectorXd dx = -solver->solve(r);
    timings->factorisation_s += since(t0);
    return dx;
  };
  // The forming model's tangent is primal-dual (forming_model.h): the first tangent of a solve is
  // the direct iteration's matrix, later ones move to Newton's by themselves, so every solve
  // starts at tangent weight 1 without direct iterations, as the axisymmetric solver does for its
  // self-starting problem (options.picard_before_newton and initial_theta are not used). Measured
  // on ex4a (n = 4, sticking, 4 mm): 78 instead of 121 iterations, every step a full one.
  constexpr int picard_before_newton = 0;
  constexpr double initial_theta = 1.0;
  double theta = 0.0;
  // An evaluation at the current x made by the previous iteration's full-step trial.
  bool have_eval = false;
  double eval_theta = 0.0, eval_scale = 0.0;
  if (options.verbose) std::fprintf(stderr, "    iter  theta   |dx|/|x|    |r|/|f|     alpha\n");
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (newton_allowed && it == picard_before_newton + 1) theta = initial_theta;
    double used_theta = theta;
    double scale = (have_eval && eval_theta == used_theta) ? eval_scale : evaluate(used_theta);
    have_eval = false;
    if (!r.allFinite()) {
      sum.message = "residual is not finite";
      return sum;
    }
    sum.residual_norm = relative(r.norm(), scale);
    const bool factored = factorize();
    Eigen::VectorXd dx;
    double alpha = 1.0;
    bool accepted = false;
    if (used_theta > 0.0 && factored) {
      dx = solve();
      const double slope = r.dot(dx);
      accepted = slope < 0.0 && dx.allFinite();
      // A step that already passes the convergence test below ends the solve: accepted without
      // evaluating the new point (its matrix would not be used).
      const bool final_step = it > 1 && sum.residual_norm <= options.tolerance &&
                              dx.norm() <= options.tolerance * (*x + dx).norm();
      if (accepted && !final_step && -slope > 1e-13 * std::abs(p0)) {
        // Full step first, evaluated completely with the tangent weight it would lead to.
        const double next_theta = theta > 0.98 ? 1.0 : 1.0 - 0.25 * (1.0 - theta);
        const double p_start = p0;
        const Eigen::VectorXd x_start = *x;
        const Eigen::VectorXd r_start = r;
        *x += dx;
        const double trial_scale = evaluate(next_theta);
        if (p0 <= p_start + 1e-4 * slope && r.allFinite()) {
          have_eval = true;
          eval_theta = next_theta;
          eval_scale = trial_scale;
        } else {
          alpha = 0.5;
          while (potential(x_start + alpha * dx) > p_start + 1e-4 * alpha * slope) {
            alpha *= 0.5;
            if (alpha < 1.0 / 16.0) {
              accepted = false;
              break;
            }
          }
        }
        *x = x_start;
        if (!have_eval) {
          r = r_start;
          p0 = p_start;
        }
      }
      if (accepted) {
        const double keep = alpha == 1.0 ? 0.25 : 0.5;
        theta = theta > 0.98 ? 1.0 : 1.0 - keep * (1.0 - theta);
      } else {
        theta = theta < 0.05 ? 0.0 : 0.25 * theta;
      }
    }
    if (!accepted) {
      if (used_theta > 0.0 || !factored) {
        scale = evaluate(0.0);
        sum.residual_norm = relative(r.norm(), scale);
        if (!factorize()) {
          sum.message = "secant matrix is not positive definite";
          return sum;
        }
      }
      used_theta = 0.0;
      alpha = 1.0;
      dx = solve();
      ++sum.picard_steps;
      if (newton_allowed && it > picard_before_newton && theta == 0.0) theta = 0.1;
    } else {
      ++sum.newton_steps;
    }
    *x += alpha * dx;
    sum.iterations = it;
    sum.update_norm = relative(alpha * dx.norm(), x->norm());
    if (options.verbose) {
      std::fprintf(stderr, "    %4d  %.3f  %.3e   %.3e   %.3f\n", it, used_theta, sum.update_norm,
                   sum.residual_norm, alpha);
    }
    if (problem.update_lagged(*x)) have_eval = false;
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

}  // namespace vs::shell3d
