#include "output/cup_profile_output.h"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <limits>

#include "output/number_format.h"

namespace vs {

namespace {

nlohmann::ordered_json summary_json(const CupProfileSummary& s) {
  auto extrema = [](const std::vector<ProfileExtremum>& list) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const ProfileExtremum& e : list) {
      a.push_back({{"angle_from_rd_deg", e.angle_deg}, {"height_mm", e.height_mm}});
    }
    return a;
  };
  nlohmann::ordered_json j;
  j["points"] = s.points;
  j["mean_height_mm"] = s.mean_height_mm;
  j["min_height_mm"] = s.min_height_mm;
  j["max_height_mm"] = s.max_height_mm;
  j["amplitude_mm"] = s.amplitude_mm;
  j["ears"] = extrema(s.ears);
  j["valleys"] = extrema(s.valleys);
  return j;
}

std::string angles_text(const std::vector<ProfileExtremum>& list) {
  if (list.empty()) return "none";
  std::string s;
  for (const ProfileExtremum& e : list)
    s += fmt::format("{}{:.1f}", s.empty() ? "" : ", ", e.angle_deg);
  return s + " deg from RD";
}

std::string summary_text(const CupProfileSummary& s) {
  return fmt::format("mean {:.3f} mm, {:.3f}-{:.3f} mm, amplitude {:.3f} mm", s.mean_height_mm,
                     s.min_height_mm, s.max_height_mm, s.amplitude_mm);
}

}  // namespace

double profile_rolling_direction_deg(const Scene& scene) {
  return scene.material.anisotropy.rolling_direction_deg;
}

PlotSeries cup_profile_series(const CupProfile& p) {
  PlotSeries line;
  if (p.angle_from_rd_deg.empty()) return line;
  line.x.push_back(p.angle_from_rd_deg.back() - 360.0);
  line.y.push_back(p.height_mm.back());
  line.x.insert(line.x.end(), p.angle_from_rd_deg.begin(), p.angle_from_rd_deg.end());
  line.y.insert(line.y.end(), p.height_mm.begin(), p.height_mm.end());
  line.x.push_back(p.angle_from_rd_deg.front() + 360.0);
  line.y.push_back(p.height_mm.front());
  return line;
}

CupProfileReport cup_profile_report(const Scene& scene, const RunResult& result) {
  CupProfileReport r;
  r.ear_offset_deg = std::numeric_limits<double>::quiet_NaN();
  r.applies = result.geometry == Geometry::kShell3d && scene.blank.edge == EdgeCondition::kFree;
  if (!r.applies) {
    r.reason = result.geometry == Geometry::kShell3d ? "the blank edge is not free"
                                                     : "an axisymmetric run has no earing profile";
    return r;
  }
  r.has_measured = !scene.output.measured_cup_profile.empty();
  if (r.has_measured) {
    r.measured_file = scene.output.measured_cup_profile;
    r.measured = summarize_cup_profile(scene.output.measured_cup_angle_deg,
                                       scene.output.measured_cup_height_mm);
  }
  if (!result.shell || result.shell->stages.empty()) {
    r.reason = "the run has no 3D stage";
    return r;
  }
  const CupProfileResult p = rim_cup_profile(scene, *result.shell, result.shell->stages.back(),
                                             profile_rolling_direction_deg(scene));
  r.available = p.available;
  r.reason = p.reason;
  if (!p.available) return r;
  r.profile = p.profile;
  r.summary = summarize_cup_profile(r.profile.angle_from_rd_deg, r.profile.height_mm);
  if (r.has_measured) r.ear_offset_deg = max_extremum_offset_deg(r.summary.ears, r.measured.ears);
  return r;
}

std::string cup_profile_csv(const CupProfile& p) {
  std::string out = fmt::format("# punch_travel_mm={}, rolling_direction_deg={}, unfolded={}\n",
                                format_number(p.punch_travel_mm),
                                format_number(p.rolling_direction_deg), p.unfolded ? 1 : 0);
  out += "angle_from_rd_deg,cup_height_mm,x_mm,y_mm,z_mm\n";
  for (std::size_t i = 0; i < p.angle_from_rd_deg.size(); ++i) {
    const Eigen::Vector3d& x = p.x_mm[i];
    out += fmt::format("{},{},{},{},{}\n", format_number(p.angle_from_rd_deg[i]),
                       format_number(p.height_mm[i]), format_number(x.x()), format_number(x.y()),
                       format_number(x.z()));
  }
  return out;
}

SvgFigure cup_profile_figure(const Scene& scene, const RunResult& result,
                             const CupProfileReport& report) {
  SvgFigure f;
  std::string what = "cup height around the rim";
  if (report.available) what += fmt::format(" at {:.2f} mm travel", report.profile.punch_travel_mm);
  f.title = scene.title.empty() ? what : scene.title + ": " + what;
  if (!result.completed()) f.title += " (run failed)";
  f.x_label = "angle from the rolling direction [deg]";
  f.y_label = "cup height [mm]";
  f.x_range = AxisRange{0.0, 360.0};
  if (report.available && !report.profile.angle_from_rd_deg.empty()) {
    const CupProfile& p = report.profile;
    PlotSeries line = cup_profile_series(p);
    line.label = "computed";
    line.colour = 0;
    line.style =
        p.angle_from_rd_deg.size() <= 120 ? SeriesStyle::kLineAndMarkers : SeriesStyle::kLine;
    f.series.push_back(std::move(line));
    PlotSeries ears;
    ears.label = "computed ears";
    ears.colour = 0;
    ears.style = SeriesStyle::kMarkers;
    ears.marker_radius_px = 5.0;
    for (const ProfileExtremum& e : report.summary.ears) {
      ears.x.push_back(e.angle_deg);
      ears.y.push_back(e.height_mm);
    }
    if (!ears.x.empty()) f.series.push_back(std::move(ears));
  }
  if (report.has_measured) {
    PlotSeries m;
    m.label = "measured";
    m.colour = 1;
    m.style = SeriesStyle::kMarkers;
    m.marker_radius_px = 3.5;
    m.x = scene.output.measured_cup_angle_deg;
    m.y = scene.output.measured_cup_height_mm;
    f.series.push_back(std::move(m));
  }
  return f;
}

nlohmann::ordered_json cup_profile_json(const CupProfileReport& r) {
  nlohmann::ordered_json j;
  j["available"] = r.available;
  if (!r.available) j["reason"] = r.reason;
  if (r.available) {
    j["punch_travel_mm"] = r.profile.punch_travel_mm;
    j["rolling_direction_deg"] = r.profile.rolling_direction_deg;
    j["unfolded_quarter"] = r.profile.unfolded;
    j["computed"] = summary_json(r.summary);
  }
  if (r.has_measured) {
    j["measured_file"] = r.measured_file;
    j["measured"] = summary_json(r.measured);
    j["ear_offset_deg"] = r.ear_offset_deg;  // NaN -> null
  }
  return j;
}

std::string cup_profile_report_text(const CupProfileReport& r) {
  if (!r.applies) return "";
  if (!r.available) return fmt::format("cup height        not computed: {}", r.reason);
  std::string out = fmt::format("cup height        {} at {:.3f} mm travel ({} rim points{})",
                                summary_text(r.summary), r.profile.punch_travel_mm,
                                r.summary.points, r.profile.unfolded ? ", quarter unfolded" : "");
  out += fmt::format("\nears              {}", angles_text(r.summary.ears));
  if (r.has_measured) {
    out += fmt::format("\nmeasured height   {}; ears {}", summary_text(r.measured),
                       angles_text(r.measured.ears));
    if (std::isfinite(r.ear_offset_deg)) {
      out += fmt::format(
          "\near offset        {:.1f} deg (measured ear to nearest computed ear, "
          "largest)",
          r.ear_offset_deg);
    }
  }
  return out;
}

}  // namespace vs
