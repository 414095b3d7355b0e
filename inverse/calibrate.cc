#include "calibrate.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>

#include "core/error.h"
#include "least_squares.h"
#include "objective.h"
#include "report.h"
#include "scene/scene_echo.h"
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
      if (is_strain_profile(d.measurement.kind) && scene_index(config, d) == static_cast<int>(s)) {
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

// A cup height profile needs a 3D scene with a free blank edge, and parameters that leave the
// blank and the rolling direction alone (the rim is identified with the scene as configured).
void check_cup_profile_data(const CalibrationConfig& config, const DataSpec& d,
                            const std::string& source, const Scene& scene) {
  const std::string& name = d.measurement.name;
  if (scene.geometry != Geometry::kShell3d || scene.blank.edge != EdgeCondition::kFree) {
    throw InputError(fmt::format(
        "{}: data set '{}' (cup_height_profile) needs a 3D cup: {} must have geometry = "
        "\"shell3d\" and blank.edge = \"free\"",
        d.where, name, source));
  }
  for (const ParameterSpec& p : config.parameters) {
    if (p.fixed) continue;
    if (p.address.rfind("blank.", 0) == 0 ||
        p.address == "material.anisotropy.rolling_direction_deg") {
      throw InputError(fmt::format(
          "{}: parameter '{}' moves the blank or the rolling direction, with which data set '{}' "
          "(cup_height_profile) identifies the rim: it cannot be calibrated from a cup profile",
          p.where, p.address, name));
    }
  }
}

// Data that the scenes cannot produce, and parameter bounds the scenes reject, are
// configuration errors too: found here rather than as failed runs.
void check_against_scenes(const CalibrationConfig& config,
                          const std::vector<SceneBinding>& bindings) {
  for (const auto& d : config.data) {
    const SceneBinding& binding = bindings[scene_index(config, d)];
    const Scene scene = binding.base_scene();
    const Measurement& m = d.measurement;
    if (m.kind == MeasurementKind::kCupHeightProfile) {
      check_cup_profile_data(config, d, binding.source(), scene);
      continue;
    }
    const double needed = m.kind == MeasurementKind::kLoadTravel ? m.x.back() : m.travel_mm;
    if (needed > scene.process.punch_travel_mm * (1.0 + 1e-12)) {
      throw InputError(
          fmt::format("{}: data set '{}' needs {} mm of punch travel but {} stops "
                      "at process.punch_travel_mm = {} mm",
                      d.where, m.name, needed, binding.source(), scene.process.punch_travel_mm));
    }
    if (is_strain_profile(m.kind) && m.x.back() > scene.blank.radius_mm) {
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

std::vector<DataSet> make_data_sets(const CalibrationConfig& config,
                                    const std::vector<SceneBinding>& bindings) {
  std::vector<DataSet> sets;
  for (const auto& d : config.data) {
    DataSet set;
    set.measurement = d.measurement;
    set.scene = scene_index(config, d);
    if (d.measurement.kind == MeasurementKind::kCupHeightProfile) {
      set.scene_spec = std::make_shared<const Scene>(
          bindings.at(static_cast<std::size_t>(set.scene)).base_scene());
    }
    set.shape_only = d.shape_only;
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

// Whether data set k states its noise (a sigma, a weight or a sigma column); the relative
// default is a fraction of the curve's range, not a noise scale.
bool sigma_stated(const DataSpec& d) {
  return d.sigma > 0.0 || d.weight > 0.0 || !d.measurement.point_sigma.empty();
}

// The trust caveats of an evaluation's forward runs (RunResult::warnings), each once, with
// "<scene>: " in front when there are several scenes.
std::vector<std::string> forward_warnings(const Evaluation& e,
                                          const std::vector<std::string>& scene_sources) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < e.runs.size(); ++k) {
    for (const std::string& w : e.runs[k].warnings) {
      const std::string text = e.runs.size() > 1 && k < scene_sources.size()
                                   ? fmt::format("{}: {}", scene_sources[k], w)
                                   : w;
      if (std::find(out.begin(), out.end(), text) == out.end()) out.push_back(text);
    }
  }
  return out;
}

// `resolution`: per data set, the forward resolution of its simulated values in data units
// (forward_resolution()); `config` data sets in the pipeline's order.
std::vector<DataSetFit> make_fits(const ResidualPipeline& pipeline, const Evaluation& e,
                                  const CalibrationConfig& config,
                                  const std::vector<double>& resolution) {
  const LackOfFitOptions& lack_of_fit_options = config.uncertainty.lack_of_fit;
  std::vector<DataSetFit> fits;
  for (std::size_t k = 0; k < pipeline.data_sets().size(); ++k) {
    const DataSet& d = pipeline.data_sets()[k];
    const Measurement& m = d.measurement;
    DataSetFit fit;
    fit.name = m.name;
    fit.kind = m.kind;
    fit.travel_mm = m.travel_mm;
    fit.x = m.x;
    fit.measured = m.y;
    fit.weight = d.weights;
    const SimulatedCurve curve = data_set_curve(d, e.runs.at(d.scene));
    fit.ok = curve.ok;
    fit.simulated = curve.ok ? curve.y : std::vector<double>(m.x.size(), kNaN);
    fit.shape_only = d.shape_only;
    fit.correction = d.correction;
    if (curve.ok && d.shape_only) {
      const SimulatedCurve raw = simulate_curve(m, e.runs.at(d.scene), d.scene_spec.get());
      fit.shape_offset_mm = raw.ok && !raw.y.empty() ? curve.y.front() - raw.y.front() : kNaN;
    }
    double sum_sq = 0.0, cost = 0.0;
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      const double diff = fit.simulated[i] - m.y[i];
      sum_sq += diff * diff;
      cost += 0.5 * d.weights[i] * d.weights[i] * diff * diff;
    }
    fit.rms_difference = std::sqrt(sum_sq / static_cast<double>(m.x.size()));
    fit.cost = cost;
    if (sigma_stated(config.data.at(k))) {
      std::vector<double> normalised;
      for (std::size_t i = 0; i < m.x.size(); ++i) {
        normalised.push_back(d.weights[i] * (fit.simulated[i] - m.y[i]));
      }
      fit.lack_of_fit = lack_of_fit(normalised, m.name, lack_of_fit_options);
    } else {
      std::vector<double> difference;
      for (std::size_t i = 0; i < m.x.size(); ++i) difference.push_back(fit.simulated[i] - m.y[i]);
      fit.lack_of_fit =
          lack_of_fit_unstated(difference, std::vector<double>(m.x.size(), resolution.at(k)),
                               ordinate_unit(m.kind), m.name, lack_of_fit_options);
    }
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

// Where the report is written: the option's folder, else the config's.
std::string report_directory(const CalibrationConfig& config, const CalibrationOptions& options) {
  return options.output_directory.empty() ? config.output_directory : options.output_directory;
}

// identified_<scene>.toml of each scene (one binding per config scene, in order): a header naming
// the values that apply to it, then the scene with `values` written in, as the fit ran it. Its
// output.directory is run_identified_<scene> beside the report's final folder: the fit does not
// use it, and running the scene must not replace the base scene's run folder. A scene that cannot
// be built gets "" and a report note.
void identify_scenes(const ForwardCache& cache, const CalibrationConfig& config,
                     const CalibrationOptions& options, const std::vector<double>& values,
                     CalibrationResult* result) {
  const std::vector<ParameterSpec>& specs = cache.parameters();
  const std::string report_dir = options.report_destination.empty()
                                     ? report_directory(config, options)
                                     : options.report_destination;
  for (std::size_t k = 0; k < cache.scenes().size(); ++k) {
    const SceneBinding& b = cache.scenes()[k];
    const std::string& name = config.scenes[k].name;
    try {
      std::string text = fmt::format(
          "# Scene '{}' as the fit of {} ran it, with the identified values\n"
          "# written in (calibration.json has their intervals and the fit's verdicts):\n",
          name, config.path.empty() ? "a calibration" : config.path);
      for (std::size_t i = 0; i < specs.size(); ++i) {
        if (!b.applies(static_cast<int>(i))) continue;  // not a key of this scene
        text += fmt::format("#   {} = {}{}\n", specs[i].address, values[i],
                            specs[i].fixed ? " (fixed)" : "");
      }
      Scene identified = b.bind(values);
      if (!report_dir.empty()) {
        identified.output.directory = (fs::path(report_dir) / ("run_identified_" + name)).string();
      }
      result->identified_scenes.push_back(text + scene_toml(identified));
    } catch (const std::exception& e) {
      result->identified_scenes.emplace_back();
      result->report_notes.push_back(
          fmt::format("no identified scene for {}: {}", b.source(), e.what()));
    }
  }
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
    result->output_directory = report_directory(config, options);
    result->report_notes = write_calibration_report(*result, config, result->output_directory);
  }
}

// Per data set, what the forward solver's convergence leaves unresolved in its simulated
// values, in data units (least_squares.h): factor x tolerance x the data set's largest
// |measured value|.
std::vector<double> forward_resolution(const CalibrationConfig& config,
                                       const std::vector<SceneBinding>& bindings,
                                       const ResidualPipeline& pipeline, double factor) {
  std::vector<double> resolution;
  for (const DataSet& d : pipeline.data_sets()) {
    const double tolerance =
        config.forward.tolerance > 0.0
            ? config.forward.tolerance
            : bindings.at(static_cast<std::size_t>(d.scene)).base_scene().numerics.tolerance;
    double largest = 0.0;
    for (double y : d.measurement.y) largest = std::max(largest, std::abs(y));
    resolution.push_back(factor * tolerance * largest);
  }
  return resolution;
}

// Per residual, the forward resolution weighted like the residual (the noise-floor stop);
// empty when noise_floor_factor is 0 (no stop).
Eigen::VectorXd residual_noise(const CalibrationConfig& config,
                               const std::vector<SceneBinding>& bindings,
                               const ResidualPipeline& pipeline) {
  const double factor = config.optimizer.noise_floor_factor;
  if (!(factor > 0.0)) return {};
  const std::vector<double> resolution = forward_resolution(config, bindings, pipeline, factor);
  Eigen::VectorXd noise(pipeline.num_residuals());
  for (std::size_t k = 0; k < pipeline.data_sets().size(); ++k) {
    const DataSet& d = pipeline.data_sets()[k];
    const int offset = pipeline.offset(static_cast<int>(k));
    for (std::size_t i = 0; i < d.weights.size(); ++i) {
      noise[offset + static_cast<Eigen::Index>(i)] = resolution[k] * d.weights[i];
    }
  }
  return noise;
}

std::vector<BoundEffect> bound_effects(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r,
                                       const Eigen::VectorXd& x, const Objective& objective,
                                       double floor) {
  std::vector<BoundEffect> effects;
  const Eigen::VectorXd g = jacobian.transpose() * r;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double scale = objective.scale()[j];
    const double lower = objective.lower()[j], upper = objective.upper()[j];
    const int side = std::isfinite(lower) && std::abs(x[j] - lower) <= 1e-6 * scale   ? -1
                     : std::isfinite(upper) && std::abs(x[j] - upper) <= 1e-6 * scale ? 1
                                                                                      : 0;
    if (side == 0) continue;
    BoundEffect e;
    e.name = objective.names()[static_cast<std::size_t>(j)];
    e.side = side;
    e.bound = side < 0 ? lower : upper;
    e.gradient = g[j];
    const double h = jacobian.col(j).squaredNorm();
    const bool outward = side < 0 ? g[j] > 0.0 : g[j] < 0.0;
    e.unconstrained = h > 0.0 ? x[j] - g[j] / h : x[j];
    e.cost_decrease = outward && h > 0.0 ? 0.5 * g[j] * g[j] / h : 0.0;
    e.active = outward && e.cost_decrease > floor;
    const char* which = side < 0 ? "lower" : "upper";
    e.text =
        e.active
            ? fmt::format(
                  "{} is AT its {} bound {:.6g}, which holds the fit back: the cost gradient "
                  "there is {:.3g} per unit (pushing outward); without the bound the linearised "
                  "fit would go to {:.4g} and lower the cost by {:.3g}",
                  e.name, which, e.bound, e.gradient, e.unconstrained, e.cost_decrease)
            : fmt::format(
                  "{} is AT its {} bound {:.6g}, where the data put it: the cost gradient there "
                  "({:.3g} per unit) does not push beyond it by more than the forward noise",
                  e.name, which, e.bound, e.gradient);
    effects.push_back(e);
  }
  return effects;
}

// The scenes of a discrepancy source: each scene at the reference's parameters (the source's
// `set`: a parameter's address gives its value, any other address is a scene edit). Throws
// InputError.
std::vector<Scene> discrepancy_scenes(const CalibrationConfig& config,
                                      const DiscrepancySpec& source) {
  CalibrationConfig c = config;
  auto is_parameter = [&c](const std::string& address) {
    return std::any_of(c.parameters.begin(), c.parameters.end(),
                       [&address](const ParameterSpec& p) { return p.address == address; });
  };
  for (const auto& edit : source.set) {
    if (!is_parameter(edit.first)) c.forward.overrides.push_back(edit);
  }
  const std::vector<SceneBinding> bindings = bind_scenes(c);
  std::vector<double> values;
  for (const ParameterSpec& p : c.parameters) {
    double value = p.initial;
    for (const auto& [address, text] : source.set) {
      if (address == p.address) value = std::strtod(text.c_str(), nullptr);  // validated
    }
    values.push_back(value);
  }
  std::vector<Scene> scenes;
  for (const SceneBinding& b : bindings) scenes.push_back(b.bind(values));
  return scenes;
}

// A forward run that reports an exception as a failed run (forward_model.h).
RunResult run_guarded(const ForwardModel& model, const Scene& scene) {
  try {
    return model(scene);
  } catch (const std::exception& e) {
    RunResult run;
    run.termination = Termination::kFailed;
    run.message = e.what();
    return run;
  }
}

// The model-form alternatives to refit: the config's, and with two or more discrepancy sources
// each source alone.
std::vector<ModelFormSpec> model_form_alternatives(const CalibrationConfig& config) {
  std::vector<ModelFormSpec> forms = config.model_forms;
  if (config.discrepancy_alternatives && config.discrepancies.size() >= 2) {
    for (const DiscrepancySpec& source : config.discrepancies) {
      ModelFormSpec form;
      form.name = fmt::format("discrepancy '{}' alone", source.name);
      form.where = source.where;
      form.discrepancy = std::vector<std::string>{source.name};
      forms.push_back(form);
    }
  }
  return forms;
}

// The configuration of one model-form refit: the alternative's scene edits added to
// [forward.set], its data and discrepancy sources, started from the identified values, plain
// Levenberg-Marquardt.
CalibrationConfig model_form_config(const CalibrationConfig& config, const ModelFormSpec& form,
                                    const std::vector<ParameterResult>& identified) {
  CalibrationConfig c = config;
  c.model_forms.clear();
  c.discrepancy_alternatives = false;
  if (form.discrepancy) {
    std::erase_if(c.discrepancies, [&form](const DiscrepancySpec& d) {
      return std::find(form.discrepancy->begin(), form.discrepancy->end(), d.name) ==
             form.discrepancy->end();
    });
  }
  c.optimizer.method = OptimizerMethod::kLevenbergMarquardt;
  for (const auto& edit : form.overrides) c.forward.overrides.push_back(edit);
  std::erase_if(c.data, [&form](const DataSpec& d) { return form.drops(d.measurement.name); });
  for (DiscrepancySpec& source : c.discrepancies) {
    std::erase_if(source.references, [&form](const auto& r) { return form.drops(r.first); });
  }
  for (std::size_t i = 0; i < c.parameters.size() && i < identified.size(); ++i) {
    c.parameters[i].initial = identified[i].value;
  }
  return c;
}

std::string edits_text(const ModelFormSpec& form) {
  std::string text;
  for (const auto& [address, value] : form.overrides) {
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", address, value);
  }
  if (!form.drop_data.empty()) {
    text +=
        fmt::format("{}without data {}", text.empty() ? "" : ", ", fmt::join(form.drop_data, ", "));
  }
  if (form.discrepancy) {
    text += fmt::format(
        "{}{}", text.empty() ? "" : ", ",
        form.discrepancy->empty()
            ? std::string("without the discrepancy correction")
            : fmt::format("corrected by '{}' only", fmt::join(*form.discrepancy, "', '")));
  }
  return text;
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
      text += fmt::format(
          "  {:32s} {:>14.6g} +- {:<10.3g} 95% [{:.6g}, {:.6g}] {}{}{}\n", p.spec.address, p.value,
          u.std_error, u.interval_lower, u.interval_upper, p.unit,
          u.forward_resolution > 0.1 * u.std_error
              ? fmt::format(" (incl. +- {:.3g} forward resolution)", u.forward_resolution)
              : std::string(),
          u.determined ? "" : "  (poorly determined)");
    } else {
      text += fmt::format("  {:32s} {:>14.6g} {}\n", p.spec.address, p.value, p.unit);
    }
    ++k;
  }
  if (!discrepancies.empty()) {
    text += fmt::format(
        "  discrepancy correction in the simulated curves: the mean of {} reference(s) ({} "
        "forward runs at their parameters):\n",
        discrepancies.size(), discrepancy_forward_runs);
    for (const auto& source : discrepancies) {
      std::string sizes;
      for (const auto& c : source.curves) {
        const std::string unit = c.unit == "1" ? "" : " " + c.unit;
        sizes += fmt::format("{}{} rms {:.3g}{} (max {:.3g}{})", sizes.empty() ? "" : ", ", c.data,
                             c.rms, unit, c.max_abs, unit);
      }
      text += fmt::format("    '{}' ({}): {}\n", source.name, source.edits,
                          source.ok ? sizes : source.message);
    }
  }
  if (!model_form_ranges.empty()) {
    text += fmt::format(
        "  model-form range over the main fit and {} alternative(s) ({} forward "
        "runs):\n",
        model_form.size(), model_form_forward_runs);
    for (const auto& range : model_form_ranges) {
      text += fmt::format("  {:32s} [{:.6g}, {:.6g}]{}\n", range.name, range.lower, range.upper,
                          range.exceeds_interval ? "  (wider than the statistical interval)" : "");
    }
    for (const auto& f : model_form) {
      std::string values;
      for (double v : f.values) values += fmt::format("{}{:.6g}", values.empty() ? "" : ", ", v);
      text += fmt::format("    {} ({}): {}\n", f.name, f.edits,
                          f.values.empty() ? f.message
                                           : fmt::format("{} ({} forward runs, {})", values,
                                                         f.forward_runs, f.termination));
      for (const auto& w : f.forward_warnings)
        text += fmt::format("      its forward model warns: {}\n", w);
    }
  }
  for (const auto& w : forward_warnings) {
    text += fmt::format("  warning: at the identified parameters the forward model warns: {}\n", w);
  }
  for (const auto& b : bound_effects) text += fmt::format("  {}\n", b.text);
  for (const auto& w : data_weighting) {
    if (w.relative_default) text += fmt::format("  data {}: {}\n", w.name, w.text);
  }
  for (const auto& f : fits) {
    if (f.lack_of_fit.verdict == LackOfFitVerdict::kStructural) {
      text += fmt::format("  lack of fit: {}\n", f.lack_of_fit.text);
    }
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
  for (const ModelFormSpec& form : config.model_forms) {
    // Each alternative's scene edits are checked now, not after the main fit.
    CalibrationConfig alternative = config;
    for (const auto& edit : form.overrides) alternative.forward.overrides.push_back(edit);
    try {
      bind_scenes(alternative);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: model_form '{}': {}", form.where, form.name, e.what()));
    }
  }
  // The scenes of each discrepancy source, checked now and run before the fit.
  std::vector<std::vector<Scene>> source_scenes;
  for (const DiscrepancySpec& source : config.discrepancies) {
    try {
      source_scenes.push_back(discrepancy_scenes(config, source));
    } catch (const InputError& e) {
      throw InputError(
          fmt::format("{}: discrepancy '{}': {}", source.where, source.name, e.what()));
    }
  }
  const std::vector<ModelFormSpec> forms = model_form_alternatives(config);

  CalibrationResult result;
  for (const auto& b : bindings) result.scene_sources.push_back(b.source());
  for (const auto& d : config.data) {
    result.data_weighting.push_back({d.measurement.name, data_set_sigma(d).text, !sigma_stated(d)});
  }
  const ForwardModel model_for_alternatives = forms.empty() ? ForwardModel{} : model;
  std::vector<DataSet> data_sets = make_data_sets(config, bindings);
  std::string start_failure;  // a discrepancy source whose forward run failed
  for (std::size_t k = 0; k < config.discrepancies.size(); ++k) {
    const DiscrepancySpec& source = config.discrepancies[k];
    say(fmt::format("discrepancy '{}': forward run at the reference's parameters", source.name));
    std::vector<RunResult> runs;
    for (const Scene& scene : source_scenes[k]) {
      runs.push_back(run_guarded(model, scene));
      ++result.discrepancy_forward_runs;
    }
    result.discrepancies.push_back(learn_discrepancy(source, data_sets, runs));
    if (!result.discrepancies.back().ok && start_failure.empty()) {
      start_failure = result.discrepancies.back().message;
    }
  }
  if (start_failure.empty() && !result.discrepancies.empty()) {
    const auto corrections = mean_corrections(result.discrepancies, data_sets);
    for (std::size_t k = 0; k < data_sets.size(); ++k) data_sets[k].correction = corrections[k];
  }
  ResidualPipeline pipeline(std::move(data_sets));
  const Eigen::VectorXd noise = residual_noise(config, bindings, pipeline);
  // The scale of the lack-of-fit diagnostic for data sets with no stated sigma: the forward
  // resolution exists whether or not the noise-floor stop is on.
  const std::vector<double> resolution = forward_resolution(
      config, bindings, pipeline,
      config.optimizer.noise_floor_factor > 0.0 ? config.optimizer.noise_floor_factor
                                                : kDefaultNoiseFloorFactor);
  ForwardCache cache(std::move(model), std::move(bindings), config.parameters, std::move(pipeline),
                     config.optimizer.threads);
  // A line per forward evaluation that takes a while, so that a long fit shows its progress
  // between the optimiser's iteration lines; quick ones stay silent.
  cache.set_on_evaluation([&](const Evaluation& e) {
    if (!options.progress || e.wall_time_s < options.progress_evaluation_s) return;
    std::string values;
    for (std::size_t i = 0; i < cache.free_indices().size(); ++i) {
      values +=
          fmt::format("{}{} {:.6g}", i == 0 ? "" : ", ",
                      cache.parameters()[static_cast<std::size_t>(cache.free_indices()[i])].address,
                      e.x[static_cast<Eigen::Index>(i)]);
    }
    say(fmt::format("  evaluation {}: {}: {} ({:.1f} s of forward runs)", e.index + 1, values,
                    e.ok ? fmt::format("cost {:.6g}", e.cost) : "failed: " + e.message,
                    e.wall_time_s));
  });
  Objective objective(&cache, config.optimizer.fd);
  say(fmt::format("calibrate: {} free parameters, {} residuals, {} scene(s), {} thread(s)",
                  objective.num_parameters(), objective.num_residuals(),
                  result.scene_sources.size(), config.optimizer.threads));

  const Eigen::VectorXd x0 = objective.initial();
  // Nothing to fit from: stop now, with the reason, the parameters at their initial values.
  auto stop_at_start = [&](const std::string& message, double cost) {
    result.termination = CalibrationTermination::kFailed;
    result.message = message;
    result.uncertainty_message = "no fit";
    const auto values = cache.all_values(x0);
    for (std::size_t i = 0; i < cache.parameters().size(); ++i) {
      const ParameterSpec& spec = cache.parameters()[i];
      result.parameters.push_back({spec, unit_of_address(spec.address), values[i]});
    }
    result.final_cost = cost;
    finish(cache, config, options, start, &result);
    return result;
  };
  if (!start_failure.empty()) return stop_at_start(start_failure, kNaN);
  const auto first = objective.evaluate(x0);
  result.initial_cost = first->cost;
  // Said at once: a long fit on a model that warns (a mesh finer than the thickness, ...) can be
  // stopped before it has run for hours.
  for (const std::string& w : forward_warnings(*first, result.scene_sources))
    say("warning: at the initial parameters the forward model warns: " + w);
  if (!first->ok) {
    return stop_at_start("the forward run at the initial parameters fails: " +
                             first_failure(*first, result.scene_sources),
                         first->cost);
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
    if (config.optimizer.global.algorithm == "surface") {
      say(fmt::format("global search: the grid costs scatter about the quadratic by {:.4g} rms",
                      result.global.surface_rms));
    }
  }

  LeastSquaresOptions ls = config.optimizer.least_squares;
  ls.progress = options.progress;
  ls.residual_noise = noise;
  const LeastSquaresSummary summary = solve_least_squares(objective, x_start, ls);
  result.noise_floor = summary.noise_floor;
  result.noise_floor_cost = summary.noise_floor_cost;
  result.passes = summary.passes;
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

  // Not for a failed fit, whose point is the start.
  if (result.termination != CalibrationTermination::kFailed) {
    identify_scenes(cache, config, options, values, &result);
  }

  const auto final_point = objective.evaluate(x);
  result.final_cost = final_point->cost;
  result.forward_warnings = forward_warnings(*final_point, result.scene_sources);
  if (final_point->ok) {
    result.fits = make_fits(cache.pipeline(), *final_point, config, resolution);
    if (result.termination == CalibrationTermination::kNotConverged) {
      const std::string why =
          fmt::format("{}, {} iterations{}", summary.termination, summary.iterations,
                      summary.message.empty() ? "" : ": " + summary.message);
      for (DataSetFit& f : result.fits) note_unconverged_fit(why, &f.lack_of_fit);
    }
    const FdJacobian j = options.uncertainty ? objective.jacobian(x) : FdJacobian{};
    if (!options.uncertainty) {
      result.uncertainty_message = "not computed (model-form refit)";
    } else if (j.ok) {
      UncertaintyOptions uncertainty_options = config.uncertainty;
      for (const DataSpec& d : config.data)
        uncertainty_options.eliminated_parameters += d.shape_only;
      result.uncertainty = estimate_uncertainty(j.jacobian, final_point->cost, x, objective.scale(),
                                                objective.lower(), objective.upper(),
                                                objective.names(), uncertainty_options);
      add_forward_resolution(j.jacobian, noise_floor_cost(final_point->residuals, noise),
                             &result.uncertainty);
      result.uncertainty_available = true;
      result.bound_effects = bound_effects(j.jacobian, final_point->residuals, x, objective,
                                           noise_floor_cost(final_point->residuals, noise));
      // A parameter the bound holds back has the bound's value, not one the data determine.
      for (const BoundEffect& b : result.bound_effects) {
        for (auto& u : result.uncertainty.parameters) {
          if (b.active && u.name == b.name) u.determined = false;
        }
      }
    } else {
      result.uncertainty_message = "Jacobian at the optimum failed: " + j.message;
    }
  } else {
    result.uncertainty_message =
        "the forward model fails at the final point: " + final_point->message;
  }

  if (result.termination != CalibrationTermination::kFailed && !forms.empty()) {
    // Model-form sensitivity: the same fit under each alternative model choice, from here.
    const Eigen::VectorXd main_values = result.free_values();
    Eigen::VectorXd lower = main_values, upper = main_values;
    for (const ModelFormSpec& form : forms) {
      say(fmt::format("model form '{}': refit with {}", form.name, edits_text(form)));
      CalibrationOptions quiet;
      quiet.write_report = false;
      quiet.uncertainty = false;
      ModelFormFit fit;
      fit.name = form.name;
      fit.edits = edits_text(form);
      fit.dropped_data = form.drop_data;
      CalibrationResult alternative;
      try {
        alternative = calibrate(model_form_config(config, form, result.parameters), quiet,
                                model_for_alternatives);
      } catch (const std::exception& e) {
        // Checked before the main fit; should a refit still refuse its input, the main fit and
        // the other alternatives are kept and this one says why.
        alternative.termination = CalibrationTermination::kFailed;
        alternative.message = e.what();
        alternative.final_cost = kNaN;
      }
      fit.termination = to_string(alternative.termination);
      fit.message = alternative.message;
      fit.final_cost = alternative.final_cost;
      fit.forward_runs = alternative.forward_runs;
      fit.forward_warnings = alternative.forward_warnings;
      result.model_form_forward_runs += alternative.forward_runs;
      if (alternative.termination != CalibrationTermination::kFailed) {
        const Eigen::VectorXd v = alternative.free_values();
        fit.values.assign(v.data(), v.data() + v.size());
        lower = lower.cwiseMin(v);
        upper = upper.cwiseMax(v);
      }
      result.model_form.push_back(fit);
    }
    for (Eigen::Index j = 0; j < main_values.size(); ++j) {
      ModelFormRange range;
      range.name = objective.names()[static_cast<std::size_t>(j)];
      range.lower = lower[j];
      range.upper = upper[j];
      if (result.uncertainty_available) {
        const auto& u = result.uncertainty.parameters.at(static_cast<std::size_t>(j));
        range.exceeds_interval = range.upper - range.lower > u.interval_upper - u.interval_lower;
      }
      result.model_form_ranges.push_back(range);
    }
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
