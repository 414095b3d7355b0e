#include "output/run_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "output/cup_profile_output.h"
#include "output/fld.h"
#include "output/profile_csv.h"
#include "output/run_manifest.h"
#include "output/run_plots.h"
#include "output/shell_stage_vtu.h"
#include "output/step_csv.h"
#include "output/svg_plot.h"
#include "output/text_file.h"
#include "output/vtu_writer.h"
#include "scene/scene_echo.h"

namespace vs {
namespace {

class FolderWriter {
 public:
  explicit FolderWriter(const std::string& directory) : directory_(directory) {}

  void text(const std::string& name, const std::string& content) {
    write_text_file(path(name), content);
    written_.push_back(name);
  }

  void svg(const std::string& name, const SvgFigure& figure) {
    write_svg(figure, path(name));
    written_.push_back(name);
  }

  bool has(const std::string& name) const {
    return std::find(written_.begin(), written_.end(), name) != written_.end();
  }

  const std::vector<std::string>& written() const { return written_; }

 private:
  std::string path(const std::string& name) const {
    return (std::filesystem::path(directory_) / name).string();
  }

  std::string directory_;
  std::vector<std::string> written_;
};

// Two travels that round to the same two decimals get "_2", "_3"... rather than overwrite.
std::string unique_strains_name(const FolderWriter& out, const Profile& p) {
  const std::string base = strains_file_name(p.punch_travel_mm, p.line);
  std::string name = base;
  for (int k = 2; out.has(name); ++k) {
    name = base.substr(0, base.size() - 4) + fmt::format("_{}.csv", k);
  }
  return name;
}

// The scene with the values the run chose itself (numerics.implicit_solves by the model's size),
// so that scene.toml and run.json hold the scene as run.
Scene scene_as_run(const Scene& scene, const RunResult& result) {
  Scene as_run = scene;
  if (result.implicit_solves > 0) as_run.numerics.implicit_solves = result.implicit_solves;
  return as_run;
}

}  // namespace

std::vector<std::string> write_run_folder(const Scene& scene, const RunResult& result,
                                          const std::string& directory,
                                          const RunWriterOptions& options) {
  FolderWriter out(directory);
  const Scene as_run = scene_as_run(scene, result);
  out.text("scene.toml", scene_toml(as_run));
  out.text("load_travel.csv", load_travel_csv(result.steps));
  out.text("thinnest_point.csv", thinnest_point_csv(result.steps, scene.blank.thickness_mm));
  const FormingLimitCurve flc = forming_limit_curve(scene);
  for (const Profile* p : profile_stages(result)) {
    out.text(unique_strains_name(out, *p), profile_csv(*p));
  }
  if (result.shell) {
    // ParaView series: each output stage once (the final state often repeats the last one).
    // stage_0 is the state at zero travel when the run reached it.
    const ShellFields& shell = *result.shell;
    std::vector<const ShellStage*> stages;
    if (!shell.initial.x.empty()) stages.push_back(&shell.initial);
    for (const ShellStage& st : shell.stages) stages.push_back(&st);
    std::vector<PvdEntry> series;
    for (std::size_t k = 0; k < stages.size(); ++k) {
      const ShellStage& st = *stages[k];
      if (k > 0 && st.punch_travel_mm == stages[k - 1]->punch_travel_mm) continue;
      const std::string vtu = fmt::format("stage_{}.vtu", series.size());
      out.text(vtu, stage_vtu(shell.mesh, st, scene.blank.thickness_mm, flc));
      series.push_back({st.punch_travel_mm, vtu});
    }
    out.text("stages.pvd", render_pvd(series));
  }

  const Profile* state = final_state(result);
  std::vector<FldPoint> points = fld_points(result);
  apply_forming_limit(flc, &points);
  out.text("fld_points.csv", fld_points_csv(points));
  std::vector<StrainPath> paths;
  if (state != nullptr && !result.history.empty()) {
    paths = strain_paths(result, strain_path_elements(*state, options.strain_path_elements));
  }
  out.text("strain_paths.csv", strain_paths_csv(paths));

  const CupProfileReport cup = cup_profile_report(scene, result);
  if (cup.available) out.text("cup_profile.csv", cup_profile_csv(cup.profile));

  if (scene.output.plots) {
    out.svg("load_travel.svg", load_travel_figure(scene, result));
    out.svg("thickness_strain.svg", thickness_strain_figure(scene, result));
    out.svg("strains.svg", strains_figure(scene, result));
    out.svg("deformed_stages.svg", deformed_stages_figure(scene, result));
    out.svg("fld.svg", fld_figure(scene, result, paths, flc));
    if (cup.available) out.svg("cup_profile.svg", cup_profile_figure(scene, result, cup));
  }

  std::vector<std::string> files = out.written();
  files.push_back("run.json");
  // Invalid UTF-8 in a title must not cost the manifest: replace it instead of throwing.
  const std::string manifest = run_manifest(as_run, result, files)
                                   .dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  out.text("run.json", manifest + '\n');
  return out.written();
}

}  // namespace vs
