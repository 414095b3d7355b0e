// ESAFORM 2021 cup (experiments/04_esaform_cup): the final cup height from a forward run's
// per-step history. Header-only so that the quick test (tests/system/esaform_cup_test.cc) shares
// it with the driver.
//
// Axes: the punch moves +z from below and the die sits above the sheet, so the cup bottom ends
// up highest and the wall hangs down to the rim. Definitions (see README.md):
//   full draw: the first step whose rim node (free edge of the meridian) has passed the die
//              shoulder into the die opening, r_rim <= die opening radius (the flange is gone and
//              the rim's mid-surface is inside the straight part of the opening);
//   cup height H = (z_center + h_center / 2) - z_rim, i.e. from the cup's outer bottom surface
//              (the side facing the die, away from the punch; mid-surface height plus half the
//              current bottom thickness at the axis) to the rim edge (mid-surface rim node).
// If the rim never reaches the opening, the run did not draw the cup completely: drawn = false
// and the height is that of the last step (a lower bound).
#pragma once

#include <algorithm>
#include <string>

#include "../common/harness.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vsx {

struct CupGeometry {
  double die_radius_mm = 0.0;          // die opening radius
  double die_profile_radius_mm = 0.0;  // die shoulder radius
  double thickness_mm = 0.0;           // initial sheet thickness
};

inline CupGeometry cup_geometry(const vs::Scene& scene) {
  CupGeometry g;
  g.thickness_mm = scene.blank.thickness_mm;
  for (const vs::ToolSpec& tool : scene.tools) {
    if (tool.name == "die") {
      g.die_radius_mm = tool.radius_mm;
      g.die_profile_radius_mm = tool.profile_radius_mm;
    }
  }
  return g;
}

struct CupHeight {
  bool drawn = false;                  // the rim entered the die opening
  double travel_mm = 0.0;              // punch travel where the height is taken
  double height_mm = 0.0;              // H at that step
  double rim_r_mm = 0.0;               // rim radius there
  double flange_off_travel_mm = -1.0;  // rim left the flat die face (r < die + shoulder radius)
  double height_end_mm = 0.0;          // H at the last step (stability of the measure)
  double peak_force_N = 0.0;
  double peak_force_travel_mm = 0.0;
};

inline double cup_height_of(const vs::Profile& p) {
  return p.node_z_mm.front() + 0.5 * p.thickness_mm.front() - p.node_z_mm.back();
}

inline CupHeight evaluate_cup(const vs::RunResult& result, const CupGeometry& g) {
  CupHeight out;
  for (const vs::StepRecord& s : result.steps) {
    if (s.punch_force_N > out.peak_force_N) {
      out.peak_force_N = s.punch_force_N;
      out.peak_force_travel_mm = s.punch_travel_mm;
    }
  }
  const vs::Profile* at = nullptr;
  for (const vs::Profile& p : result.history) {
    if (p.node_r_mm.empty()) continue;
    const double rim_r = p.node_r_mm.back();
    if (out.flange_off_travel_mm < 0.0 && rim_r < g.die_radius_mm + g.die_profile_radius_mm) {
      out.flange_off_travel_mm = p.punch_travel_mm;
    }
    if (!at && rim_r <= g.die_radius_mm) at = &p;
  }
  if (result.history.empty()) return out;
  out.drawn = at != nullptr;
  if (!at) at = &result.history.back();
  out.travel_mm = at->punch_travel_mm;
  out.height_mm = cup_height_of(*at);
  out.rim_r_mm = at->node_r_mm.back();
  out.height_end_mm = cup_height_of(result.history.back());
  return out;
}

// The bundled cup scene (or its fixed-gap variant) with the per-step history on and the given
// overrides. An override of material.hardening.law first clears the scene's hardening table (the
// Swift keys of the bundled scene are not accepted by a Voce law), so the overrides must then give
// every parameter.
inline vs::Scene make_cup_scene(const std::string& source_dir, const Overrides& ov,
                                const std::string& scene_name = "ex3_flat_punch_cup") {
  const std::string path = scene_path(source_dir, scene_name);
  toml::table table = vs::read_scene_table(path);
  vs::set_scene_value_from_text(table, "output.history", "true");
  vs::set_scene_value_from_text(table, "output.plots", "false");
  for (const Override& o : ov) {
    if (o.address == "material.hardening.law") {
      if (toml::table* h = table["material"]["hardening"].as_table()) h->clear();
    }
    vs::set_scene_value_from_text(table, o.address, o.value);
  }
  return vs::scene_from_table(table, path, path.substr(0, path.find_last_of('/')));
}

}  // namespace vsx
