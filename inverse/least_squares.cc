#include "least_squares.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <cmath>

namespace vs {
namespace {

// One residual block over all data sets and one parameter block z = x / scale.
class CalibrationCost final : public ceres::CostFunction {
 public:
  explicit CalibrationCost(Objective* objective) : objective_(objective) {
    set_num_residuals(objective->num_residuals());
    mutable_parameter_block_sizes()->push_back(objective->num_parameters());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::Index p = objective_->num_parameters();
    const Eigen::Index m = objective_->num_residuals();
    const Eigen::VectorXd x =
        Eigen::Map<const Eigen::VectorXd>(parameters[0], p).cwiseProduct(objective_->scale());
    const auto evaluation = objective_->evaluate(x);
    if (!evaluation->ok) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, m) = evaluation->residuals;
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const FdJacobian fd = objective_->jacobian(x);
      if (!fd.ok) return false;
      // d r / d z = d r / d x * scale, row-major as Ceres expects.
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          jacobians[0], m, p) = fd.jacobian * objective_->scale().asDiagonal();
    }
    return true;
  }

 private:
  Objective* objective_;
};

class ProgressCallback final : public ceres::IterationCallback {
 public:
  ProgressCallback(Objective* objective, std::function<void(const std::string&)> sink,
                   int* iterations)
      : objective_(objective), sink_(std::move(sink)), iterations_(iterations) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    *iterations_ = s.iteration;
    if (sink_) {
      sink_(fmt::format("iter {:3d}  cost {:.6e}  |step| {:.3e}  forward runs {:4d}  {:7.2f} s{}",
                        s.iteration, s.cost, s.step_norm, objective_->cache().forward_runs(),
                        s.cumulative_time_in_seconds, s.step_is_successful ? "" : "  (rejected)"));
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  Objective* objective_;
  std::function<void(const std::string&)> sink_;
  int* iterations_;
};

}  // namespace

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

  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(new CalibrationCost(&objective), nullptr, z.data());
  for (Eigen::Index i = 0; i < p; ++i) {
    const int index = static_cast<int>(i);
    if (std::isfinite(objective.lower()[i])) {
      problem.SetParameterLowerBound(z.data(), index, objective.lower()[i] / objective.scale()[i]);
    }
    if (std::isfinite(objective.upper()[i])) {
      problem.SetParameterUpperBound(z.data(), index, objective.upper()[i] / objective.scale()[i]);
    }
  }

  int iterations = 0;
  ProgressCallback progress(&objective, options.progress, &iterations);
  ceres::Solver::Options solver_options;
  solver_options.minimizer_type = ceres::TRUST_REGION;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options.max_iterations;
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
  solver_options.callbacks.push_back(&progress);

  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);

  LeastSquaresSummary out;
  out.x = z.cwiseProduct(objective.scale());
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.iterations = iterations;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.usable = summary.IsSolutionUsable();
  out.termination = ceres::TerminationTypeToString(summary.termination_type);
  out.message = summary.message;
  return out;
}

}  // namespace vs
