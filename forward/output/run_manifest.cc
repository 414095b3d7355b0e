#include "output/run_manifest.h"

#include "linalg/blas_library.h"
#include "output/build_info.h"
#include "output/run_summary.h"
#include "output/scene_json.h"
#include "output/suspect_results.h"

namespace vs {

nlohmann::ordered_json run_manifest(const Scene& scene, const RunResult& result,
                                    const std::vector<std::string>& files) {
  const RunSummary s = summarize_run(scene, result);
  nlohmann::ordered_json j;
  j["program"] = {{"name", "vshell"},
                  {"version", program_version()},
                  {"git_describe", program_git_describe()},
                  {"compiler", compiler_version()},
                  {"instruction_set", instruction_set()},
                  {"eigen_version", eigen_version()},
                  {"blas_library", blas_library()}};
  j["geometry"] = result.geometry == Geometry::kShell3d ? "shell3d" : "axisymmetric";
  j["built"] = result.built;
  j["dofs"] = result.dofs;
  j["termination"] = s.termination;
  j["message"] = s.message;
  j["warnings"] = s.warnings;
  j["steps"] = s.steps;
  j["total_iterations"] = s.total_iterations;
  j["total_cutbacks"] = s.total_cutbacks;
  j["friction_fallbacks"] = s.friction_fallbacks;
  j["timings"] = {{"total_s", result.timings.total_s},
                  {"assembly_s", result.timings.assembly_s},
                  {"linear_solve_s", result.timings.linear_solve_s},
                  {"contact_s", result.timings.contact_s},
                  {"factorisations", result.timings.factorisations},
                  {"krylov_steps", result.timings.krylov_steps},
                  {"krylov_iterations", result.timings.krylov_iterations},
                  {"factorisation_fallbacks", result.timings.factorisation_fallbacks}};
  // NaN (no step at all) becomes null in JSON.
  j["final_punch_travel_mm"] = s.final_punch_travel_mm;
  j["peak_punch_force_N"] = s.peak_punch_force_N;
  j["punch_travel_at_peak_mm"] = s.punch_travel_at_peak_mm;
  j["final_min_thickness_mm"] = s.final_min_thickness_mm;
  j["final_thinning_percent"] = s.final_thinning_percent;
  j["final_thinnest_r0_mm"] = s.final_thinnest_r0_mm;
  j["final_thinnest_x0_mm"] = s.final_thinnest_x0_mm;
  j["final_thinnest_y0_mm"] = s.final_thinnest_y0_mm;
  j["forming_limit"] = {{"curve", s.flc_description},
                        {"smallest_margin", s.flc_min_margin},
                        {"zone", s.flc_min_zone},
                        {"element", s.flc_min_element},
                        {"x0_mm", s.flc_min_x0_mm},
                        {"y0_mm", s.flc_min_y0_mm},
                        {"r0_mm", s.flc_min_r0_mm},
                        {"eps_major", s.flc_min_eps_major},
                        {"eps_minor", s.flc_min_eps_minor},
                        {"failed_elements", s.flc_failed_elements},
                        {"marginal_elements", s.flc_marginal_elements},
                        {"elements", s.flc_elements}};
  const LoadCurveNoise noise = load_curve_noise(result.steps);
  j["load_curve"] = {{"force_increments", noise.increments},
                     {"slope_reversals", noise.reversals},
                     {"rms_second_difference_of_peak", noise.rms_second_difference},
                     {"noise_like", noise.noise_like}};
  j["cup_profile"] = cup_profile_json(s.cup_profile);
  j["profiles"] = result.profiles.size();
  j["history_entries"] = result.history.size();
  j["scene"] = scene_to_json(scene);
  j["files"] = files;
  return j;
}

}  // namespace vs
