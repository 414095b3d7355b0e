// The cup-height (earing) profile of a 3D run in its run folder: the report (profile, summary,
// the measured profile's summary when the scene names one), cup_profile.csv, cup_profile.svg and
// the run.json entry.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "output/cup_profile.h"
#include "output/cup_profile_summary.h"
#include "output/svg_plot.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct CupProfileReport {
  // A 3D run whose blank has a free edge: the profile is wanted (even if it cannot be made).
  bool applies = false;
  bool available = false;
  std::string reason;  // why not available
  CupProfile profile;  // the final stage's
  CupProfileSummary summary;
  bool has_measured = false;  // scene.output.measured_cup_profile given
  std::string measured_file;
  CupProfileSummary measured;
  // Largest distance from a measured ear to the nearest computed ear [deg] (NaN without both).
  double ear_offset_deg = 0.0;
};

// The angle of the rolling direction from the x axis that the profile is measured from.
double profile_rolling_direction_deg(const Scene& scene);

CupProfileReport cup_profile_report(const Scene& scene, const RunResult& result);

// "# punch_travel_mm=<t>, rolling_direction_deg=<rd>, unfolded=<quarter mirrored>", the header
// angle_from_rd_deg,cup_height_mm,x_mm,y_mm,z_mm, one row per rim node by increasing angle.
std::string cup_profile_csv(const CupProfile& profile);

// The profile as a plot line closed across 0/360 deg (the last point one turn back, the first
// one on), so that it spans the whole 0-360 axis.
PlotSeries cup_profile_series(const CupProfile& profile);

// Cup height [mm] against the angle from RD over 0-360 deg (the periodic profile closed across
// 0/360), the measured points when the scene names them, the computed ears marked.
SvgFigure cup_profile_figure(const Scene& scene, const RunResult& result,
                             const CupProfileReport& report);

// The run.json entry (written for every run, so that both geometries have the same keys):
// available / reason, travel, RD, whether a quarter was unfolded, the summary, the measured one
// and the ear offset.
nlohmann::ordered_json cup_profile_json(const CupProfileReport& report);

// Lines for the terminal summary ("" when the profile does not apply), e.g.
//   cup height        mean 34.15 mm, 33.13-35.26 mm, amplitude 2.13 mm at 40.000 mm travel
//   ears              0.2, 89.9, 180.1, 270.0 deg from RD
std::string cup_profile_report_text(const CupProfileReport& report);

}  // namespace vs
