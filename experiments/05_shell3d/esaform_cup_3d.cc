// The ESAFORM 2021 cup in 3D with the fixed-gap blank holder
// (data/scenes/esaform_cup_3d_quarter.toml): one full draw at the given divisions, its run time,
// steps, factorisations and the cup height around the rim, against the axisymmetric fixed-gap
// cup (data/scenes/ex3_flat_punch_cup_fixed_gap.toml). One run per call, so that long runs can be
// started one at a time (README.md, "ESAFORM cup in 3D, fixed-gap holder").
//
// Cup height (experiments/04_esaform_cup/cup_height.h, per rim node): the first output stage at
// which every rim node has passed into the die opening (r <= die radius) is the full draw; there
// H = (z_centre + h_centre / 2) - z_rim, from the cup's outer bottom surface at the axis to the
// rim node's mid-surface. Mean over the quarter rim by the trapezoid rule in the polar angle.
// Stages every 0.5 mm from 30 mm on locate the draw to half a millimetre of travel.
//
// usage: esaform_cup_3d --divisions N [--csv FILE] [--set KEY=VALUE ...]
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <string>

#include "04_esaform_cup/cup_height.h"
#include "common/harness.h"
#include "run/simulate.h"

namespace {

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

struct RimHeight {
  bool drawn = false;
  double travel_mm = 0.0;
  double mean_mm = 0.0, min_mm = 0.0, max_mm = 0.0;
  double angle_min_deg = 0.0, angle_max_deg = 0.0;  // polar angle of the lowest / highest rim node
  double rim_r_max_mm = 0.0;                        // largest rim radius there
};

RimHeight rim_height(const vs::RunResult& r, double die_radius_mm) {
  RimHeight out;
  const vs::shell3d::ShellMesh& mesh = r.shell->mesh;
  const std::vector<int>& rim = mesh.set("edge");
  int centre = -1;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    if (mesh.nodes[static_cast<std::size_t>(i)].head<2>().norm() < 1e-9) centre = i;
  }
  if (rim.empty() || centre < 0) return out;
  const vs::ShellStage* at = nullptr;
  for (const vs::ShellStage& st : r.shell->stages) {
    double rmax = 0.0;
    for (int i : rim) rmax = std::max(rmax, st.x[static_cast<std::size_t>(i)].head<2>().norm());
    if (rmax <= die_radius_mm) {
      at = &st;
      out.rim_r_max_mm = rmax;
      break;
    }
  }
  out.drawn = at != nullptr;
  if (!at) at = &r.shell->stages.back();
  out.travel_mm = at->punch_travel_mm;
  const std::size_t c = static_cast<std::size_t>(centre);
  const double top = at->x[c].z() + 0.5 * at->thickness_mm[c];
  // Rim nodes sorted by their polar angle (initial positions: the mesh is material).
  std::vector<std::pair<double, double>> by_angle;  // (angle, height)
  for (int i : rim) {
    const auto& p0 = mesh.nodes[static_cast<std::size_t>(i)];
    by_angle.emplace_back(std::atan2(p0.y(), p0.x()), top - at->x[static_cast<std::size_t>(i)].z());
  }
  std::sort(by_angle.begin(), by_angle.end());
  double integral = 0.0;
  for (std::size_t k = 0; k + 1 < by_angle.size(); ++k) {
    integral += 0.5 * (by_angle[k].second + by_angle[k + 1].second) *
                (by_angle[k + 1].first - by_angle[k].first);
  }
  out.mean_mm = integral / (by_angle.back().first - by_angle.front().first);
  out.min_mm = out.max_mm = by_angle.front().second;
  for (const auto& [angle, h] : by_angle) {
    if (h <= out.min_mm) {
      out.min_mm = h;
      out.angle_min_deg = angle * 180.0 / std::numbers::pi;
    }
    if (h >= out.max_mm) {
      out.max_mm = h;
      out.angle_max_deg = angle * 180.0 / std::numbers::pi;
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int divisions = 0;
  std::string csv;
  vsx::Overrides ov;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--divisions" && i + 1 < argc) {
      divisions = std::stoi(argv[++i]);
    } else if (a == "--csv" && i + 1 < argc) {
      csv = argv[++i];
    } else if (a == "--set" && i + 1 < argc) {
      const std::string kv = argv[++i];
      const auto eq = kv.find('=');
      if (eq == std::string::npos) {
        std::fprintf(stderr, "--set needs KEY=VALUE\n");
        return 2;
      }
      ov.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    } else {
      std::fprintf(stderr, "usage: %s --divisions N [--csv FILE] [--set KEY=VALUE ...]\n", argv[0]);
      return 2;
    }
  }
  if (divisions < 1) {
    std::fprintf(stderr, "--divisions N (N >= 1) is required\n");
    return 2;
  }
  std::string travels = "[10.0, 20.0";
  for (double t = 30.0; t <= 42.0 + 1e-9; t += 0.5) travels += fmt::format(", {:.1f}", t);
  travels += "]";
  vsx::Overrides all = {{"blank.divisions", std::to_string(divisions)},
                        {"process.output_travels_mm", travels}};
  all.insert(all.end(), ov.begin(), ov.end());
  const vs::Scene scene =
      vsx::make_scene(vsx::scene_path(VS_SOURCE_DIR, "esaform_cup_3d_quarter"), all);
  const vsx::CupGeometry g = vsx::cup_geometry(scene);
  const std::string load_before = load_average();
  const vs::RunResult r = vs::simulate(scene);
  const std::string load_after = load_average();
  const RimHeight h = rim_height(r, g.die_radius_mm);
  // The axisymmetric reference: the bundled fixed-gap cup (cup_height.h's definition).
  const vs::Scene axi_scene =
      vsx::make_cup_scene(VS_SOURCE_DIR, {}, "ex3_flat_punch_cup_fixed_gap");
  const vs::RunResult axi = vs::simulate(axi_scene);
  const vsx::CupHeight ah = vsx::evaluate_cup(axi, vsx::cup_geometry(axi_scene));
  double peak = 0.0, peak_at = 0.0;
  for (const vs::StepRecord& s : r.steps) {
    if (s.punch_force_N > peak) {
      peak = s.punch_force_N;
      peak_at = s.punch_travel_mm;
    }
  }
  const std::string header =
      "divisions,elements,unknowns,completed,wall_s,steps,factorisations,iterations,drawn,"
      "draw_travel_mm,mean_height_mm,min_height_mm,max_height_mm,angle_min_deg,angle_max_deg,"
      "axisym_height_mm,axisym_draw_travel_mm,peak_force_kN,peak_travel_mm,load_before,load_after,"
      "overrides";
  const std::string row = fmt::format(
      "{},{},{},{},{:.1f},{},{},{},{},{:.1f},{:.3f},{:.3f},{:.3f},{:.1f},{:.1f},{:.3f},{:.2f},{:."
      "2f},"
      "{:.2f},{},{},{}",
      divisions, r.shell->mesh.num_elements(), r.dofs, r.completed() ? "yes" : "no",
      r.timings.total_s, r.steps.size(), r.timings.factorisations, r.total_iterations,
      h.drawn ? "yes" : "no", h.travel_mm, h.mean_mm, h.min_mm, h.max_mm, h.angle_min_deg,
      h.angle_max_deg, ah.height_mm, ah.travel_mm, peak / 1000.0, peak_at, load_before, load_after,
      vsx::describe(ov));
  std::printf("%s\n%s\n", header.c_str(), row.c_str());
  if (!r.completed()) std::printf("stopped: %s\n", r.message.c_str());
  if (!csv.empty()) {
    const bool fresh = !std::ifstream(csv).good();
    std::ofstream f(csv, std::ios::app);
    if (fresh) f << header << "\n";
    f << row << "\n";
  }
  return 0;
}
