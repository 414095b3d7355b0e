#include "shell3d/forming/sparse_nonlinear.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

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
                                        Eigen::VectorXd* x, SparseSolveTimings* timings,
                                        bool reuse_factorisation) {
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
  auto evaluate_residual = [&]() {
    const auto t0 = Clock::now();
    const double scale = problem.evaluate_residual(*x, &r, &p0);
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
  // The forming model's tangent is primal-dual (forming_model.h): the first tangent of a run is
  // the direct iteration's matrix, later ones move to Newton's by themselves (and a solve's first
  // one is linearised about the previous solve), so every solve starts at tangent weight 1
  // without direct iterations, as the axisymmetric solver does for its self-starting problem
  // (options.picard_before_newton and initial_theta are not used). Measured on ex4a (n = 4,
  // sticking, 4 mm): 78 instead of 121 iterations, every step a full one.
  constexpr int picard_before_newton = 0;
  constexpr double initial_theta = 1.0;
  double theta = 0.0;
  // An evaluation at the current x made by the previous iteration's full-step trial.
  bool have_eval = false;
  double eval_theta = 0.0, eval_scale = 0.0;
  // Chord steps (sparse_nonlinear.h). Measured on ex4a (n = 4, punch friction 0.2, 10 mm, speed
  // setting): factorisations 572 -> 280 with the same answers; the Newton tail of the
  // regularised Coulomb friction converges only linearly, so a reused factorisation loses little
  // per iteration there. Accepting any non-growing chord update stalled (contraction 0.93 over
  // 100 iterations); kChordStart 1e-2 / 3e-2 / 1e-1 gave 1 133 / 1 057 / 989 factorisations over
  // 30 mm at equal run time (more residual evaluations).
  constexpr double kChordStart = 3e-2;
  constexpr double kChordContraction = 0.5;
  bool chord = false;
  double last_update = 0.0;  // |dx| of the last accepted step
  // After an accepted iterate: the lagged quantities (refreshing the evaluation in hand, if any)
  // and the stopping test.
  auto finish_iteration = [&](int it) {
    if (problem.update_lagged(*x) && (have_eval || chord)) {
      const auto t0 = Clock::now();
      const bool fresh = problem.refresh(*x, &r, &p0);
      have_eval = have_eval && fresh;
      chord = chord && fresh;
      timings->assembly_s += since(t0);
    }
    if (!nonlinear_converged(options, sum, it)) return false;
    sum.converged = true;
    sum.message = fmt::format("converged in {} iterations", it);
    return true;
  };
  if (reuse_factorisation && solver->analyses() > 0) {
    eval_scale = evaluate_residual();
    chord = true;
    last_update = std::numeric_limits<double>::infinity();
  }
  if (options.verbose) std::fprintf(stderr, "    iter  theta   |dx|/|x|    |r|/|f|     alpha\n");
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (newton_allowed && it == picard_before_newton + 1) theta = initial_theta;
    if (chord) {
      chord = false;
      sum.residual_norm = relative(r.norm(), eval_scale);
      Eigen::VectorXd dx = solve();
      const double slope = r.dot(dx);
      bool ok = slope < 0.0 && dx.allFinite() && dx.norm() <= kChordContraction * last_update;
      const bool final_step = sum.residual_norm <= options.tolerance &&
                              dx.norm() <= options.tolerance * (*x + dx).norm();
      if (ok && !final_step) {
        const double p_start = p0;
        const Eigen::VectorXd x_start = *x, r_start = r;
        *x += dx;
        eval_scale = evaluate_residual();
        ok = p0 <= p_start + 1e-4 * slope && r.allFinite();
        if (!ok) {
          *x = x_start;
          r = r_start;
          p0 = p_start;
        }
      }
      if (ok) {
        ++sum.chord_steps;
        if (final_step) *x += dx;
        sum.iterations = it;
        last_update = dx.norm();
        sum.update_norm = relative(last_update, x->norm());
        if (options.verbose) {
          std::fprintf(stderr, "    %4d  chord  %.3e   %.3e   %.3f\n", it, sum.update_norm,
                       sum.residual_norm, 1.0);
        }
        chord = !final_step;
        if (finish_iteration(it)) return sum;
        continue;
      }
      have_eval = false;  // a Newton iteration at the same x
    }
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
        const bool to_chord = theta > 0.98 && dx.norm() <= kChordStart * x->norm();
        const double trial_scale = to_chord ? evaluate_residual() : evaluate(next_theta);
        if (p0 <= p_start + 1e-4 * slope && r.allFinite()) {
          have_eval = !to_chord;
          chord = to_chord;
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
        if (!have_eval && !chord) {
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
    last_update = alpha * dx.norm();
    sum.update_norm = relative(last_update, x->norm());
    if (options.verbose) {
      std::fprintf(stderr, "    %4d  %.3f  %.3e   %.3e   %.3f\n", it, used_theta, sum.update_norm,
                   sum.residual_norm, alpha);
    }
    if (finish_iteration(it)) return sum;
  }
  sum.message = fmt::format("no convergence in {} iterations (|dx|/|x| = {:.2e}, |r|/|f| = {:.2e})",
                            options.max_iterations, sum.update_norm, sum.residual_norm);
  return sum;
}

}  // namespace vs::shell3d
