// Runs the forward model once per parameter vector and remembers the result. A point is one
// vector of free parameters; evaluating it means binding every scene, running it, and mapping
// the runs to residuals. Batches (finite-difference perturbations) run in std::thread workers;
// results are collected by index, so the evaluation log and every number derived from it are
// the same whatever the thread count or scheduling.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "forward_model.h"
#include "parameter_spec.h"
#include "residual_pipeline.h"
#include "scene_binding.h"

namespace vs {

// One evaluated point: what the evaluation log (evaluations.csv) records.
struct Evaluation {
  int index = 0;        // position in the log, 0-based
  Eigen::VectorXd x;    // free parameters, in their own units
  bool ok = false;      // residuals available
  std::string message;  // why not, or notes (e.g. a run that stopped after the data)
  Eigen::VectorXd residuals;
  double cost = 0.0;            // 0.5 |r|^2 (the Ceres convention); NaN when !ok
  double wall_time_s = 0.0;     // sum over this point's forward runs
  std::vector<RunResult> runs;  // one per scene
};

class ForwardCache {
 public:
  // `parameters` are all parameters (fixed ones supply their initial value); the cache owns
  // copies of everything it needs.
  ForwardCache(ForwardModel model, std::vector<SceneBinding> scenes,
               std::vector<ParameterSpec> parameters, ResidualPipeline pipeline, int threads);

  // Not reentrant: call from one thread (the optimiser's). Parallelism is inside.
  std::shared_ptr<const Evaluation> evaluate(const Eigen::VectorXd& x);
  std::vector<std::shared_ptr<const Evaluation>> evaluate_batch(
      const std::vector<Eigen::VectorXd>& points);

  // Called on the optimiser's thread for every new evaluation, in log order (progress lines).
  void set_on_evaluation(std::function<void(const Evaluation&)> on_evaluation) {
    on_evaluation_ = std::move(on_evaluation);
  }

  const std::vector<std::shared_ptr<const Evaluation>>& log() const { return log_; }
  int forward_runs() const { return forward_runs_; }  // scene runs started
  int failed_evaluations() const { return failed_evaluations_; }
  int num_free() const { return static_cast<int>(free_.size()); }
  const std::vector<ParameterSpec>& parameters() const { return parameters_; }
  const std::vector<int>& free_indices() const { return free_; }
  const ResidualPipeline& pipeline() const { return pipeline_; }
  const std::vector<SceneBinding>& scenes() const { return scenes_; }

  // All parameter values (fixed ones at their initial value) for free values x.
  std::vector<double> all_values(const Eigen::VectorXd& x) const;

 private:
  ForwardModel model_;
  std::vector<SceneBinding> scenes_;
  std::vector<ParameterSpec> parameters_;
  std::vector<int> free_;
  ResidualPipeline pipeline_;
  int threads_ = 1;
  std::map<std::vector<double>, std::shared_ptr<const Evaluation>> memo_;
  std::vector<std::shared_ptr<const Evaluation>> log_;
  int forward_runs_ = 0;
  int failed_evaluations_ = 0;
  std::function<void(const Evaluation&)> on_evaluation_;
};

}  // namespace vs
