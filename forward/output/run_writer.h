// Writes the run folder of either geometry from a Scene and its RunResult, with the same names,
// columns and units:
//   scene.toml                                   the scene as run (scene_echo.h): every key
//                                                that applies, with its value; runs again as is
//   load_travel.csv, thinnest_point.csv          per step
//   strains_travel_<travel>mm.csv                per profile (axisymmetric: the meridian)
//   strains_travel_<travel>mm_<line>.csv         per profile of a 3D run (lines x, y, diagonal;
//                                                a full blank adds x_neg, y_neg, diagonal_neg)
//   fld_points.csv, strain_paths.csv             forming limit diagram data
//   stage_<k>.vtu, stages.pvd                    3D: ParaView series: zero travel (stage_0),
//                                                the output stages and the end
//   load_travel.svg, thickness_strain.svg, strains.svg, deformed_stages.svg, fld.svg
//                                                if scene.output.plots
//   cup_profile.csv, cup_profile.svg (if plots)  3D with a free blank edge: rim height against
//                                                the angle from RD at the end (cup_profile.h)
//   run.json                                     manifest (written last, lists all the above)
// A failed or partial result is written as far as it goes; missing profiles or history never
// throw. Only an I/O failure (folder missing, disk full) throws InputError.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct RunWriterOptions {
  // Elements whose strain paths go to strain_paths.csv and fld.svg: the finally thinnest one
  // plus evenly spaced others.
  std::size_t strain_path_elements = 6;
};

// Writes into the existing folder `directory`; returns the names written (relative to it), in
// the order written, run.json last. load_travel.csv is rewritten even if a LoadTravelStream
// produced it during the run: the bytes are the same, and the file is then complete even if a
// step callback was missed.
std::vector<std::string> write_run_folder(const Scene& scene, const RunResult& result,
                                          const std::string& directory,
                                          const RunWriterOptions& options = {});

}  // namespace vs
