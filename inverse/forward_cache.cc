#include "forward_cache.h"

#include <fmt/format.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>

namespace vs {
namespace {

std::vector<double> key_of(const Eigen::VectorXd& x) { return {x.data(), x.data() + x.size()}; }

struct Job {
  std::size_t point = 0;
  std::size_t scene = 0;
};

struct JobResult {
  RunResult run;
  double wall_time_s = 0.0;
};

}  // namespace

ForwardCache::ForwardCache(ForwardModel model, std::vector<SceneBinding> scenes,
                           std::vector<ParameterSpec> parameters, ResidualPipeline pipeline,
                           int threads)
    : model_(std::move(model)),
      scenes_(std::move(scenes)),
      parameters_(std::move(parameters)),
      free_(free_parameter_indices(parameters_)),
      pipeline_(std::move(pipeline)),
      threads_(std::max(1, threads)) {}

std::vector<double> ForwardCache::all_values(const Eigen::VectorXd& x) const {
  std::vector<double> values;
  for (const auto& p : parameters_) values.push_back(p.initial);
  for (std::size_t i = 0; i < free_.size(); ++i) values[free_[i]] = x[static_cast<Eigen::Index>(i)];
  return values;
}

std::shared_ptr<const Evaluation> ForwardCache::evaluate(const Eigen::VectorXd& x) {
  return evaluate_batch({x}).front();
}

std::vector<std::shared_ptr<const Evaluation>> ForwardCache::evaluate_batch(
    const std::vector<Eigen::VectorXd>& points) {
  // New points, in batch order (duplicates within the batch are run once).
  std::vector<std::size_t> fresh;
  std::map<std::vector<double>, std::size_t> fresh_slot;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto key = key_of(points[i]);
    if (memo_.count(key) || fresh_slot.count(key)) continue;
    fresh_slot[key] = fresh.size();
    fresh.push_back(i);
  }

  std::vector<Job> jobs;
  for (std::size_t f = 0; f < fresh.size(); ++f) {
    for (std::size_t s = 0; s < scenes_.size(); ++s) jobs.push_back({f, s});
  }
  std::vector<JobResult> results(jobs.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      const auto start = std::chrono::steady_clock::now();
      JobResult& out = results[j];
      try {
        const Scene scene = scenes_[jobs[j].scene].bind(all_values(points[fresh[jobs[j].point]]));
        out.run = model_(scene);
      } catch (const std::exception& e) {
        // A value the scene rejects or a model that throws is a failed run, not a crash.
        out.run = RunResult{};
        out.run.termination = Termination::kFailed;
        out.run.message = e.what();
      }
      out.wall_time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  };
  const std::size_t workers = std::min<std::size_t>(threads_, jobs.size());
  if (workers <= 1) {
    worker();
  } else {
    // Forward runs side by side: each runs its own element loops on one thread. With OpenMP's
    // default team in every run, two runs on two cores put four threads on two cores, and a team
    // whose partner is descheduled spins at every barrier (measured: the 3D cup of
    // data/calibration, 48 elements, to 8 mm with two CalculiX runs beside it: 10.1 s with two
    // threads, 2.4 s with one). The per-thread setting touches only the pool's threads.
    const auto single = [&] {
      omp_set_num_threads(1);
      worker();
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(single);
    for (auto& thread : pool) thread.join();
  }
  forward_runs_ += static_cast<int>(jobs.size());

  // Residuals and log entries on this thread, in batch order.
  for (std::size_t f = 0; f < fresh.size(); ++f) {
    auto evaluation = std::make_shared<Evaluation>();
    evaluation->index = static_cast<int>(log_.size());
    evaluation->x = points[fresh[f]];
    for (std::size_t s = 0; s < scenes_.size(); ++s) {
      JobResult& job = results[f * scenes_.size() + s];
      evaluation->wall_time_s += job.wall_time_s;
      if (!job.run.completed() && !job.run.message.empty()) {
        evaluation->message += fmt::format("{}: {}; ", scenes_[s].source(), job.run.message);
      }
      evaluation->runs.push_back(std::move(job.run));
    }
    const Residuals r = pipeline_.residuals(evaluation->runs);
    evaluation->ok = r.ok;
    if (r.ok) {
      evaluation->residuals = r.values;
      evaluation->cost = 0.5 * r.values.squaredNorm();
    } else {
      evaluation->cost = std::numeric_limits<double>::quiet_NaN();
      evaluation->message =
          r.message + (evaluation->message.empty() ? "" : "; ") + evaluation->message;
      ++failed_evaluations_;
    }
    while (!evaluation->message.empty() &&
           (evaluation->message.back() == ' ' || evaluation->message.back() == ';')) {
      evaluation->message.pop_back();
    }
    memo_[key_of(evaluation->x)] = evaluation;
    log_.push_back(evaluation);
    if (on_evaluation_) on_evaluation_(*evaluation);
  }

  std::vector<std::shared_ptr<const Evaluation>> out;
  for (const auto& point : points) out.push_back(memo_.at(key_of(point)));
  return out;
}

}  // namespace vs
