#include "fit_hardening_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "material/hardening.h"
#include "output/svg_plot.h"
#include "tensile_fit.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

struct FitArgs {
  std::string csv;
  std::string law = "all";
  std::string output_directory = "fit_hardening";
  double elastic_modulus_MPa = 70000.0;
  double max_strain = 0.0;
  bool allow_past_maximum = false;
};

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw InputError("cannot write " + path.string());
}

nlohmann::json law_json(const LawFit& fit) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const ParameterUncertainty& p : fit.uncertainty.parameters) {
    parameters.push_back({{"name", p.name},
                          {"value", p.value},
                          {"std_error", p.std_error},
                          {"ci95", {p.interval_lower, p.interval_upper}},
                          {"determined", p.determined}});
  }
  nlohmann::json j = {{"law", fit_law_name(fit.law)},
                      {"parameters", parameters},
                      {"rms_MPa", fit.rms_MPa},
                      {"max_abs_residual_MPa", fit.max_abs_residual_MPa},
                      {"aic", fit.aic},
                      {"termination", fit.termination},
                      {"interval_quantile", fit.uncertainty.quantile_kind},
                      {"statements", fit.uncertainty.statements},
                      {"considere_found", fit.considere_found},
                      {"considere_true_strain", fit.considere_true_strain},
                      {"considere_plastic_strain", fit.considere_plastic_strain}};
  if (fit.law == FitLaw::kHollomon) j["sigma0_MPa_plateau_at_first_point"] = fit.spec.sigma0_MPa;
  return j;
}

std::string law_csv(const FitRange& range, const TensileCurve& curve, const LawFit& fit) {
  std::string text =
      "line,true_strain,plastic_strain,measured_true_stress_MPa,fitted_MPa,residual_MPa\n";
  for (std::size_t i = 0; i < range.rows.size(); ++i) {
    text += fmt::format("{},{:.8g},{:.8g},{:.8g},{:.8g},{:.6g}\n", curve.line[range.rows[i]],
                        range.true_strain[i], range.plastic_strain[i], range.true_stress_MPa[i],
                        fit.fitted_MPa[i], fit.fitted_MPa[i] - range.true_stress_MPa[i]);
  }
  return text;
}

SvgFigure figure(const TensileCurve& curve, const FitRange& range, const std::vector<LawFit>& fits,
                 double modulus) {
  SvgFigure fig;
  fig.title = "Hardening fits to " + fs::path(curve.source).filename().string();
  fig.x_label = "plastic strain [-]";
  fig.y_label = "true stress [MPa]";
  PlotSeries measured{"measured (to the load maximum)", {}, {}, SeriesStyle::kMarkers, 0};
  measured.marker_radius_px = 1.5;
  for (int i = 0; i <= range.max_load_row; i += 4) {
    const double ep = curve.true_strain[i] - curve.true_stress_MPa[i] / modulus;
    if (ep <= 0.0) continue;
    measured.x.push_back(ep);
    measured.y.push_back(curve.true_stress_MPa[i]);
  }
  fig.series.push_back(measured);
  const double e_max = std::max(range.plastic_strain.back(), range.max_load_plastic_strain);
  int colour = 1;
  for (const LawFit& fit : fits) {
    const Hardening h(fit.spec);
    PlotSeries s{fmt::format("{} (RMS {:.2f} MPa)", fit_law_name(fit.law), fit.rms_MPa),
                 {},
                 {},
                 SeriesStyle::kLine,
                 colour++};
    for (int k = 0; k <= 200; ++k) {
      const double ep = 1.25 * e_max * k / 200.0;
      s.x.push_back(ep);
      s.y.push_back(h.flow_stress(ep));
    }
    fig.series.push_back(s);
  }
  PlotSeries maximum{"load maximum",
                     {range.max_load_plastic_strain},
                     {range.max_load_true_stress_MPa},
                     SeriesStyle::kMarkers,
                     5};
  maximum.marker_radius_px = 5.0;
  fig.series.push_back(maximum);
  return fig;
}

void run_fit(const FitArgs& args) {
  try {
    const TensileCurve curve = read_tensile_csv(args.csv);
    TensileFitOptions options;
    options.elastic_modulus_MPa = args.elastic_modulus_MPa;
    options.max_true_strain = args.max_strain;
    options.allow_past_maximum = args.allow_past_maximum;
    const FitRange range = select_fit_range(curve, options);
    for (const std::string& w : range.warnings) fmt::print(stderr, "warning: {}\n", w);

    std::vector<FitLaw> laws;
    if (args.law == "all") {
      laws = {FitLaw::kSwift, FitLaw::kVoce, FitLaw::kHollomon};
    } else {
      laws = {parse_fit_law(args.law)};
    }
    std::error_code ec;
    fs::create_directories(args.output_directory, ec);
    if (!fs::is_directory(args.output_directory)) {
      throw InputError("cannot create output folder " + args.output_directory);
    }
    const fs::path dir(args.output_directory);
    std::vector<LawFit> fits;
    for (FitLaw law : laws) {
      fits.push_back(fit_hardening_law(law, range.plastic_strain, range.true_stress_MPa,
                                       args.elastic_modulus_MPa));
      write_text(dir / ("fit_" + fit_law_name(law) + ".csv"), law_csv(range, curve, fits.back()));
    }
    const auto best = std::min_element(fits.begin(), fits.end(),
                                       [](const auto& a, const auto& b) { return a.aic < b.aic; });
    nlohmann::json j = {
        {"source", args.csv},
        {"elastic_modulus_MPa", args.elastic_modulus_MPa},
        {"fitted_points", range.rows.size()},
        {"fitted_lines", {curve.line[range.rows.front()], curve.line[range.rows.back()]}},
        {"fitted_plastic_strain", {range.plastic_strain.front(), range.plastic_strain.back()}},
        {"load_maximum",
         {{"line", curve.line[range.max_load_row]},
          {"engineering_stress_MPa", range.max_load_eng_stress_MPa},
          {"true_strain", range.max_load_true_strain},
          {"plastic_strain", range.max_load_plastic_strain},
          {"true_stress_MPa", range.max_load_true_stress_MPa},
          {"after_load_reversal", range.max_load_after_reversal}}},
        {"load_reversal_line",
         range.reversal_row >= 0 ? nlohmann::json(curve.line[range.reversal_row]) : nullptr},
        {"usable_range_end_true_strain", range.end_true_strain},
        {"warnings", range.warnings},
        {"best_law_by_aic", fit_law_name(best->law)},
        {"note",
         "intervals assume independent residuals; consecutive points of one curve are correlated, "
         "so they understate the material's uncertainty"}};
    for (const LawFit& fit : fits) j["fits"].push_back(law_json(fit));
    write_text(dir / "fit.json", j.dump(2) + "\n");
    write_svg(figure(curve, range, fits, args.elastic_modulus_MPa), (dir / "fit.svg").string());

    fmt::print(
        "{}: {} points, plastic strain {:.4f} to {:.4f}; load maximum at true strain {:.4f} "
        "({:.1f} MPa true)\n",
        args.csv, range.rows.size(), range.plastic_strain.front(), range.plastic_strain.back(),
        range.max_load_true_strain, range.max_load_true_stress_MPa);
    for (const LawFit& fit : fits) {
      fmt::print(
          "{:9s} RMS {:6.3f} MPa  AIC {:9.1f}  Considere true strain {:.4f} (measured load "
          "maximum {:.4f}{})\n",
          fit_law_name(fit.law), fit.rms_MPa, fit.aic, fit.considere_true_strain,
          range.max_load_true_strain,
          range.max_load_after_reversal ? ", after a load reversal: not comparable" : "");
      for (const ParameterUncertainty& p : fit.uncertainty.parameters) {
        fmt::print("          {:11s} {:12.6g} +- {:10.3g}  95% [{:.6g}, {:.6g}]\n", p.name, p.value,
                   p.std_error, p.interval_lower, p.interval_upper);
      }
      for (const std::string& s : fit.uncertainty.statements) fmt::print("          note: {}\n", s);
    }
    fmt::print("best law (AIC): {}\noutput folder: {}\n", fit_law_name(best->law),
               args.output_directory);
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    throw CLI::RuntimeError(2);
  }
}

}  // namespace

void add_fit_hardening_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* sub = app.add_subcommand(
      "fit-hardening",
      "Fit Swift/Voce/Hollomon hardening to a measured tensile curve (CSV with columns "
      "Time,Estrain,Estress,Tstrain,Tstress) up to the load maximum");
  sub->add_option("CSV", args->csv, "Tensile curve CSV")->required()->type_name("FILE");
  sub->add_option("--law", args->law, "swift, voce, hollomon or all")
      ->check(CLI::IsMember({"swift", "voce", "hollomon", "all"}))
      ->capture_default_str();
  sub->add_option("-o,--output", args->output_directory, "Output folder")->capture_default_str();
  sub->add_option("--elastic-modulus-MPa", args->elastic_modulus_MPa,
                  "Young's modulus for plastic strain = true strain - true stress / E")
      ->capture_default_str();
  sub->add_option("--max-strain", args->max_strain,
                  "Fit only up to this true strain (default: the load maximum)");
  sub->add_flag("--allow-past-maximum", args->allow_past_maximum,
                "Allow --max-strain beyond the load maximum (warns instead of refusing)");
  sub->callback([args] { run_fit(*args); });
}

}  // namespace vs
