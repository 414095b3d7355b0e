#include "report.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "output/number_format.h"
#include "output/svg_plot.h"
#include "output/text_file.h"

namespace vs {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

// JSON has no inf/NaN, and null would leave readers guessing: a non-finite number is left out
// (an unbounded side, an undetermined standard error, a cost of a failed run) and the entry
// says why in words (determined = false, termination = "failed" with its message).
void put_finite(ordered_json& j, const char* key, double value) {
  if (std::isfinite(value)) j[key] = value;
}

// The rows and columns of `m` for the parameters `keep` (those with finite entries).
ordered_json matrix(const Eigen::MatrixXd& m, const std::vector<Eigen::Index>& keep) {
  ordered_json rows = ordered_json::array();
  for (Eigen::Index i : keep) {
    ordered_json row = ordered_json::array();
    for (Eigen::Index j : keep) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

// Free parameters with a finite variance (undetermined ones have NaN rows and columns), so
// that the covariance and correlation among them are finite.
std::vector<Eigen::Index> finite_rows(const Eigen::MatrixXd& covariance,
                                      const Eigen::MatrixXd& correlation) {
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < covariance.rows(); ++i) {
    if (std::isfinite(covariance(i, i)) && std::isfinite(correlation(i, i))) keep.push_back(i);
  }
  for (Eigen::Index i : keep) {
    for (Eigen::Index j : keep) {
      if (!std::isfinite(covariance(i, j)) || !std::isfinite(correlation(i, j))) return {};
    }
  }
  return keep;
}

std::string axis_label(MeasurementKind kind, bool ordinate) {
  if (!ordinate) {
    return kind == MeasurementKind::kLoadTravel         ? "punch travel [mm]"
           : kind == MeasurementKind::kCupHeightProfile ? "angle from the rolling direction [deg]"
                                                        : "r0 [mm]";
  }
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return "punch force [N]";
    case MeasurementKind::kThicknessStrain:
      return "thickness strain [-]";
    case MeasurementKind::kCircumferentialStrain:
      return "circumferential strain [-]";
    case MeasurementKind::kCupHeightProfile:
      return "cup height [mm]";
  }
  return "";
}

SvgFigure fit_figure(const DataSetFit& fit) {
  SvgFigure figure;
  figure.title = !is_strain_profile(fit.kind)
                     ? fmt::format("{}: measured and fitted{}", fit.name,
                                   fit.shape_only ? " (shape only: offset removed)" : "")
                     : fmt::format("{} at {} mm travel: measured and fitted", fit.name,
                                   format_number(fit.travel_mm));
  figure.x_label = axis_label(fit.kind, false);
  figure.y_label = axis_label(fit.kind, true);
  PlotSeries measured{"measured", fit.x, fit.measured, SeriesStyle::kMarkers};
  PlotSeries fitted{fit.correction.empty() ? "fitted" : "fitted, with the discrepancy correction",
                    fit.x, fit.simulated, SeriesStyle::kLine};
  figure.series = {measured, fitted};
  return figure;
}

SvgFigure cost_figure(const CalibrationResult& result) {
  SvgFigure figure;
  figure.title = "cost of every forward evaluation (failed ones omitted)";
  figure.x_label = "evaluation";
  figure.y_label = "log10 cost";
  PlotSeries series{"", {}, {}, SeriesStyle::kMarkers};
  for (const auto& e : result.evaluations) {
    if (!e->ok || !(e->cost > 0.0)) continue;
    series.x.push_back(e->index);
    series.y.push_back(std::log10(e->cost));
  }
  figure.series = {series};
  return figure;
}

}  // namespace

std::string fit_csv(const DataSetFit& fit) {
  std::string text = fmt::format("# data set: {} ({})\n", fit.name, to_string(fit.kind));
  if (is_strain_profile(fit.kind)) {
    text += fmt::format("# punch travel: {} mm\n", format_number(fit.travel_mm));
  }
  if (fit.kind == MeasurementKind::kCupHeightProfile) {
    text += "# final rim profile of the run, interpolated periodically at the measured angles\n";
    if (fit.shape_only) {
      text +=
          fmt::format("# shape only: simulated heights shifted by the best constant offset {} mm\n",
                      format_number(fit.shape_offset_mm));
    }
  }
  const bool corrected = !fit.correction.empty();
  if (corrected) {
    text += "# simulated includes the discrepancy correction (column discrepancy_correction)\n";
  }
  const std::string y = ordinate_name(fit.kind);
  text += fmt::format("{},{}_measured,{}_simulated,weight,residual{}\n", abscissa_name(fit.kind), y,
                      y, corrected ? ",discrepancy_correction" : "");
  for (std::size_t i = 0; i < fit.x.size(); ++i) {
    text += fmt::format("{},{},{},{},{}", format_number(fit.x[i]), format_number(fit.measured[i]),
                        format_number(fit.simulated[i]), format_number(fit.weight[i]),
                        format_number(fit.weight[i] * (fit.simulated[i] - fit.measured[i])));
    text += corrected ? fmt::format(",{}\n", format_number(fit.correction[i])) : "\n";
  }
  return text;
}

std::string calibration_json(const CalibrationResult& result, const CalibrationConfig& config) {
  ordered_json j;
  j["config"] = config.path;
  j["scenes"] = result.scene_sources;
  j["method"] = config.optimizer.method == OptimizerMethod::kGlobalThenLocal
                    ? "global_then_local"
                    : "levenberg_marquardt";
  j["finite_differences"] = {
      {"method", config.optimizer.fd.method == FdMethod::kRidders ? "ridders" : "central"},
      {"relative_step", config.optimizer.fd.relative_step},
      {"threads", config.optimizer.threads},
      {"forward_tolerance", config.forward.tolerance}};
  j["termination"] = to_string(result.termination);
  if (result.termination == CalibrationTermination::kFailed) j["failure"] = result.message;
  j["ceres_termination"] = result.ceres_termination;
  j["message"] = result.message;
  j["iterations"] = result.iterations;
  put_finite(j, "initial_cost", result.initial_cost);
  put_finite(j, "final_cost", result.final_cost);
  j["stopped_at_noise_floor"] = result.noise_floor;
  if (result.noise_floor_cost > 0.0) j["noise_floor_cost"] = result.noise_floor_cost;
  j["noise_floor_factor"] = config.optimizer.noise_floor_factor;
  j["active_set_passes"] = result.passes;
  j["forward_runs"] = result.forward_runs;
  j["evaluations"] = result.evaluations.size();
  j["failed_evaluations"] = result.failed_evaluations;
  j["wall_time_s"] = result.wall_time_s;
  if (result.global_search_used) {
    ordered_json global = {{"algorithm", config.optimizer.global.algorithm},
                           {"seed", config.optimizer.global.seed},
                           {"max_evaluations", config.optimizer.global.max_evaluations},
                           {"evaluations", result.global.evaluations},
                           {"failed_evaluations", result.global.failed_evaluations}};
    put_finite(global, "best_cost", result.global.cost);
    global["result"] = result.global.result;
    if (config.optimizer.global.algorithm == "surface") {
      global["grid_points"] = config.optimizer.global.grid_points;
      global["grid_half_width"] = config.optimizer.global.grid_half_width;
      global["surface_rounds"] = config.optimizer.global.surface_rounds;
      put_finite(global, "surface_rms", result.global.surface_rms);
    }
    j["global_search"] = global;
  }

  ordered_json parameters = ordered_json::array();
  std::size_t k = 0;
  for (const auto& p : result.parameters) {
    ordered_json entry = {{"address", p.spec.address},
                          {"unit", p.unit},
                          {"fixed", p.spec.fixed},
                          {"initial", p.spec.initial}};
    put_finite(entry, "lower", p.spec.lower);  // absent: unbounded
    put_finite(entry, "upper", p.spec.upper);
    entry["scale"] = p.spec.scale;
    entry["value"] = p.value;
    if (!p.spec.fixed && result.uncertainty_available) {
      const auto& u = result.uncertainty.parameters.at(k);
      put_finite(entry, "std_error", u.std_error);  // absent: not determined
      put_finite(entry, "interval_lower", u.interval_lower);
      put_finite(entry, "interval_upper", u.interval_upper);
      entry["forward_resolution"] = u.forward_resolution;  // included in the interval
      entry["determined"] = u.determined;
      entry["at_bound"] = u.at_bound;
    }
    for (const auto& b : result.bound_effects) {
      if (b.name != p.spec.address || p.spec.fixed) continue;
      ordered_json effect = {{"side", b.side < 0 ? "lower" : "upper"},
                             {"bound", b.bound},
                             {"cost_gradient", b.gradient},
                             {"holds_the_fit_back", b.active}};
      if (b.active) {
        effect["unconstrained_value"] = b.unconstrained;
        effect["cost_decrease_without_bound"] = b.cost_decrease;
      }
      effect["statement"] = b.text;
      entry["bound_effect"] = effect;
    }
    if (!p.spec.fixed && !result.model_form_ranges.empty()) {
      for (const auto& range : result.model_form_ranges) {
        if (range.name != p.spec.address) continue;
        entry["model_form_lower"] = range.lower;
        entry["model_form_upper"] = range.upper;
        entry["model_form_wider_than_interval"] = range.exceeds_interval;
      }
    }
    if (!p.spec.fixed) ++k;
    parameters.push_back(entry);
  }
  j["parameters"] = parameters;

  if (result.uncertainty_available) {
    const auto& u = result.uncertainty;
    std::vector<std::string> names;
    for (const auto& pu : u.parameters) names.push_back(pu.name);
    const std::vector<Eigen::Index> keep = finite_rows(u.covariance, u.correlation);
    std::vector<std::string> matrix_names;
    for (Eigen::Index i : keep) matrix_names.push_back(names.at(static_cast<std::size_t>(i)));
    ordered_json uj = {{"confidence", config.uncertainty.confidence},
                       {"quantile", u.quantile},
                       {"quantile_kind", u.quantile_kind},
                       {"residual_variance", u.residual_variance},
                       {"degrees_of_freedom", u.degrees_of_freedom},
                       {"rank", u.rank}};
    put_finite(uj, "condition_number", u.condition_number);  // absent: rank deficient
    uj["singular_values"] = u.singular_values;
    uj["free_parameters"] = names;
    // Covariance and correlation over the determined parameters only (the others have no
    // finite entries).
    uj["matrix_parameters"] = matrix_names;
    uj["correlation"] = matrix(u.correlation, keep);
    uj["covariance"] = matrix(u.covariance, keep);
    uj["statements"] = u.statements;
    j["uncertainty"] = uj;
  } else {
    j["uncertainty"] = {{"unavailable", result.uncertainty_message}};
  }

  ordered_json weighting = ordered_json::array();
  for (const auto& w : result.data_weighting) {
    weighting.push_back(
        {{"name", w.name}, {"weighting", w.text}, {"relative_default", w.relative_default}});
  }
  j["data_weighting"] = weighting;

  ordered_json data = ordered_json::array();
  for (const auto& fit : result.fits) {
    ordered_json entry = {
        {"name", fit.name}, {"kind", to_string(fit.kind)}, {"points", fit.x.size()}};
    put_finite(entry, "cost", fit.cost);
    put_finite(entry, "rms_difference", fit.rms_difference);
    entry["rms_unit"] = ordinate_unit(fit.kind);
    if (is_strain_profile(fit.kind)) entry["travel_mm"] = fit.travel_mm;
    if (fit.kind == MeasurementKind::kCupHeightProfile) {
      entry["shape_only"] = fit.shape_only;
      if (fit.shape_only) put_finite(entry, "shape_offset_mm", fit.shape_offset_mm);
    }
    const LackOfFit& l = fit.lack_of_fit;
    // The scale of the test: the stated sigma, or the forward resolution when none was stated
    // (lack_of_fit.h); rms_normalised is in that unit.
    ordered_json lof = {{"verdict", to_string(l.verdict)},
                        {"points", l.points},
                        {"sigma_stated", l.sigma_stated},
                        {"rms_unit", l.sigma_stated ? "sigma" : "forward_resolution"},
                        {"fit_converged", l.fit_converged}};
    if (!l.sigma_stated) {
      lof["rms_difference"] = l.rms_difference;
      lof["forward_resolution"] = l.resolution;
      lof["data_unit"] = l.unit;
    }
    if (l.verdict != LackOfFitVerdict::kNotTested) {
      lof["rms_normalised"] = l.rms;
      lof["runs"] = l.runs;
      lof["runs_expected"] = l.runs_expected;
      put_finite(lof, "runs_z", l.runs_z);
      lof["runs_p"] = l.runs_p;
      lof["lag1_autocorrelation"] = l.lag1;
      lof["lag1_z"] = l.lag1_z;
      lof["z_critical"] = l.z_critical;
    }
    lof["statement"] = l.text;
    entry["lack_of_fit"] = lof;
    data.push_back(entry);
  }
  j["data_sets"] = data;
  if (!result.model_form.empty()) {
    ordered_json forms = ordered_json::array();
    for (const auto& f : result.model_form) {
      ordered_json entry = {{"name", f.name},
                            {"scene_edits", f.edits},
                            {"dropped_data", f.dropped_data},
                            {"termination", f.termination},
                            {"message", f.message},
                            {"forward_runs", f.forward_runs}};
      put_finite(entry, "final_cost", f.final_cost);
      if (!f.values.empty()) entry["values"] = f.values;
      entry["forward_warnings"] = f.forward_warnings;
      forms.push_back(entry);
    }
    j["model_form"] = {{"fits", forms}, {"forward_runs", result.model_form_forward_runs}};
  }
  if (!result.discrepancies.empty()) {
    ordered_json sources = ordered_json::array();
    for (const auto& source : result.discrepancies) {
      ordered_json curves = ordered_json::array();
      for (const auto& c : source.curves) {
        curves.push_back({{"data", c.data},
                          {"file", c.file},
                          {"unit", c.unit},
                          {"rms_correction", c.rms},
                          {"max_abs_correction", c.max_abs}});
      }
      ordered_json entry = {
          {"name", source.name}, {"scene_edits", source.edits}, {"ok", source.ok}};
      if (!source.ok) entry["message"] = source.message;
      entry["data_sets"] = curves;
      sources.push_back(entry);
    }
    j["discrepancy"] = {{"sources", sources},
                        {"combined_as", "mean over the sources that cover a data set"},
                        {"forward_runs", result.discrepancy_forward_runs}};
  }
  j["forward_warnings"] = result.forward_warnings;
  j["notes"] = result.report_notes;
  return j.dump(2) + "\n";
}

std::string evaluations_csv(const CalibrationResult& result) {
  std::string text = "index,status,cost,wall_time_s";
  for (const auto& p : result.parameters) {
    if (!p.spec.fixed) text += fmt::format(",{}", p.spec.address);
  }
  text += ",message\n";
  for (const auto& e : result.evaluations) {
    // A failed point has no cost: the cell is left empty (status says failed).
    text += fmt::format("{},{},{},{}", e->index, e->ok ? "ok" : "failed",
                        e->ok && std::isfinite(e->cost) ? format_number(e->cost) : "",
                        format_number(e->wall_time_s));
    for (Eigen::Index i = 0; i < e->x.size(); ++i)
      text += fmt::format(",{}", format_number(e->x[i]));
    std::string message = e->message;
    for (char& c : message) {
      if (c == '"') c = '\'';
    }
    text += fmt::format(",\"{}\"\n", message);
  }
  return text;
}

std::vector<std::string> write_calibration_report(const CalibrationResult& result,
                                                  const CalibrationConfig& config,
                                                  const std::string& directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) {
    throw InputError(
        fmt::format("{}: cannot create the output folder: {}", directory, error.message()));
  }
  std::vector<std::string> notes;
  const fs::path dir(directory);
  for (const auto& fit : result.fits) {
    write_text_file((dir / ("fit_" + fit.name + ".csv")).string(), fit_csv(fit));
    if (config.plots) write_svg(fit_figure(fit), (dir / ("fit_" + fit.name + ".svg")).string());
  }
  if (config.plots) write_svg(cost_figure(result), (dir / "cost.svg").string());
  if (result.fits.empty()) notes.push_back("no fit files: the final point has no forward result");
  write_text_file((dir / "evaluations.csv").string(), evaluations_csv(result));
  CalibrationResult with_notes = result;
  with_notes.report_notes.insert(with_notes.report_notes.end(), notes.begin(), notes.end());
  write_text_file((dir / "calibration.json").string(), calibration_json(with_notes, config));
  for (std::size_t k = 0; k < result.identified_scenes.size() && k < config.scenes.size(); ++k) {
    if (result.identified_scenes[k].empty()) continue;
    write_text_file((dir / ("identified_" + config.scenes[k].name + ".toml")).string(),
                    result.identified_scenes[k]);
  }
  return notes;
}

}  // namespace vs
