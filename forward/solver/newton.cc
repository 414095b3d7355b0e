#include "solver/newton.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace vs {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
double relative(double num, double den) { return den > 0.0 ? num / den : num; }

// Armijo sufficient-decrease constant and the smallest step the backtracking tries.
constexpr double kArmijo = 1e-4;
constexpr double kMinAlpha = 1.0 / 16.0;

}  // namespace

double NewtonProblem::evaluate_residual(const Eigen::VectorXd& /*x*/, Eigen::VectorXd* /*residual*/,
                                        double* /*potential*/) {
  throw std::logic_error("NewtonProblem::evaluate_residual: this problem has no chord steps");
}

bool NewtonOptions::IsValid(std::string* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!(tolerance > 0.0 && tolerance < 1.0)) return fail("tolerance must be in (0, 1)");
  if (max_iterations < 1) return fail("max_iterations must be at least 1");
  if (picard_before_newton < 0) return fail("picard_before_newton must be >= 0");
  if (!(initial_theta > 0.0 && initial_theta <= 1.0))
    return fail("initial_theta must be in (0, 1]");
  if (!(chord_start >= 0.0 && chord_start < 1.0)) return fail("chord_start must be in [0, 1)");
  if (!(chord_contraction > 0.0 && chord_contraction < 1.0))
    return fail("chord_contraction must be in (0, 1)");
  if (krylov_max_iterations < 0) return fail("krylov_max_iterations must be >= 0");
  if (!(krylov_tolerance > 0.0 && krylov_tolerance < 1.0))
    return fail("krylov_tolerance must be in (0, 1)");
  if (!(force_floor >= 0.0)) return fail("force_floor must be >= 0");
  if (!(stagnation_force >= 0.0)) return fail("stagnation_force must be >= 0");
  return true;
}

bool newton_converged(const NewtonOptions& options, const NewtonSummary& sum, int iteration) {
  const bool small_update = sum.update_norm <= options.tolerance;
  const bool small_residual =
      options.kind == SolverKind::kPicard || sum.residual_norm <= options.tolerance;
  // A residual at round-off of a sheet that moves rigidly with next to no force (a drawn cup
  // riding on the punch) is tiny against the sheet's characteristic force but not against its
  // internal forces, which are round-off themselves: the update has vanished, so that is
  // stagnation too (measured: ESAFORM cups, force holder, 1.3e-5 N against 6 kN).
  const bool stagnated = sum.update_norm <= 1e-3 * options.tolerance &&
                         (sum.residual_norm <= 100.0 * options.tolerance ||
                          sum.residual_abs <= options.tolerance * options.stagnation_force);
  return ((small_update && small_residual) || stagnated) && iteration > 1;
}

NewtonSummary solve_newton(NewtonProblem& problem, const NewtonOptions& options, Eigen::VectorXd* x,
                           bool reuse_factorisation) {
  NewtonSummary sum;
  LinearSolver& linear = problem.linear_solver();
  Eigen::VectorXd r, dx;
  double p0 = 0.0;
  const bool newton_allowed = options.kind == SolverKind::kNewton;
  const bool chords = newton_allowed && options.chord_start > 0.0;

  // The residual's norms for the stopping test: relative to max(scale, force floor), and absolute.
  auto record_residual = [&](double scale) {
    sum.residual_abs = r.norm();
    sum.residual_norm = relative(sum.residual_abs, std::max(scale, options.force_floor));
  };
  auto evaluate = [&](double theta) {
    const auto t0 = Clock::now();
    const double scale = problem.evaluate(*x, theta, &r, &p0);
    sum.assembly_s += since(t0);
    return scale;
  };
  auto evaluate_residual = [&]() {
    const auto t0 = Clock::now();
    const double scale = problem.evaluate_residual(*x, &r, &p0);
    sum.assembly_s += since(t0);
    return scale;
  };
  auto potential = [&](const Eigen::VectorXd& y, double alpha) {
    const auto t0 = Clock::now();
    const double p = problem.potential(y, alpha);
    sum.assembly_s += since(t0);
    return p;
  };
  auto factorize = [&]() {
    const auto t0 = Clock::now();
    const bool ok = linear.factorize();
    ++sum.factorisations;
    sum.factorisation_s += since(t0);
    return ok;
  };
  // dx = -K^-1 r; approximately (the solver's cheaper solve) for a chord step.
  auto solve = [&](bool approximate = false) {
    const auto t0 = Clock::now();
    dx = -r;
    if (approximate) {
      linear.solve_approximately_in_place(&dx);
    } else {
      linear.solve_in_place(&dx);
    }
    sum.factorisation_s += since(t0);
  };
  // Whether the linear solver's factorisation fits this problem (a preconditioner for its
  // matrices), and the Krylov step dx ~ -K^-1 r on it.
  bool held = reuse_factorisation && linear.has_factorization();
  auto krylov_solve = [&]() {
    const auto t0 = Clock::now();
    int iterations = 0;
    // Forcing term of Dembo, Eisenstat and Steihaug (SIAM J. Numer. Anal. 19, 1982): a linear
    // residual of sqrt(|r|/|f|) of the nonlinear one keeps Newton's convergence superlinear
    // (order 1.5); far from the solution a loose solve is enough.
    const double eta = std::clamp(std::sqrt(sum.residual_norm), options.krylov_tolerance, 0.5);
    const bool ok =
        linear.solve_preconditioned(-r, &dx, eta, options.krylov_max_iterations, &iterations);
    sum.krylov_iterations += iterations;
    sum.factorisation_s += since(t0);
    return ok;
  };

  // Tangent weight: 0 = direct (secant) iteration, 1 = Newton.
  double theta = 0.0;
  const bool self_starting = problem.self_starting();
  const int picard_before_newton = self_starting ? 0 : options.picard_before_newton;
  const double initial_theta = self_starting ? 1.0 : options.initial_theta;
  // An evaluation at the current x made by the previous iteration's full-step trial.
  bool have_eval = false;
  double eval_theta = 0.0, eval_scale = 0.0;
  bool chord = false;        // the next iteration is a chord step on the last factorisation
  double last_update = 0.0;  // |dx| of the last accepted step

  // After an accepted iterate: the lagged quantities (refreshing the evaluation in hand, if any)
  // and the stopping test.
  auto finish_iteration = [&](int it) {
    if (problem.update_lagged(*x) && (have_eval || chord)) {
      const auto t0 = Clock::now();
      const bool fresh = problem.refresh(*x, &r, &p0);
      have_eval = have_eval && fresh;
      chord = chord && fresh;
      sum.assembly_s += since(t0);
    }
    if (!newton_converged(options, sum, it)) return false;
    sum.converged = true;
    sum.message = fmt::format("converged in {} iterations", it);
    return true;
  };

  if (chords && reuse_factorisation && linear.has_factorization()) {
    eval_scale = evaluate_residual();
    chord = true;
    last_update = std::numeric_limits<double>::infinity();
  }
  if (options.verbose) std::fprintf(stderr, "    iter  theta   |dx|/|x|    |r|/|f|     alpha\n");
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (newton_allowed && it == picard_before_newton + 1) theta = initial_theta;
    if (chord) {
      chord = false;
      record_residual(eval_scale);
      solve(/*approximate=*/true);
      const double slope = r.dot(dx);
      bool ok =
          slope < 0.0 && dx.allFinite() && dx.norm() <= options.chord_contraction * last_update;
      const bool final_step = sum.residual_norm <= options.tolerance &&
                              dx.norm() <= options.tolerance * (*x + dx).norm();
      if (ok && !final_step) {
        const double p_start = p0;
        const Eigen::VectorXd x_start = *x, r_start = r;
        *x += dx;
        eval_scale = evaluate_residual();
        ok = p0 <= p_start + kArmijo * slope && r.allFinite();
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
    record_residual(scale);
    const bool krylov =
        used_theta > 0.0 && held && options.krylov_max_iterations > 0 && krylov_solve();
    bool factored = false;
    if (!krylov) {
      factored = factorize();
      held = factored;
      if (factored)
        sum.condition_estimate = std::max(sum.condition_estimate, linear.condition_estimate());
    }
    double alpha = 1.0;
    bool accepted = false;
    if (used_theta > 0.0 && (factored || krylov)) {
      if (!krylov) solve();
      problem.set_direction(*x, dx);
      // Armijo backtracking on the convex flow potential; in the round-off regime, or when the
      // full step already passes the convergence test below (it ends the solve without
      // evaluating its end point), accept.
      const double slope = r.dot(dx);
      accepted = slope < 0.0 && dx.allFinite();
      const bool final_step = it > 1 && sum.residual_norm <= options.tolerance &&
                              dx.norm() <= options.tolerance * (*x + dx).norm();
      if (accepted && !final_step && -slope > 1e-13 * std::abs(p0)) {
        bool backtrack = true;
        if (options.full_step_evaluation) {
          // Full step first, evaluated completely with the tangent weight it would lead to.
          const double next_theta = theta > 0.98 ? 1.0 : 1.0 - 0.25 * (1.0 - theta);
          const double p_start = p0;
          const Eigen::VectorXd x_start = *x, r_start = r;
          *x += dx;
          const bool to_chord =
              chords && theta > 0.98 && dx.norm() <= options.chord_start * x->norm();
          const double trial_scale = to_chord ? evaluate_residual() : evaluate(next_theta);
          if (p0 <= p_start + kArmijo * slope && r.allFinite()) {
            backtrack = false;
            have_eval = !to_chord;
            chord = to_chord;
            eval_theta = next_theta;
            eval_scale = trial_scale;
          } else {
            alpha = 0.5;
          }
          *x = x_start;
          if (!have_eval && !chord) {
            r = r_start;
            p0 = p_start;
          }
        }
        if (backtrack) {
          while (potential(*x + alpha * dx, alpha) > p0 + kArmijo * alpha * slope) {
            alpha *= 0.5;
            if (alpha < kMinAlpha) {
              accepted = false;
              break;
            }
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
        scale = evaluate(0.0);
        record_residual(scale);
        held = factorize();
        if (!held) {
          sum.message = "secant matrix is not positive definite";
          return sum;
        }
      } else if (!factored) {
        sum.message = "secant matrix is not positive definite";
        return sum;
      }
      used_theta = 0.0;
      alpha = 1.0;
      solve();
      problem.set_direction(*x, dx);
      ++sum.picard_steps;
      if (newton_allowed && it > picard_before_newton && theta == 0.0) {
        theta = 0.1;  // try blending again next iteration
      }
    } else {
      ++sum.newton_steps;
      if (krylov) ++sum.krylov_steps;
    }
    *x += alpha * dx;
    problem.step_taken(alpha);
    sum.iterations = it;
    last_update = alpha * dx.norm();
    sum.update_norm = relative(last_update, x->norm());
    if (options.verbose) {
      std::fprintf(stderr, "    %4d  %.3f  %.3e   %.3e   %.3f%s\n", it, used_theta, sum.update_norm,
                   sum.residual_norm, alpha, krylov ? "  krylov" : "");
    }
    if (finish_iteration(it)) return sum;
  }
  sum.message = fmt::format("no convergence in {} iterations (|dx|/|x| = {:.2e}, |r|/|f| = {:.2e})",
                            options.max_iterations, sum.update_norm, sum.residual_norm);
  return sum;
}

}  // namespace vs
