#include "least_squares.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <memory>

namespace vs {
namespace {

// What the cost function learnt at the last point it differentiated: the callback judges the
// noise floor and the bounds from it (the Jacobian is evaluated at every accepted point before
// Ceres calls the callbacks).
struct LastJacobian {
  bool valid = false;
  Eigen::VectorXd z;         // scaled parameters
  Eigen::VectorXd r;         // residuals
  Eigen::MatrixXd jacobian;  // d r / d z (held columns zero)
};

// One residual block over all data sets and one parameter block z = x / scale.
class CalibrationCost final : public ceres::CostFunction {
 public:
  CalibrationCost(Objective* objective, const std::vector<bool>* held, LastJacobian* last)
      : objective_(objective), held_(held), last_(last) {
    set_num_residuals(objective->num_residuals());
    mutable_parameter_block_sizes()->push_back(objective->num_parameters());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Index p = objective_->num_parameters();
    const Eigen::Index m = objective_->num_residuals();
    const Eigen::VectorXd z = Eigen::Map<const Eigen::VectorXd>(parameters[0], p);
    const Eigen::VectorXd x = z.cwiseProduct(objective_->scale());
    const auto evaluation = objective_->evaluate(x);
    if (!evaluation->ok) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, m) = evaluation->residuals;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const FdJacobian fd = objective_->jacobian(x, *held_);
      if (!fd.ok) return false;
      // d r / d z = d r / d x * scale, row-major as Ceres expects.
      const Eigen::MatrixXd jz = fd.jacobian * objective_->scale().asDiagonal();
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          jacobians[0], m, p) = jz;
      *last_ = {true, z, evaluation->residuals, jz};
    }
    return true;
  }

 private:
  Objective* objective_;
  const std::vector<bool>* held_;
  LastJacobian* last_;
};

// -1 / +1 when z_j sits on its lower / upper bound (to rounding), else 0.
int bound_side(double z, double lower, double upper) {
  const double tol = 1e-12 * std::max(1.0, std::abs(z));
  if (std::isfinite(lower) && z <= lower + tol) return -1;
  if (std::isfinite(upper) && z >= upper - tol) return 1;
  return 0;
}

// The per-iteration checks (progress line, noise floor, a parameter pushed against a bound).
class IterationCheck final : public ceres::IterationCallback {
 public:
  IterationCheck(Objective* objective, const LeastSquaresOptions* options, const double* z,
                 const Eigen::VectorXd* lower_z, const Eigen::VectorXd* upper_z,
                 const std::vector<bool>* held, const LastJacobian* last, int iteration_offset,
                 double time_offset_s)
      : objective_(objective),
        options_(options),
        z_(z),
        lower_z_(lower_z),
        upper_z_(upper_z),
        held_(held),
        last_(last),
        offset_(iteration_offset),
        time_offset_s_(time_offset_s) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    iterations = s.iteration;
    if (options_->progress && (s.iteration > 0 || offset_ == 0)) {
      options_->progress(fmt::format(
          "iter {:3d}  cost {:.6e}  |step| {:.3e}  forward runs {:4d}  {:7.2f} s{}",
          offset_ + s.iteration, s.cost, s.step_norm, objective_->cache().forward_runs(),
          time_offset_s_ + s.cumulative_time_in_seconds,
          s.step_is_successful ? "" : "  (rejected)"));
    }
    const Eigen::Index p = objective_->num_parameters();
    const Eigen::Map<const Eigen::VectorXd> z(z_, p);
    if (!last_->valid || last_->z != z) return ceres::SOLVER_CONTINUE;
    const Eigen::VectorXd g = last_->jacobian.transpose() * last_->r;
    std::vector<bool> moving = *held_;  // true = left out of the decrease
    if (options_->active_set) {
      for (Eigen::Index j = 0; j < p; ++j) {
        if ((*held_)[j]) continue;
        const int side = bound_side(z[j], (*lower_z_)[j], (*upper_z_)[j]);
        // Pushed outward: the cost falls when moving beyond the bound.
        if ((side < 0 && g[j] > 0.0) || (side > 0 && g[j] < 0.0)) newly_held.push_back(j);
      }
      if (!newly_held.empty()) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    floor = noise_floor_cost(last_->r, options_->residual_noise);
    decrease = predicted_decrease(last_->jacobian, last_->r, moving);
    if (options_->residual_noise.size() > 0 && decrease <= floor) {
      at_noise_floor = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

  int iterations = 0;
  std::vector<Eigen::Index> newly_held;
  bool at_noise_floor = false;
  double floor = 0.0;
  double decrease = 0.0;

 private:
  Objective* objective_;
  const LeastSquaresOptions* options_;
  const double* z_;
  const Eigen::VectorXd* lower_z_;
  const Eigen::VectorXd* upper_z_;
  const std::vector<bool>* held_;
  const LastJacobian* last_;
  int offset_ = 0;
  double time_offset_s_ = 0.0;  // earlier active-set passes
};

struct PassResult {
  ceres::Solver::Summary summary;
  int iterations = 0;
  std::vector<Eigen::Index> newly_held;
  bool at_noise_floor = false;
  double floor = 0.0;
  double decrease = 0.0;
};

// One Ceres solve from z with the parameters `held` constant.
PassResult solve_pass(Objective& objective, Eigen::VectorXd& z, const Eigen::VectorXd& lower_z,
                      const Eigen::VectorXd& upper_z, const std::vector<bool>& held,
                      const LeastSquaresOptions& options, int max_iterations, int iteration_offset,
                      double time_offset_s) {
  const Eigen::Index p = objective.num_parameters();
  LastJacobian last;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(new CalibrationCost(&objective, &held, &last), nullptr, z.data());
  std::vector<int> constant;
  for (Eigen::Index i = 0; i < p; ++i) {
    const int index = static_cast<int>(i);
    if (held[static_cast<std::size_t>(i)]) constant.push_back(index);
    if (std::isfinite(lower_z[i])) problem.SetParameterLowerBound(z.data(), index, lower_z[i]);
    if (std::isfinite(upper_z[i])) problem.SetParameterUpperBound(z.data(), index, upper_z[i]);
  }
  if (!constant.empty()) {
    problem.SetManifold(z.data(), new ceres::SubsetManifold(static_cast<int>(p), constant));
  }

  IterationCheck check(&objective, &options, z.data(), &lower_z, &upper_z, &held, &last,
                       iteration_offset, time_offset_s);
  ceres::Solver::Options solver_options;
  solver_options.minimizer_type = ceres::TRUST_REGION;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = max_iterations;
  solver_options.function_tolerance = options.function_tolerance;
  solver_options.gradient_tolerance = options.gradient_tolerance;
  solver_options.parameter_tolerance = options.parameter_tolerance;
  solver_options.max_num_consecutive_invalid_steps = options.max_consecutive_invalid_steps;
  // With bounds, Ceres follows each trust-region step with a projected line search that asks for
  // full Jacobians at trial points (ceres-solver issue 187 calls it "not terribly effective");
  // here every Jacobian is 2p forward runs, so it is switched off. Bounds still hold: the step is
  // projected onto the box.
  solver_options.max_num_line_search_step_size_iterations = 0;
  // Parallelism lives in the finite differences; Ceres itself stays single threaded so the
  // cache is only ever touched from this thread.
  solver_options.num_threads = 1;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  // The callback compares z with the point of the last Jacobian.
  solver_options.update_state_every_iteration = true;
  solver_options.callbacks.push_back(&check);

  PassResult out;
  ceres::Solve(solver_options, &problem, &out.summary);
  out.iterations = check.iterations;
  out.newly_held = check.newly_held;
  out.at_noise_floor = check.at_noise_floor;
  out.floor = check.floor;
  out.decrease = check.decrease;
  return out;
}

}  // namespace

double noise_floor_cost(const Eigen::VectorXd& r, const Eigen::VectorXd& noise) {
  if (noise.size() != r.size()) return 0.0;
  const double delta = noise.norm();
  return r.norm() * delta + 0.5 * delta * delta;
}

double predicted_decrease(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                          const std::vector<bool>& held) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index j = 0; j < jacobian.cols(); ++j) {
    if (static_cast<std::size_t>(j) >= held.size() || !held[static_cast<std::size_t>(j)]) {
      columns.push_back(j);
    }
  }
  if (columns.empty() || r.size() == 0) return 0.0;
  Eigen::MatrixXd a(jacobian.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t k = 0; k < columns.size(); ++k) {
    a.col(static_cast<Eigen::Index>(k)) = jacobian.col(columns[k]);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::Index rank = qr.rank();
  if (rank == 0) return 0.0;
  const Eigen::VectorXd qtr = qr.householderQ().transpose() * r;
  return 0.5 * qtr.head(rank).squaredNorm();
}

bool LeastSquaresOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* message) {
    if (why) *why = message;
    return false;
  };
  if (max_iterations < 0) return fail("max_iterations must be >= 0");
  if (!(function_tolerance >= 0.0) || !(gradient_tolerance >= 0.0) ||
      !(parameter_tolerance >= 0.0)) {
    return fail("tolerances must be >= 0");
  }
  if (max_consecutive_invalid_steps < 1) return fail("max_consecutive_invalid_steps must be >= 1");
  return true;
}

LeastSquaresSummary solve_least_squares(Objective& objective, const Eigen::VectorXd& x0,
                                        const LeastSquaresOptions& options) {
  const Eigen::Index p = objective.num_parameters();
  Eigen::VectorXd z = x0.cwiseQuotient(objective.scale());
  const Eigen::VectorXd lower_z = objective.lower().cwiseQuotient(objective.scale());
  const Eigen::VectorXd upper_z = objective.upper().cwiseQuotient(objective.scale());

  LeastSquaresSummary out;
  std::vector<bool> held(static_cast<std::size_t>(p), false);
  std::vector<int> releases(static_cast<std::size_t>(p), 0);
  int iterations = 0;
  double elapsed_s = 0.0;
  bool first = true;
  PassResult pass;
  for (out.passes = 0;;) {
    ++out.passes;
    pass = solve_pass(objective, z, lower_z, upper_z, held, options,
                      std::max(0, options.max_iterations - iterations), iterations, elapsed_s);
    iterations += pass.iterations;
    elapsed_s += pass.summary.total_time_in_seconds;
    if (first) out.initial_cost = pass.summary.initial_cost;
    first = false;
    if (!pass.summary.IsSolutionUsable()) break;
    if (!pass.newly_held.empty()) {
      // Hold them exactly on the bound and solve again from here (the cached runs are reused).
      for (Eigen::Index j : pass.newly_held) {
        held[static_cast<std::size_t>(j)] = true;
        z[j] = bound_side(z[j], lower_z[j], upper_z[j]) < 0 ? lower_z[j] : upper_z[j];
      }
      if (std::all_of(held.begin(), held.end(), [](bool h) { return h; })) break;
      if (iterations < options.max_iterations) continue;
      break;
    }
    // Release a held parameter that the cost now pulls off its bound by more than the noise.
    if (std::none_of(held.begin(), held.end(), [](bool h) { return h; })) break;
    if (iterations >= options.max_iterations) break;
    const Eigen::VectorXd x = z.cwiseProduct(objective.scale());
    const FdJacobian full = objective.jacobian(x);
    const auto at = objective.evaluate(x);
    if (!full.ok || !at->ok) break;
    const Eigen::MatrixXd jz = full.jacobian * objective.scale().asDiagonal();
    const Eigen::VectorXd g = jz.transpose() * at->residuals;
    const double floor = noise_floor_cost(at->residuals, options.residual_noise);
    bool released = false;
    for (Eigen::Index j = 0; j < p; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      if (!held[jj] || releases[jj] >= 2) continue;
      const int side = bound_side(z[j], lower_z[j], upper_z[j]);
      const double h = jz.col(j).squaredNorm();
      const bool inward = (side < 0 && g[j] < 0.0) || (side > 0 && g[j] > 0.0);
      if (inward && h > 0.0 && 0.5 * g[j] * g[j] / h > floor) {
        held[jj] = false;
        ++releases[jj];
        released = true;
      }
    }
    if (!released) break;
  }

  out.x = z.cwiseProduct(objective.scale());
  out.final_cost = pass.summary.final_cost;
  out.iterations = iterations;
  out.usable = pass.summary.IsSolutionUsable();
  out.noise_floor = pass.at_noise_floor;
  out.noise_floor_cost = pass.floor;
  out.predicted_decrease = pass.decrease;
  out.converged =
      pass.summary.termination_type == ceres::CONVERGENCE ||
      (pass.summary.termination_type == ceres::USER_SUCCESS &&
       (pass.at_noise_floor || std::all_of(held.begin(), held.end(), [](bool h) { return h; })));
  out.termination =
      out.converged && pass.summary.termination_type == ceres::USER_SUCCESS
          ? std::string("CONVERGENCE")
          : std::string(ceres::TerminationTypeToString(pass.summary.termination_type));
  out.message = pass.at_noise_floor
                    ? fmt::format(
                          "stopped at the noise floor: the best decrease the linearised model "
                          "offers ({:.3g}) is below what the forward solver's convergence can "
                          "resolve ({:.3g})",
                          pass.decrease, pass.floor)
                    : pass.summary.message;
  if (pass.summary.termination_type == ceres::USER_SUCCESS && !pass.at_noise_floor &&
      !out.converged) {
    out.message = "iteration limit reached while holding parameters on their bounds";
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    out.held.push_back(held[static_cast<std::size_t>(j)] ? bound_side(z[j], lower_z[j], upper_z[j])
                                                         : 0);
  }
  return out;
}

}  // namespace vs
