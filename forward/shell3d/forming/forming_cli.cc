#include "shell3d/forming/forming_cli.h"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>

#include "output/load_travel_stream.h"
#include "output/progress.h"
#include "output/run_summary.h"
#include "shell3d/forming/forming_driver.h"
#include "shell3d/forming/forming_writer.h"

namespace vs::shell3d {

bool run_shell3d_scene(const Scene& scene, const Shell3dCliOptions& options, std::ostream& out,
                       std::ostream& err) {
  const std::string& dir = options.output_dir;
  LoadTravelStream stream((std::filesystem::path(dir) / "load_travel.csv").string());
  ProgressPrinter::Options progress_options;
  progress_options.total_travel_mm = scene.process.punch_travel_mm;
  progress_options.quiet = options.quiet;
  ProgressPrinter progress(progress_options, err);
  Shell3dRunOptions run_options;
  run_options.verbose = options.verbose;
  run_options.on_step = [&](const StepRecord& record) {
    stream.append(record);
    progress.update(record);
  };
  const Shell3dResult result = simulate_shell3d(scene, run_options);
  progress.finish();
  write_shell3d_run_folder(scene, result, dir);
  for (const std::string& w : result.warnings) err << "warning: " << w << '\n';
  // The axisymmetric summary applies to the step records unchanged.
  RunResult summary_input;
  summary_input.steps = result.steps;
  summary_input.termination = result.termination;
  summary_input.message = result.message;
  summary_input.total_iterations = result.total_iterations;
  summary_input.total_cutbacks = result.total_cutbacks;
  summary_input.timings.total_s = result.timings.total_s;
  const Shell3dTimings& t = result.timings;
  out << summary_report(summarize_run(summary_input)) << '\n'
      << fmt::format("model             3D shell, {} elements, {} dofs ({} blank)\n",
                     result.mesh.num_elements(), result.dofs,
                     scene.blank.symmetry == BlankSymmetry::kFull ? "full" : "quarter")
      << fmt::format(
             "time split        assembly {:.2f} s, factorisation {:.2f} s ({}), contact "
             "{:.2f} s of {:.2f} s\n",
             t.assembly_s, t.factorisation_s, t.factorisations, t.contact_s, t.total_s)
      << fmt::format("output folder     {}\n", dir);
  return result.completed();
}

}  // namespace vs::shell3d
