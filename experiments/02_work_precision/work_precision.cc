// Work-precision study (issue 5): for each bundled scene, error against wall time while varying
// elements, step caps, step fraction, thickness points and tolerance. Writes a CSV of every run,
// SVG plots of error against time and a summary with the observed orders, the Pareto front and
// the recommended settings for 10%, 1% and 0.1%.
//
//   build-exp/experiments/work_precision [--quick] [--out DIR]
#include "common/work_precision.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "common/table.h"
#include "output/svg_plot.h"

namespace {

using namespace vsx;

struct SceneCase {
  std::string name;
  Overrides ov;  // applied before every setting (study travel, outputs)
  std::string why;
};

constexpr double kBudgetS = 180.0;

std::string run_label(const Outcome& o) { return o.setting.family + " " + o.setting.label; }

void plot(const std::string& path, const std::string& title, const std::string& ylabel,
          const std::vector<Outcome>& all, double Errors::*field) {
  vs::SvgFigure fig;
  fig.title = title;
  fig.x_label = "log10(run time = thread CPU time [s])";
  fig.y_label = ylabel;
  std::map<std::string, vs::PlotSeries> by_family;
  std::vector<std::string> order;
  vs::PlotSeries front{"Pareto front", {}, {}, vs::SeriesStyle::kLine};
  front.dashed = true;
  front.colour = 7;
  std::vector<const Outcome*> fr;
  for (const Outcome& o : all) {
    const double e = o.err.*field;
    if (!o.run.result.completed() || !(e > 0.0)) continue;
    if (!by_family.count(o.setting.family)) {
      order.push_back(o.setting.family);
      by_family[o.setting.family] =
          vs::PlotSeries{o.setting.family, {}, {}, vs::SeriesStyle::kMarkers};
      by_family[o.setting.family].marker_radius_px = 3.5;
    }
    by_family[o.setting.family].x.push_back(std::log10(o.run.cpu_s));
    by_family[o.setting.family].y.push_back(std::log10(e));
    if (o.pareto) fr.push_back(&o);
  }
  std::sort(fr.begin(), fr.end(),
            [](const Outcome* a, const Outcome* b) { return a->run.cpu_s < b->run.cpu_s; });
  for (const Outcome* o : fr) {
    const double e = o->err.*field;
    if (!(e > 0.0)) continue;
    front.x.push_back(std::log10(o->run.cpu_s));
    front.y.push_back(std::log10(e));
  }
  for (const auto& f : order) fig.series.push_back(by_family[f]);
  if (field == &Errors::combined) fig.series.push_back(front);
  vs::write_svg(fig, path);
}

std::string study_scene(const SceneCase& sc, bool quick, const std::string& out_dir, Table* csv) {
  const std::string path = scene_path(VS_SOURCE_DIR, sc.name);
  const vs::Scene base = make_scene(path, sc.ov);
  std::vector<Outcome> all;
  const int max_el = max_valid_elements(base);
  for (const Setting& s : work_precision_settings(base.blank.elements, max_el, quick)) {
    Overrides ov = sc.ov;
    ov.insert(ov.end(), s.ov.begin(), s.ov.end());
    Outcome o;
    o.setting = s;
    const vs::Scene scene = make_scene(path, ov);
    o.run = run_timed(scene, 3, kBudgetS, 0.5);
    measure(&o);
    std::cout << fmt::format("  {:<30} {:8.1f} ms  {}{}\n", run_label(o), 1e3 * o.run.cpu_s,
                             o.run.result.message,
                             o.run.result.warnings.empty() ? "" : " [solver warning]");
    all.push_back(std::move(o));
  }
  const Reference ref =
      make_reference(&all, base.process.output_travels_mm, base.process.punch_travel_mm);
  std::string md = fmt::format(
      "### {}\n\n{} Valid meshes: at most {} elements (element length >= thickness {} mm); "
      "finer meshes are outside the thin-shell model and are not used.\n\n",
      sc.name, sc.why, max_el, base.blank.thickness_mm);
  if (!ref.ok) {
    md += "No reference: " + ref.note + "Errors not computed.\n\n";
    return md;
  }
  for (Outcome& o : all) o.err = errors_against(o, ref);
  mark_pareto(&all);
  for (const Outcome& o : all) {
    const vs::RunResult& r = o.run.result;
    csv->add({sc.name, o.setting.family, o.setting.label, describe(o.setting.ov),
              r.completed() ? "yes" : "no", ms(o.run.wall_s), ms(o.run.cpu_s),
              std::to_string(r.steps.size()), std::to_string(r.total_iterations),
              std::to_string(r.total_cutbacks), fmt::format("{:.2f}", o.peak_N), g4(o.err.peak),
              g4(o.err.curve), g4(o.err.strain_abs), g4(o.err.strain_rel), g4(o.thinnest_r0_mm),
              g4(o.err.position_mm), g4(o.err.combined), o.pareto ? "yes" : "no"});
  }
  std::string lv, pk, th, tm;
  for (const Outcome* o : ref.levels) {
    const auto sep = [](const std::string& x) { return x.empty() ? "" : "/"; };
    lv += sep(lv) + fmt::format("{}", o->run.result.profiles.front().r0_mm.size());
    pk += sep(pk) + fmt::format("{:.1f}", o->peak_N);
    th += sep(th) + fmt::format("{:.3f}", o->thinnest_r0_mm);
    tm += sep(tm) + fmt::format("{:.0f}", 1e3 * o->run.cpu_s);
  }
  md += fmt::format(
      "Reference levels (elements x 1, 2, 4 up to the finest valid mesh, travel cap 0.1, 0.05, "
      "0.025 mm and strain cap 0.02, 0.01, 0.005, 9 thickness points, tolerance 1e-8), completed: "
      "{} elements ({} ms). {}Peak load {} N: "
      "observed order p = {:.2f}, {} -> reference {:.1f} N, estimated error of the reference run "
      "{}. Thinnest point r0 {} mm: p = {:.2f}, {}. Curves and profiles are compared with the "
      "reference run itself.\n\n",
      lv, tm, ref.note, pk, ref.peak.order,
      ref.peak.asymptotic ? "Richardson extrapolation used"
                          : "no extrapolation (finest value used)",
      ref.peak.value, pct(ref.peak.error_est / ref.peak.value), th, ref.thinnest.order,
      ref.thinnest.asymptotic ? "extrapolated" : "finest value used");
  Table rec;
  rec.header = {
      "target",         "fastest setting within it", "cpu ms", "peak", "curve L2", "eps_t max abs",
      "thinnest dr0 mm"};
  for (double target : {0.1, 0.01, 0.001}) {
    const Outcome* o = fastest_within(all, target);
    if (!o) {
      rec.add({pct(target), "none of the settings tried", "-", "-", "-", "-", "-"});
      continue;
    }
    rec.add({pct(target), run_label(*o) + ": " + describe(o->setting.ov), ms(o->run.cpu_s),
             pct(o->err.peak), pct(o->err.curve), g4(o->err.strain_abs), g4(o->err.position_mm)});
  }
  md +=
      "Recommended settings (accuracy = max of peak-load error, load-curve relative L2 and "
      "thickness-strain error relative to max |eps_t|; the reference itself is uncertain by "
      "about the estimate above, so targets below it are not resolved):\n\n" +
      rec.markdown() + "\n";
  Table front;
  front.header = {"setting",  "cpu ms",        "combined",       "peak",
                  "curve L2", "eps_t max abs", "thinnest dr0 mm"};
  std::vector<const Outcome*> fr;
  for (const Outcome& o : all) {
    if (o.pareto) fr.push_back(&o);
  }
  std::sort(fr.begin(), fr.end(),
            [](const Outcome* a, const Outcome* b) { return a->run.cpu_s < b->run.cpu_s; });
  for (const Outcome* o : fr) {
    front.add({run_label(*o), ms(o->run.cpu_s), pct(o->err.combined), pct(o->err.peak),
               pct(o->err.curve), g4(o->err.strain_abs), g4(o->err.position_mm)});
  }
  md += "Pareto front (the reference run itself is left out):\n\n" + front.markdown();
  int failed = 0;
  for (const Outcome& o : all) {
    if (!o.run.result.completed()) {
      ++failed;
      md += fmt::format("\n- did not complete: `{}` — {}", describe(o.setting.ov),
                        o.run.result.message);
    }
  }
  md += failed ? "\n\n" : "\n";
  const std::string stem = out_dir + "/" + sc.name;
  plot(stem + "_combined.svg", sc.name + ": combined error vs time", "log10(combined error)", all,
       &Errors::combined);
  plot(stem + "_peak.svg", sc.name + ": peak load error vs time", "log10(|dP|/P)", all,
       &Errors::peak);
  plot(stem + "_curve.svg", sc.name + ": load curve relative L2 vs time", "log10(rel. L2)", all,
       &Errors::curve);
  plot(stem + "_strain.svg", sc.name + ": thickness strain max abs vs time", "log10(max |d eps_t|)",
       all, &Errors::strain_abs);
  plot(stem + "_position.svg", sc.name + ": thinnest point position vs time", "log10(|d r0| [mm])",
       all, &Errors::position_mm);
  md += fmt::format(
      "Figures: [combined]({0}_combined.svg), [peak]({0}_peak.svg), [curve]({0}_curve.svg), "
      "[strain]({0}_strain.svg), [position]({0}_position.svg).\n\n![{1}]({0}_combined.svg)\n\n",
      "02_work_precision/results/" + sc.name, sc.name);
  return md;
}

// Time-integration study: Euler against Heun on one mesh, the travel increment varied alone (the
// strain cap is lifted to its maximum 0.5 so that the travel grid sets the steps; contact events
// still split grid intervals). Errors against a Heun run at a quarter of the finest increment.
struct TiRun {
  std::string scheme;
  double dt_mm = 0.0;
  TimedRun run;
  double pole = kNaN, thin = kNaN, peak = kNaN;
  double e_pole = kNaN, e_thin = kNaN, e_peak = kNaN;
  double p_pole = kNaN, p_thin = kNaN, p_peak = kNaN;
  bool warned = false;
};

void ti_measure(TiRun* t) {
  const vs::RunResult& r = t->run.result;
  t->warned = !r.warnings.empty();
  if (!r.completed() || r.profiles.empty()) return;
  const vs::Profile& fin = r.profiles.back();
  t->pole = pole_thickness_strain(fin);
  t->thin = *std::min_element(fin.eps_thickness.begin(), fin.eps_thickness.end());
  t->peak = peak_load(r).force_N;
}

std::string time_integration_study(const std::string& scene_name, const Overrides& scene_ov,
                                   bool quick, const std::string& out_dir) {
  const std::string path = scene_path(VS_SOURCE_DIR, scene_name);
  const std::vector<double> incs =
      quick ? std::vector<double>{1.0, 0.5, 0.25} : std::vector<double>{1.0, 0.5, 0.25, 0.1, 0.05};
  const double ref_inc = incs.back() / 4.0;
  auto run = [&](const std::string& scheme, double dt) {
    TiRun t;
    t.scheme = scheme;
    t.dt_mm = dt;
    Overrides ov = scene_ov;
    ov.push_back({"numerics.time_integration", scheme});
    ov.push_back({"numerics.max_travel_increment_mm", fmt::format("{}", dt)});
    ov.push_back({"numerics.max_travel_increment_per_length", "1e9"});
    ov.push_back({"numerics.max_strain_increment", "0.5"});
    t.run = run_timed(make_scene(path, ov), 3, kBudgetS, 0.5);
    ti_measure(&t);
    std::cout << fmt::format("  {:<6} {:6.3f} mm {:9.1f} ms  {}\n", scheme, dt, 1e3 * t.run.cpu_s,
                             t.run.result.message);
    return t;
  };
  const TiRun ref = run("heun", ref_inc);
  std::vector<TiRun> rows;
  for (const char* scheme : {"euler", "heun"}) {
    const std::size_t first = rows.size();
    for (double dt : incs) {
      TiRun t = run(scheme, dt);
      t.e_pole = std::abs(t.pole - ref.pole);
      t.e_thin = std::abs(t.thin - ref.thin);
      t.e_peak = rel(t.peak, ref.peak);
      if (rows.size() > first) {
        const TiRun& c = rows.back();
        const double lr = std::log(c.dt_mm / t.dt_mm);
        t.p_pole = std::log(c.e_pole / t.e_pole) / lr;
        t.p_thin = std::log(c.e_thin / t.e_thin) / lr;
        t.p_peak = std::log(c.e_peak / t.e_peak) / lr;
      }
      rows.push_back(std::move(t));
    }
  }
  Table tab, csv;
  tab.header = {"scheme",    "travel inc mm", "cpu ms", "steps",  "pole eps_t", "err pole", "order",
                "min eps_t", "err min",       "order",  "peak N", "err peak",   "order"};
  csv.header = {"scheme",    "travel_inc_mm", "cpu_ms",   "wall_ms",    "steps",
                "completed", "pole_eps_t",    "err_pole", "order_pole", "min_eps_t",
                "err_min",   "order_min",     "peak_N",   "err_peak",   "order_peak"};
  auto f2 = [](double x) { return x == x ? fmt::format("{:.2f}", x) : std::string("-"); };
  auto e2 = [](double x) { return x == x ? fmt::format("{:.2e}", x) : std::string("-"); };
  for (const TiRun* t : [&] {
         std::vector<const TiRun*> v;
         for (const TiRun& r : rows) v.push_back(&r);
         v.push_back(&ref);
         return v;
       }()) {
    const bool is_ref = t == &ref;
    tab.add({is_ref ? "heun (reference)" : t->scheme, fmt::format("{}", t->dt_mm), ms(t->run.cpu_s),
             std::to_string(t->run.result.steps.size()), fmt::format("{:.5f}", t->pole),
             is_ref ? "-" : e2(t->e_pole), f2(t->p_pole), fmt::format("{:.5f}", t->thin),
             is_ref ? "-" : e2(t->e_thin), f2(t->p_thin), fmt::format("{:.1f}", t->peak),
             is_ref ? "-" : pct(t->e_peak), f2(t->p_peak)});
    csv.add({is_ref ? "heun_reference" : t->scheme, g4(t->dt_mm), ms(t->run.cpu_s),
             ms(t->run.wall_s), std::to_string(t->run.result.steps.size()),
             t->run.result.completed() ? "yes" : "no", g4(t->pole), g4(t->e_pole), g4(t->p_pole),
             g4(t->thin), g4(t->e_thin), g4(t->p_thin), g4(t->peak), g4(t->e_peak), g4(t->p_peak)});
  }
  write_text(out_dir + "/time_integration.csv", csv.csv());
  // Plots: error against run time per scheme.
  auto fig = [&](const std::string& file, const std::string& title, double TiRun::*field) {
    vs::SvgFigure f;
    f.title = title;
    f.x_label = "log10(run time = thread CPU time [s])";
    f.y_label = "log10(error)";
    for (const char* scheme : {"euler", "heun"}) {
      vs::PlotSeries sr{scheme, {}, {}, vs::SeriesStyle::kLineAndMarkers};
      for (const TiRun& r : rows) {
        if (r.scheme != scheme || !(r.*field > 0.0)) continue;
        sr.x.push_back(std::log10(r.run.cpu_s));
        sr.y.push_back(std::log10(r.*field));
      }
      f.series.push_back(sr);
    }
    vs::write_svg(f, out_dir + "/" + file);
  };
  fig("time_integration_pole.svg", scene_name + ": pole thickness strain error vs time",
      &TiRun::e_pole);
  fig("time_integration_min.svg", scene_name + ": min thickness strain error vs time",
      &TiRun::e_thin);
  fig("time_integration_peak.svg", scene_name + ": peak load error vs time", &TiRun::e_peak);
  bool any_warn = ref.warned;
  for (const TiRun& r : rows) any_warn = any_warn || r.warned;
  // Cheapest run of each scheme meeting absolute strain-error targets.
  Table cheap;
  cheap.header = {"target |err pole eps_t|", "euler: inc mm (cpu ms)", "heun: inc mm (cpu ms)"};
  for (double tgt : {1e-2, 1e-3, 1e-4}) {
    std::vector<std::string> row{fmt::format("{:g}", tgt)};
    for (const char* scheme : {"euler", "heun"}) {
      const TiRun* best = nullptr;
      for (const TiRun& r : rows) {
        if (r.scheme == scheme && r.e_pole <= tgt && (!best || r.run.cpu_s < best->run.cpu_s))
          best = &r;
      }
      row.push_back(best ? fmt::format("{} ({})", best->dt_mm, ms(best->run.cpu_s))
                         : std::string("not reached"));
    }
    cheap.add(row);
  }
  return fmt::format(
             "### Time integration: Euler against Heun ({})\n\n"
             "`{}`{} at the bundled mesh, travel increment (`numerics.max_travel_increment_mm`) "
             "varied alone with `numerics.max_strain_increment=0.5` so that the travel grid sets "
             "the steps (contact events still split grid intervals). Reference: Heun at {} mm. "
             "Errors: pole and minimum thickness strain at the final travel (absolute) and peak "
             "load (relative); order = log(e_coarse / e_fine) / log(inc_coarse / inc_fine) "
             "between neighbouring increments.{}\n\n",
             scene_name, scene_name, cli_args(scene_ov), ref_inc,
             any_warn ? " (solver warnings were raised: check the mesh)" : "") +
         tab.markdown() + "\nCheapest increment reaching a pole thickness-strain error:\n\n" +
         cheap.markdown() +
         fmt::format(
             "\nFigures: [pole strain](02_work_precision/results/time_integration_pole.svg), "
             "[min strain](02_work_precision/results/time_integration_min.svg), [peak "
             "load](02_work_precision/results/time_integration_peak.svg).\n\n"
             "![time integration](02_work_precision/results/time_integration_pole.svg)\n\n");
}

}  // namespace

int main(int argc, char** argv) {
  const StudyArgs args =
      parse_args(argc, argv, std::string(VS_SOURCE_DIR) + "/experiments/02_work_precision/results");
  std::vector<SceneCase> cases;
  if (args.quick) {
    cases.push_back(
        {"ex1_hemispherical_stretching",
         {{"process.punch_travel_mm", "10"}, {"process.output_travels_mm", "[5.0, 10.0]"}},
         "Quick variant: example 1 to 10 mm travel."});
  } else {
    cases.push_back({"ex1_hemispherical_stretching", {}, "Bundled scene as is (30 mm travel)."});
    cases.push_back(
        {"ex2_hemispherical_deep_drawing",
         {{"process.punch_travel_mm", "38"},
          {"process.output_travels_mm", "[10.0, 20.0, 30.0, 38.0]"}},
         "Travel 38 mm (kept from the older studies, where the bundled 40 mm run stopped "
         "at 39.84 mm; it now completes, see the stability study)."});
    cases.push_back({"ex3_flat_punch_cup",
                     {{"blank.elements", "50"}},
                     "50 elements instead of the bundled 80 (80 elements are 0.67 mm long, shorter "
                     "than the 1 mm thickness: outside the thin-shell model); 40 mm travel."});
  }
  std::filesystem::create_directories(args.out_dir);
  std::cout << "Work-precision study; machine: " << machine_description() << "\n";
  Table csv;
  csv.header = {"scene",           "family",        "value",         "overrides",
                "completed",       "wall_ms",       "cpu_ms",        "steps",
                "iterations",      "cutbacks",      "peak_N",        "err_peak",
                "err_curve_l2",    "err_eps_t_abs", "err_eps_t_rel", "thinnest_r0_mm",
                "err_thinnest_mm", "err_combined",  "pareto"};
  std::string md = fmt::format(
      "Machine: {}; load average {} at the start (other processes share the cores, so wall times "
      "are inflated and noisy). Run time in the tables and plots is therefore the thread CPU time "
      "(the wall time of this single-threaded solver on an idle core); the CSV has both. Median "
      "of up to 3 repeats (one when a run takes over 0.5 s).\n\n",
      machine_description(), load_average());
  for (const SceneCase& sc : cases) {
    std::cout << sc.name << "\n";
    md += study_scene(sc, args.quick, args.out_dir, &csv);
  }
  std::cout << "time integration (ex1)\n";
  md += time_integration_study("ex1_hemispherical_stretching",
                               args.quick ? Overrides{{"process.punch_travel_mm", "10"},
                                                      {"process.output_travels_mm", "[5.0, 10.0]"}}
                                          : Overrides{},
                               args.quick, args.out_dir);
  write_text(args.out_dir + "/work_precision.csv", csv.csv());
  write_text(args.out_dir + "/summary.md", md);
  std::cout << "\n" << md << "wrote " << args.out_dir << "\n";
  return 0;
}
