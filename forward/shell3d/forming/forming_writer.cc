#include "shell3d/forming/forming_writer.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "output/number_format.h"
#include "output/step_csv.h"
#include "output/svg_plot.h"
#include "output/text_file.h"
#include "output/vtu_writer.h"
#include "shell3d/forming/forming_fields.h"

namespace vs::shell3d {

namespace {

// Profile lines from the centre (node sets of forming_mesh.h): the halves x, y >= 0 always, the
// other halves when the mesh is a full blank.
std::vector<std::string> profile_lines(const ShellMesh& mesh) {
  std::vector<std::string> lines;
  for (const char* line : {"y0", "x0", "diagonal"}) {
    lines.emplace_back(line);
    const std::string other = std::string(line) + "_neg";
    if (mesh.node_sets.count(other) != 0) lines.push_back(other);
  }
  return lines;
}

// Thickness strain along y = 0 against the initial x: the half x >= 0 of a quarter blank, the
// whole line through the centre of a full blank (the half x <= 0 at negative x).
PlotSeries y0_series(const ShellMesh& mesh, const ShellStage& st, double h0) {
  PlotSeries s;
  if (mesh.node_sets.count("y0_neg") != 0) {
    const LineProfile neg = line_profile(mesh, st, "y0_neg", h0);
    for (std::size_t i = neg.nodes.size(); i-- > 1;) {  // the centre comes with the x >= 0 half
      s.x.push_back(-neg.r0_mm[i]);
      s.y.push_back(neg.eps_thickness[i]);
    }
  }
  const LineProfile pos = line_profile(mesh, st, "y0", h0);
  s.x.insert(s.x.end(), pos.r0_mm.begin(), pos.r0_mm.end());
  s.y.insert(s.y.end(), pos.eps_thickness.begin(), pos.eps_thickness.end());
  return s;
}

std::string title(const Scene& scene, const Shell3dResult& result, const std::string& what) {
  std::string t = scene.title.empty() ? what : scene.title + ": " + what;
  if (!result.completed()) t += " (run failed)";
  return t;
}

SvgFigure load_travel_figure(const Scene& scene, const Shell3dResult& result) {
  SvgFigure f;
  f.title = title(scene, result, "punch force");
  f.x_label = "punch travel [mm]";
  f.y_label = "punch force [kN]";
  PlotSeries s;
  s.label = "3D shell (whole blank)";
  for (const StepRecord& r : result.steps) {
    s.x.push_back(r.punch_travel_mm);
    s.y.push_back(1e-3 * r.punch_force_N);
  }
  f.series.push_back(std::move(s));
  return f;
}

SvgFigure thickness_figure(const Scene& scene, const Shell3dResult& result) {
  SvgFigure f;
  const bool full = scene.blank.symmetry == BlankSymmetry::kFull;
  f.title = title(scene, result,
                  full ? "thickness strain along the line y = 0"
                       : "thickness strain along the symmetry line y = 0");
  f.x_label = "initial x on y = 0 [mm]";
  f.y_label = "thickness strain [-]";
  for (std::size_t k = 0; k < result.stages.size(); ++k) {
    const ShellStage& st = result.stages[k];
    if (k > 0 && st.punch_travel_mm == result.stages[k - 1].punch_travel_mm) continue;
    PlotSeries s = y0_series(result.mesh, st, scene.blank.thickness_mm);
    s.label = fmt::format("travel {:.2f} mm", st.punch_travel_mm);
    s.style = SeriesStyle::kLineAndMarkers;
    f.series.push_back(std::move(s));
  }
  return f;
}

SvgFigure fld_figure(const Scene& scene, const Shell3dResult& result) {
  SvgFigure f;
  f.title = title(scene, result, "forming limit diagram (element centres)");
  f.x_label = "minor true strain [-]";
  f.y_label = "major true strain [-]";
  PlotSeries s;
  s.label = "elements, final state";
  s.style = SeriesStyle::kMarkers;
  if (!result.stages.empty()) {
    const ElementStrains e = element_strains(result.mesh, result.stages.back());
    s.x = e.minor;
    s.y = e.major;
  }
  f.series.push_back(std::move(s));
  return f;
}

std::string fld_csv(const ShellMesh& mesh, const ShellStage* stage) {
  std::string out = "element,r0_mm,eps_major,eps_minor,eps_thickness,eps_effective\n";
  if (stage == nullptr) return out;
  const ElementStrains e = element_strains(mesh, *stage);
  for (std::size_t i = 0; i < e.major.size(); ++i) {
    out += fmt::format("{},{},{},{},{},{}\n", i, format_number(e.r0_mm[i]),
                       format_number(e.major[i]), format_number(e.minor[i]),
                       format_number(e.thickness[i]), format_number(e.effective[i]));
  }
  return out;
}

std::string travel_name(const std::string& stem, double travel, const std::string& ext) {
  return fmt::format("{}_travel_{:.2f}mm.{}", stem, travel, ext);
}

}  // namespace

std::string profiles_csv(const ShellMesh& mesh, const ShellStage& stage,
                         double initial_thickness_mm) {
  std::string out = "line,node,r0_mm,r_mm,z_mm,thickness_mm,eps_thickness,contact_tool\n";
  for (const std::string& line : profile_lines(mesh)) {
    const LineProfile p = line_profile(mesh, stage, line, initial_thickness_mm);
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
      out += fmt::format("{},{},{},{},{},{},{},{}\n", line, p.nodes[i], format_number(p.r0_mm[i]),
                         format_number(p.r_mm[i]), format_number(p.z_mm[i]),
                         format_number(p.thickness_mm[i]), format_number(p.eps_thickness[i]),
                         p.contact_tool[i]);
    }
  }
  return out;
}

std::string stage_vtu(const ShellMesh& mesh, const ShellStage& stage, double initial_thickness_mm) {
  VtuGrid grid;
  const std::size_t nn = stage.x.size();
  for (const Eigen::Vector3d& x : stage.x) {
    grid.points.insert(grid.points.end(), {x.x(), x.y(), x.z()});
  }
  for (const auto& el : mesh.elements) {
    for (int a : el) grid.connectivity.push_back(a);
    grid.offsets.push_back(static_cast<std::int64_t>(grid.connectivity.size()));
    grid.types.push_back(kVtkBiquadraticQuad);  // same node order as lagrange9.h
  }
  VtuField thickness{"thickness_mm", 1, stage.thickness_mm};
  VtuField eps_t{"eps_thickness", 1, {}};
  VtuField contact{"contact_tool", 1, {}};
  VtuField disp{"displacement_mm", 3, {}};
  for (std::size_t i = 0; i < nn; ++i) {
    eps_t.values.push_back(std::log(stage.thickness_mm[i] / initial_thickness_mm));
    contact.values.push_back(stage.contact_tool[i] + 1.0);  // 0 free, k = tool k-1
    const Eigen::Vector3d d = stage.x[i] - mesh.nodes[i];
    disp.values.insert(disp.values.end(), {d.x(), d.y(), d.z()});
  }
  const ElementStrains e = element_strains(mesh, stage);
  return render_vtu(grid, {thickness, eps_t, contact, disp},
                    {VtuField{"eps_major", 1, e.major}, VtuField{"eps_minor", 1, e.minor},
                     VtuField{"eps_thickness_membrane", 1, e.thickness},
                     VtuField{"eps_effective", 1, e.effective}});
}

void write_shell3d_run_folder(const Scene& scene, const Shell3dResult& result,
                              const std::string& dir) {
  namespace fs = std::filesystem;
  auto path = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
  const double h0 = scene.blank.thickness_mm;
  write_text_file(path("load_travel.csv"), load_travel_csv(result.steps));
  std::vector<PvdEntry> series;
  for (std::size_t k = 0; k < result.stages.size(); ++k) {
    const ShellStage& st = result.stages[k];
    // The final state often repeats the last output travel: write it once.
    if (k > 0 && st.punch_travel_mm == result.stages[k - 1].punch_travel_mm) continue;
    write_text_file(path(travel_name("profiles", st.punch_travel_mm, "csv")),
                    profiles_csv(result.mesh, st, h0));
    const std::string vtu = fmt::format("stage_{}.vtu", series.size());
    write_text_file(path(vtu), stage_vtu(result.mesh, st, h0));
    series.push_back({st.punch_travel_mm, vtu});
  }
  write_text_file(path("stages.pvd"), render_pvd(series));
  write_text_file(path("fld_points.csv"),
                  fld_csv(result.mesh, result.stages.empty() ? nullptr : &result.stages.back()));
  if (scene.output.plots) {
    write_svg(load_travel_figure(scene, result), path("load_travel.svg"));
    write_svg(thickness_figure(scene, result), path("thickness_strain.svg"));
    write_svg(fld_figure(scene, result), path("fld.svg"));
  }
}

}  // namespace vs::shell3d
