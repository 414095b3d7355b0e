// run.json: what was run (resolved scene, program, compiler, Eigen), how it ended (termination,
// message, steps, iterations, cut-backs, timings), the headline results (peak punch force, final
// thinning) and the files of the run folder.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// `files`: names (relative to the run folder) of the files written for this run.
nlohmann::ordered_json run_manifest(const Scene& scene, const RunResult& result,
                                    const std::vector<std::string>& files);

}  // namespace vs
