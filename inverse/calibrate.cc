#include "calibrate.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "least_squares.h"
#include "objective.h"
#include "report.h"
#include "scene/scene_table.h"

namespace vs {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int scene_index(const CalibrationConfig& config, const DataSpec& d) {
  for (std::size_t s = 0; s < config.scenes.size(); ++s) {
    if (d.scene.empty() || config.scenes[s].name == d.scene) return static_cast<int>(s);
  }
  return 0;
}

// Reads the scenes, attaches the parameters, fills scene-defaulted initial values and scales.
std::vector<SceneBinding> bind_scenes(CalibrationConfig& config) {
  std::vector<SceneBinding> bindings;
  for (std::size_t s = 0; s < config.scenes.size(); ++s) {
    std::vector<double> travels;
    for (const auto& d : config.data) {
      if (d.measurement.kind != MeasurementKind::kLoadTravel &&
          scene_index(config, d) == static_cast<int>(s)) {
        travels.push_back(d.measurement.travel_mm);
      }
    }
    const std::string& path = config.scenes[s].path;
    bindings.emplace_back(read_scene_table(path), path, fs::path(path).parent_path().string(),
                          config.forward, travels);
  }
  std::vector<std::vector<std::string>> reasons;
  for (auto& b : bindings) reasons.push_back(b.attach(config.parameters));
  for (std::size_t i = 0; i < config.parameters.size(); ++i) {
    ParameterSpec& p = config.parameters[i];
    const SceneBinding* home = nullptr;
    for (const auto& b : bindings) {
      if (b.applies(static_cast<int>(i))) {
        home = &b;
        break;
      }
    }
    if (home == nullptr) {
      throw InputError(fmt::format("{}: parameter '{}' is not a number in the scene: {}", p.where,
                                   p.address, reasons.front()[i]));
    }
    if (home->is_integer(p.address)) {
      throw InputError(fmt::format(
          "{}: parameter '{}' is an integer key: integer keys cannot be calibrated (the fit "
          "moves parameters continuously); set it in [forward.set] instead",
          p.where, p.address));
    }
    if (std::isnan(p.initial)) p.initial = home->value_of(p.address);
    if (p.scale == 0.0) p.scale = p.initial != 0.0 ? std::abs(p.initial) : 1.0;
  }
  return bindings;
}

// Data that the scenes cannot produce, and parameter bounds the scenes reject, are
// configuration errors too: found here rather than as failed runs.
void check_against_scenes(const CalibrationConfig& config,
                          const std::vector<SceneBinding>& bindings) {
  for (const auto& d : config.data) {
    const SceneBinding& binding = bindings[scene_index(config, d)];
    const Scene scene = binding.base_scene();
    const Measurement& m = d.measurement;
    const double needed = m.kind == MeasurementKind::kLoadTravel ? m.x.back() : m.travel_mm;
    if (needed > scene.process.punch_travel_mm * (1.0 + 1e-12)) {
      throw InputError(
          fmt::format("{}: data set '{}' needs {} mm of punch travel but {} stops "
                      "at process.punch_travel_mm = {} mm",
                      d.where, m.name, needed, binding.source(), scene.process.punch_travel_mm));
    }
    if (m.kind != MeasurementKind::kLoadTravel && m.x.back() > scene.blank.radius_mm) {
      throw InputError(fmt::format("{}: data set '{}' has r0_mm = {} beyond the blank radius {} mm",
                                   d.where, m.name, m.x.back(), scene.blank.radius_mm));
    }
  }
  std::vector<double> initial;
  for (const auto& p : config.parameters) initial.push_back(p.initial);
  for (std::size_t i = 0; i < config.parameters.size(); ++i) {
    const ParameterSpec& p = config.parameters[i];
    for (double value : {p.initial, p.lower, p.upper}) {
      if (!std::isfinite(value) || (p.fixed && value != p.initial)) continue;
      std::vector<double> values = initial;
      values[i] = value;
      for (const auto& b : bindings) {
        try {
          b.bind(values);
        } catch (const InputError& e) {
          throw InputError(
              fmt::format("{}: parameter {} = {} (initial or bound) is rejected by "
                          "the scene: {}",
                          p.where, p.address, value, e.what()));
        }
      }
    }
  }
}

std::vector<DataSet> make_data_sets(const CalibrationConfig& config) {
  std::vector<DataSet> sets;
  for (const auto& d : config.data) {
    DataSet set;
    set.measurement = d.measurement;
    set.scene = scene_index(config, d);
    for (std::size_t i = 0; i < d.measurement.x.size(); ++i) {
      const double w = !d.measurement.point_sigma.empty() ? 1.0 / d.measurement.point_sigma[i]
                       : d.weight > 0.0                   ? d.weight
                                                          : 1.0 / data_set_sigma(d).sigma;
      set.weights.push_back(w);
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

std::vector<DataSetFit> make_fits(const ResidualPipeline& pipeline, const Evaluation& e) {
  std::vector<DataSetFit> fits;
  for (const auto& d : pipeline.data_sets()) {
    const Measurement& m = d.measurement;
    DataSetFit fit;
    fit.name = m.name;
    fit.kind = m.kind;
    fit.travel_mm = m.travel_mm;
    fit.x = m.x;
    fit.measured = m.y;
    fit.weight = d.weights;
    const SimulatedCurve curve = simulate_curve(m, e.runs.at(d.scene));
    fit.ok = curve.ok;
    fit.simulated = curve.ok ? curve.y : std::vector<double>(m.x.size(), kNaN);
    double sum_sq = 0.0, cost = 0.0;
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      const double diff = fit.simulated[i] - m.y[i];
      sum_sq += diff * diff;
      cost += 0.5 * d.weights[i] * d.weights[i] * diff * diff;
    }
    fit.rms_difference = std::sqrt(sum_sq / static_cast<double>(m.x.size()));
    fit.cost = cost;
    fits.push_back(std::move(fit));
  }
  return fits;
}

// The reason an evaluation failed, one line: the failed scene runs' own messages (the scene
// file and why it stopped) when a run failed, else the residual pipeline's message.
std::string first_failure(const Evaluation& e, const std::vector<std::string>& scenes) {
  std::string text;
  for (std::size_t s = 0; s < e.runs.size(); ++s) {
    if (e.runs[s].completed()) continue;
    text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", s < scenes.size() ? scenes[s] : "",
                        e.runs[s].message);
  }
  if (text.empty()) text = e.message;
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

// Counters, timing and the report folder, on every way out of calibrate().
void finish(const ForwardCache& cache, const CalibrationConfig& config,
            const CalibrationOptions& options, std::chrono::steady_clock::time_point start,
            CalibrationResult* result) {
  result->forward_runs = cache.forward_runs();
  result->failed_evaluations = cache.failed_evaluations();
  result->evaluations = cache.log();
  result->wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.write_report) {
    result->output_directory =
        options.output_directory.empty() ? config.output_directory : options.output_directory;
    result->report_notes = write_calibration_report(*result, config, result->output_directory);
  }
}

}  // namespace

std::string to_string(CalibrationTermination termination) {
  switch (termination) {
    case CalibrationTermination::kConverged:
      return "converged";
    case CalibrationTermination::kNotConverged:
      return "not_converged";
    case CalibrationTermination::kFailed:
      return "failed";
  }
  return "?";
}

Eigen::VectorXd CalibrationResult::free_values() const {
  std::vector<double> values;
  for (const auto& p : parameters) {
    if (!p.spec.fixed) values.push_back(p.value);
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

std::string CalibrationResult::brief_report() const {
  const std::string costs = std::isfinite(initial_cost) && std::isfinite(final_cost)
                                ? fmt::format("cost {:.6g} -> {:.6g}", initial_cost, final_cost)
                            : std::isfinite(final_cost)
                                ? fmt::format("cost {:.6g}", final_cost)
                                : std::string("no cost (no successful forward run)");
  std::string text = fmt::format(
      "calibration {}: {}, {} iterations, {} forward runs ({} failed evaluations), {:.2f} s\n",
      to_string(termination), costs, iterations, forward_runs, failed_evaluations, wall_time_s);
  if (!message.empty()) text += fmt::format("  {}\n", message);
  std::size_t k = 0;
  for (const auto& p : parameters) {
    if (p.spec.fixed) {
      text += fmt::format("  {:32s} {:>14.6g} {} (fixed)\n", p.spec.address, p.value, p.unit);
      continue;
    }
    if (uncertainty_available) {
      const auto& u = uncertainty.parameters.at(k);
      text += fmt::format("  {:32s} {:>14.6g} +- {:<10.3g} 95% [{:.6g}, {:.6g}] {}{}\n",
                          p.spec.address, p.value, u.std_error, u.interval_lower, u.interval_upper,
                          p.unit, u.determined ? "" : "  (poorly determined)");
    } else {
      text += fmt::format("  {:32s} {:>14.6g} {}\n", p.spec.address, p.value, p.unit);
    }
    ++k;
  }
  for (const auto& w : data_weighting) {
    if (w.relative_default) text += fmt::format("  data {}: {}\n", w.name, w.text);
  }
  if (uncertainty_available) {
    for (const auto& s : uncertainty.statements) text += fmt::format("  note: {}\n", s);
  } else if (!uncertainty_message.empty()) {
    text += fmt::format("  note: no uncertainty: {}\n", uncertainty_message);
  }
  if (!output_directory.empty()) text += fmt::format("  report: {}\n", output_directory);
  return text;
}

CalibrationResult calibrate(const CalibrationConfig& input, const CalibrationOptions& options,
                            ForwardModel model) {
  const auto start = std::chrono::steady_clock::now();
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };

  // Everything that can be wrong with the input, before the first forward run.
  CalibrationConfig config = input;
  if (config.scenes.empty()) throw InputError("calibration: no scene given");
  std::vector<SceneBinding> bindings = bind_scenes(config);
  validate_calibration_config(config);
  check_against_scenes(config, bindings);

  CalibrationResult result;
  for (const auto& b : bindings) result.scene_sources.push_back(b.source());
  for (const auto& d : config.data) {
    result.data_weighting.push_back(
        {d.measurement.name, data_set_sigma(d).text,
         d.sigma == 0.0 && d.weight == 0.0 && d.measurement.point_sigma.empty()});
  }
  ForwardCache cache(std::move(model), std::move(bindings), config.parameters,
                     ResidualPipeline(make_data_sets(config)), config.optimizer.threads);
  Objective objective(&cache, config.optimizer.fd);
  say(fmt::format("calibrate: {} free parameters, {} residuals, {} scene(s), {} thread(s)",
                  objective.num_parameters(), objective.num_residuals(),
                  result.scene_sources.size(), config.optimizer.threads));

  const Eigen::VectorXd x0 = objective.initial();
  const auto first = objective.evaluate(x0);
  result.initial_cost = first->cost;
  if (!first->ok) {
    // Nothing to fit from: stop now, with the forward run's own reason.
    result.termination = CalibrationTermination::kFailed;
    result.message = "the forward run at the initial parameters fails: " +
                     first_failure(*first, result.scene_sources);
    result.uncertainty_message = "no fit";
    const auto values = cache.all_values(x0);
    for (std::size_t i = 0; i < cache.parameters().size(); ++i) {
      const ParameterSpec& spec = cache.parameters()[i];
      result.parameters.push_back({spec, unit_of_address(spec.address), values[i]});
    }
    result.final_cost = first->cost;
    finish(cache, config, options, start, &result);
    return result;
  }
  Eigen::VectorXd x_start = x0;
  if (config.optimizer.method == OptimizerMethod::kGlobalThenLocal) {
    say(fmt::format("global search: {} with seed {}, at most {} evaluations",
                    config.optimizer.global.algorithm, config.optimizer.global.seed,
                    config.optimizer.global.max_evaluations));
    result.global_search_used = true;
    result.global = global_search(objective, x0, config.optimizer.global);
    if (std::isfinite(result.global.cost)) x_start = result.global.x;
    say(fmt::format("global search: best cost {:.6e} after {} evaluations ({})", result.global.cost,
                    result.global.evaluations, result.global.result));
  }

  LeastSquaresOptions ls = config.optimizer.least_squares;
  ls.progress = options.progress;
  const LeastSquaresSummary summary = solve_least_squares(objective, x_start, ls);
  result.iterations = summary.iterations;
  result.ceres_termination = summary.termination;
  result.message = summary.message;
  result.termination = summary.converged ? CalibrationTermination::kConverged
                       : summary.usable  ? CalibrationTermination::kNotConverged
                                         : CalibrationTermination::kFailed;

  const Eigen::VectorXd x = summary.usable ? summary.x : x_start;
  const auto& specs = cache.parameters();
  const auto values = cache.all_values(x);
  for (std::size_t i = 0; i < specs.size(); ++i) {
    result.parameters.push_back({specs[i], unit_of_address(specs[i].address), values[i]});
  }

  const auto final_point = objective.evaluate(x);
  result.final_cost = final_point->cost;
  if (final_point->ok) {
    result.fits = make_fits(cache.pipeline(), *final_point);
    const FdJacobian j = objective.jacobian(x);
    if (j.ok) {
      result.uncertainty = estimate_uncertainty(j.jacobian, final_point->cost, x, objective.scale(),
                                                objective.lower(), objective.upper(),
                                                objective.names(), config.uncertainty);
      result.uncertainty_available = true;
    } else {
      result.uncertainty_message = "Jacobian at the optimum failed: " + j.message;
    }
  } else {
    result.uncertainty_message =
        "the forward model fails at the final point: " + final_point->message;
  }

  if (result.termination == CalibrationTermination::kFailed) {
    // Ceres only says "Residual and Jacobian evaluation failed": add the forward run's reason.
    const auto& log = cache.log();
    for (auto e = log.rbegin(); e != log.rend(); ++e) {
      if ((*e)->ok) continue;
      result.message += " Last failed forward run: " + first_failure(**e, result.scene_sources);
      break;
    }
  }
  finish(cache, config, options, start, &result);
  return result;
}

}  // namespace vs
