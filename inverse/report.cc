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

// JSON has no inf/NaN: they become null (an undetermined std error, an absent bound).
ordered_json number(double value) {
  return std::isfinite(value) ? ordered_json(value) : ordered_json(nullptr);
}

ordered_json matrix(const Eigen::MatrixXd& m) {
  ordered_json rows = ordered_json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    ordered_json row = ordered_json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(number(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

std::string axis_label(MeasurementKind kind, bool ordinate) {
  if (!ordinate) return kind == MeasurementKind::kLoadTravel ? "punch travel [mm]" : "r0 [mm]";
  switch (kind) {
    case MeasurementKind::kLoadTravel:
      return "punch force [N]";
    case MeasurementKind::kThicknessStrain:
      return "thickness strain [-]";
    case MeasurementKind::kCircumferentialStrain:
      return "circumferential strain [-]";
  }
  return "";
}

std::string fit_csv(const DataSetFit& fit) {
  std::string text = fmt::format("# data set: {} ({})\n", fit.name, to_string(fit.kind));
  if (fit.kind != MeasurementKind::kLoadTravel) {
    text += fmt::format("# punch travel: {} mm\n", format_number(fit.travel_mm));
  }
  const std::string y = ordinate_name(fit.kind);
  text +=
      fmt::format("{},{}_measured,{}_simulated,weight,residual\n", abscissa_name(fit.kind), y, y);
  for (std::size_t i = 0; i < fit.x.size(); ++i) {
    text += fmt::format("{},{},{},{},{}\n", format_number(fit.x[i]), format_number(fit.measured[i]),
                        format_number(fit.simulated[i]), format_number(fit.weight[i]),
                        format_number(fit.weight[i] * (fit.simulated[i] - fit.measured[i])));
  }
  return text;
}

SvgFigure fit_figure(const DataSetFit& fit) {
  SvgFigure figure;
  figure.title = fit.kind == MeasurementKind::kLoadTravel
                     ? fmt::format("{}: measured and fitted", fit.name)
                     : fmt::format("{} at {} mm travel: measured and fitted", fit.name,
                                   format_number(fit.travel_mm));
  figure.x_label = axis_label(fit.kind, false);
  figure.y_label = axis_label(fit.kind, true);
  PlotSeries measured{"measured", fit.x, fit.measured, SeriesStyle::kMarkers};
  PlotSeries fitted{"fitted", fit.x, fit.simulated, SeriesStyle::kLine};
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
  j["ceres_termination"] = result.ceres_termination;
  j["message"] = result.message;
  j["iterations"] = result.iterations;
  j["initial_cost"] = number(result.initial_cost);
  j["final_cost"] = number(result.final_cost);
  j["forward_runs"] = result.forward_runs;
  j["evaluations"] = result.evaluations.size();
  j["failed_evaluations"] = result.failed_evaluations;
  j["wall_time_s"] = result.wall_time_s;
  if (result.global_search_used) {
    j["global_search"] = {{"algorithm", config.optimizer.global.algorithm},
                          {"seed", config.optimizer.global.seed},
                          {"max_evaluations", config.optimizer.global.max_evaluations},
                          {"evaluations", result.global.evaluations},
                          {"failed_evaluations", result.global.failed_evaluations},
                          {"best_cost", number(result.global.cost)},
                          {"result", result.global.result}};
  }

  ordered_json parameters = ordered_json::array();
  std::size_t k = 0;
  for (const auto& p : result.parameters) {
    ordered_json entry = {{"address", p.spec.address},     {"unit", p.unit},
                          {"fixed", p.spec.fixed},         {"initial", p.spec.initial},
                          {"lower", number(p.spec.lower)}, {"upper", number(p.spec.upper)},
                          {"scale", p.spec.scale},         {"value", p.value}};
    if (!p.spec.fixed && result.uncertainty_available) {
      const auto& u = result.uncertainty.parameters.at(k);
      entry["std_error"] = number(u.std_error);
      entry["interval_lower"] = number(u.interval_lower);
      entry["interval_upper"] = number(u.interval_upper);
      entry["determined"] = u.determined;
      entry["at_bound"] = u.at_bound;
    }
    if (!p.spec.fixed) ++k;
    parameters.push_back(entry);
  }
  j["parameters"] = parameters;

  if (result.uncertainty_available) {
    const auto& u = result.uncertainty;
    j["uncertainty"] = {{"confidence", config.uncertainty.confidence},
                        {"quantile", u.quantile},
                        {"quantile_kind", u.quantile_kind},
                        {"residual_variance", u.residual_variance},
                        {"degrees_of_freedom", u.degrees_of_freedom},
                        {"rank", u.rank},
                        {"condition_number", number(u.condition_number)},
                        {"singular_values", u.singular_values},
                        {"free_parameters",
                         [&] {
                           std::vector<std::string> names;
                           for (const auto& pu : u.parameters) names.push_back(pu.name);
                           return names;
                         }()},
                        {"correlation", matrix(u.correlation)},
                        {"covariance", matrix(u.covariance)},
                        {"statements", u.statements}};
  } else {
    j["uncertainty"] = {{"unavailable", result.uncertainty_message}};
  }

  ordered_json data = ordered_json::array();
  for (const auto& fit : result.fits) {
    ordered_json entry = {{"name", fit.name},
                          {"kind", to_string(fit.kind)},
                          {"points", fit.x.size()},
                          {"cost", number(fit.cost)},
                          {"rms_difference", number(fit.rms_difference)},
                          {"rms_unit", fit.kind == MeasurementKind::kLoadTravel ? "N" : "1"}};
    if (fit.kind != MeasurementKind::kLoadTravel) entry["travel_mm"] = fit.travel_mm;
    data.push_back(entry);
  }
  j["data_sets"] = data;
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
    text += fmt::format("{},{},{},{}", e->index, e->ok ? "ok" : "failed", format_number(e->cost),
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
  return notes;
}

}  // namespace vs
