// `vshell run` for geometry = "shell3d" scenes: streams load_travel.csv while the solver runs,
// prints the progress line, writes the run folder and prints the summary. The CLI (app/vshell.cc)
// parses arguments, loads the scene and creates the folder; this does the rest.
#pragma once

#include <iosfwd>
#include <string>

#include "scene/scene.h"

namespace vs::shell3d {

struct Shell3dCliOptions {
  std::string output_dir;  // existing folder
  bool quiet = false;      // no progress lines
  bool verbose = false;    // nonlinear iteration tables
};

// Returns true if the run reached the full punch travel.
bool run_shell3d_scene(const Scene& scene, const Shell3dCliOptions& options, std::ostream& out,
                       std::ostream& err);

}  // namespace vs::shell3d
