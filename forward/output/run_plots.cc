#include "output/run_plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "output/profile_csv.h"

namespace vs {
namespace {

// "<scene title>: <what>", and a note when the run stopped early so a partial figure is not
// mistaken for a complete one.
std::string figure_title(const Scene& scene, const RunResult& result, const std::string& what) {
  std::string title = scene.title.empty() ? what : scene.title + ": " + what;
  if (!result.completed()) title += " (run failed)";
  return title;
}

std::string travel_label(double punch_travel_mm) {
  return fmt::format("travel {:.2f} mm", punch_travel_mm);
}

PlotSeries line(const std::string& label, const std::vector<double>& x,
                const std::vector<double>& y) {
  PlotSeries s;
  s.label = label;
  s.x = x;
  s.y = y;
  return s;
}

}  // namespace

SvgFigure load_travel_figure(const Scene& scene, const RunResult& result) {
  SvgFigure f;
  f.title = figure_title(scene, result, "punch force");
  f.x_label = "punch travel [mm]";
  f.y_label = "punch force [kN]";
  PlotSeries s;
  for (const StepRecord& r : result.steps) {
    s.x.push_back(r.punch_travel_mm);
    s.y.push_back(r.punch_force_N / 1000.0);
  }
  // Few steps are easier to read with their points marked.
  s.style = s.x.size() <= 30 ? SeriesStyle::kLineAndMarkers : SeriesStyle::kLine;
  f.series.push_back(std::move(s));
  return f;
}

SvgFigure thickness_strain_figure(const Scene& scene, const RunResult& result) {
  SvgFigure f;
  const std::string line_name = primary_line(result);
  const bool meridian = line_name == "meridian";
  f.title = figure_title(scene, result,
                         meridian ? "thickness strain" : "thickness strain along the x axis");
  f.x_label = meridian ? "initial radius r0 [mm]" : "initial distance from the centre [mm]";
  f.y_label = "thickness strain ln(h/h0) [-]";
  for (const Profile* p : profile_stages(result, line_name)) {
    f.series.push_back(line(travel_label(p->punch_travel_mm), p->r0_mm, p->eps_thickness));
  }
  return f;
}

SvgFigure strains_figure(const Scene& scene, const RunResult& result) {
  SvgFigure f;
  const Profile* p = final_state(result);
  const std::string at = p == nullptr ? std::string() : ", " + travel_label(p->punch_travel_mm);
  f.title = figure_title(scene, result, "strains" + at);
  f.x_label = "initial radius r0 [mm]";
  f.y_label = "true strain [-]";
  if (p != nullptr) {
    f.series.push_back(line("meridional", p->r0_mm, p->eps_meridional));
    f.series.push_back(line("circumferential", p->r0_mm, p->eps_circumferential));
    f.series.push_back(line("thickness", p->r0_mm, p->eps_thickness));
  }
  return f;
}

SvgFigure deformed_stages_figure(const Scene& scene, const RunResult& result) {
  SvgFigure f;
  const std::string line_name = primary_line(result);
  f.title = figure_title(
      scene, result,
      line_name == "meridian" ? "deformed meridian" : "deformed section along the x axis");
  f.x_label = "radius r [mm]";
  f.y_label = "height z [mm]";
  f.equal_aspect = true;
  for (const Profile* p : profile_stages(result, line_name)) {
    f.series.push_back(line(travel_label(p->punch_travel_mm), p->node_r_mm, p->node_z_mm));
  }
  return f;
}

SvgFigure fld_figure(const Scene& scene, const RunResult& result,
                     const std::vector<StrainPath>& paths, const FormingLimitCurve& flc) {
  SvgFigure f;
  f.title = figure_title(scene, result, "forming limit diagram");
  f.x_label = "minor true strain [-]";
  f.y_label = "major true strain [-]";
  PlotSeries final_points;
  final_points.label = "elements, final state";
  final_points.style = SeriesStyle::kMarkers;
  final_points.colour = 6;  // black: the paths take the coloured entries
  for (const FldPoint& p : fld_points(result)) {
    final_points.x.push_back(p.eps_minor);
    final_points.y.push_back(p.eps_major);
  }
  f.series.push_back(std::move(final_points));
  if (flc.defined()) {
    // The curve over the minor strains of the plot, with a quarter of their span to each side
    // (at least 0.2 in all) so that the branches around plane strain show.
    double lo = 0.0, hi = 0.0;
    for (const PlotSeries& s : f.series) {
      for (double x : s.x) {
        if (std::isfinite(x)) {
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
      }
    }
    for (const StrainPath& path : paths) {
      for (double x : path.eps_minor) {
        if (std::isfinite(x)) {
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
      }
    }
    const double pad = 0.25 * std::max(hi - lo, 0.2);
    const FlcPolyline curve = flc_polyline(flc, lo - pad, hi + pad, 0.0);
    PlotSeries s = line(
        flc.model == FormingLimitModel::kKeelerBrazier ? "FLC (Keeler-Brazier)" : "FLC (table)",
        curve.minor, curve.major);
    s.colour = 6;
    s.line_width_px = 2.0;
    f.series.push_back(std::move(s));
    if (flc.safety_margin > 0.0) {
      const FlcPolyline band = flc_polyline(flc, lo - pad, hi + pad, flc.safety_margin);
      PlotSeries m = line(fmt::format("FLC - {:.3g} (safety margin)", flc.safety_margin),
                          band.minor, band.major);
      m.colour = 6;
      m.dashed = true;
      f.series.push_back(std::move(m));
    }
  }
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const StrainPath& path = paths[k];
    PlotSeries s;
    s.label = fmt::format("element {} (r0 {:.1f} mm)", path.element, path.r0_mm);
    s.x = path.eps_minor;
    s.y = path.eps_major;
    s.colour = static_cast<int>(k % 6);  // skip black (final points) and faint yellow
    s.dashed = k >= 6;
    f.series.push_back(std::move(s));
  }
  return f;
}

}  // namespace vs
