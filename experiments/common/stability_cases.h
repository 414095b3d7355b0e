// The stiff and extreme cases of issue 5, as overrides of the bundled scenes. Header-only.
#pragma once

#include <string>
#include <vector>

#include "stability.h"

namespace vsx {

// Example 1 with friction 0.04 is the base; `quick` keeps a representative subset and shortens
// the travel to 5 mm.
inline std::vector<StabilityCase> stability_cases(const std::string& source_dir, bool quick) {
  const std::string ex1 = "ex1_hemispherical_stretching";
  const Overrides short_run{{"process.punch_travel_mm", "5"},
                            {"process.output_travels_mm", "[5.0]"}};
  const vs::Scene ex1_scene =
      make_scene(scene_path(source_dir, ex1), quick ? short_run : Overrides{});
  std::vector<StabilityCase> c;
  auto add = [&](const std::string& group, const std::string& name, Overrides ov,
                 const std::string& scene) {
    c.push_back({group, name, scene, std::move(ov)});
  };
  auto add1 = [&](const std::string& group, const std::string& name, Overrides ov) {
    add(group, name, std::move(ov), ex1);
  };
  add1("base", "ex1 bundled (friction 0.04)", {});
  add1("friction", "punch friction 0.5", {{"tool.punch.friction", "0.5"}});
  add1("friction", "punch friction 1.0", {{"tool.punch.friction", "1.0"}});
  add1("friction", "punch sticking", {{"tool.punch.friction", "sticking"}});
  if (!quick) {
    add1("friction", "punch and die sticking",
         {{"tool.punch.friction", "sticking"}, {"tool.die.friction", "sticking"}});
  }
  // thickness / punch radius (50.8 mm)
  add1("thickness", "h/Rp = 1e-4", {{"blank.thickness_mm", "0.00508"}});
  if (!quick) add1("thickness", "h/Rp = 1e-3", {{"blank.thickness_mm", "0.0508"}});
  add1("thickness", "h/Rp = 1e-2", {{"blank.thickness_mm", "0.508"}});
  // 12 elements: 5.2 mm long, not shorter than the 5.08 mm sheet (valid shell mesh).
  add1("thickness", "h/Rp = 1e-1 (die 56.5, blank 62.85, 12 elements)",
       {{"blank.thickness_mm", "5.08"},
        {"tool.die.radius_mm", "56.5"},
        {"blank.radius_mm", "62.85"},
        {"blank.elements", "12"}});
  for (const char* r : quick ? std::vector<const char*>{"0.2", "5"}
                             : std::vector<const char*>{"0.2", "0.5", "2", "5"}) {
    add1("anisotropy", std::string("R = ") + r, {{"material.r_value", r}});
  }
  for (const char* n : quick ? std::vector<const char*>{"0.02", "0.6"}
                             : std::vector<const char*>{"0.02", "0.05", "0.1", "0.3", "0.6"}) {
    add1("hardening", std::string("Swift n = ") + n, {{"material.hardening.n", n}});
  }
  add1("hardening", "perfectly plastic (Swift n = 0)", {{"material.hardening.n", "0"}});
  add1("rate", "power m = 0.1", {{"material.rate.law", "power"}, {"material.rate.m", "0.1"}});
  if (!quick) {
    add1("rate", "perzyna gamma 1e-4/s (strong)",
         {{"material.rate.law", "perzyna"}, {"material.rate.gamma_per_s", "1e-4"}});
  }
  for (const char* v : quick ? std::vector<const char*>{"1e-8"}
                             : std::vector<const char*>{"1e-2", "1e-3", "1e-6", "1e-8"}) {
    add1("rate cut-off", std::string("strain_rate_cutoff = ") + v,
         {{"numerics.strain_rate_cutoff", v}});
  }
  for (const char* v : quick ? std::vector<const char*>{"1"}
                             : std::vector<const char*>{"0.05", "0.1", "0.25", "1"}) {
    add1("step fraction", std::string("step_fraction = ") + v, {{"numerics.step_fraction", v}});
  }
  if (!quick) {
    add1("solver", "picard (paper's direct iteration)", {{"numerics.solver", "picard"}});
    add1("solver", "tolerance 1e-12", {{"numerics.tolerance", "1e-12"}});
    add1("solver", "max_iterations 3 (must stop cleanly)", {{"numerics.max_iterations", "3"}});
    add1("travel", "travel 45 mm (past the maximum load?)", {{"process.punch_travel_mm", "45"}});
    add1("travel", "n = 0.05, travel 45 mm",
         {{"material.hardening.n", "0.05"}, {"process.punch_travel_mm", "45"}});
    add("scene", "ex2 bundled (40 mm)", {}, "ex2_hemispherical_deep_drawing");
    add("scene", "ex2 punch friction 0.5", {{"tool.punch.friction", "0.5"}},
        "ex2_hemispherical_deep_drawing");
    // The bundled ex3 mesh (80 elements of 0.67 mm, thickness 1 mm) is outside the thin-shell
    // model; 50 elements (1.075 mm) are the valid counterpart.
    add("scene", "ex3 50 elements (42 mm)", {{"blank.elements", "50"}}, "ex3_flat_punch_cup");
    add("scene", "ex3 50 elements, sticking on the punch",
        {{"blank.elements", "50"}, {"tool.punch.friction", "sticking"}}, "ex3_flat_punch_cup");
  }
  add1("units", "all lengths x 10 (time x 10)", ex1_scaled(ex1_scene, 10.0));
  if (!quick) {
    add1("units", "all lengths x 0.1 (time x 0.1)", ex1_scaled(ex1_scene, 0.1));
    Overrides p = ex1_scaled(ex1_scene, 10.0);
    p.push_back({"material.rate.law", "power"});
    p.push_back({"material.rate.m", "0.1"});
    p.push_back({"material.rate.reference_rate_per_s", "0.1"});
    add1("units", "x 10, power m = 0.1, reference rate / 10", p);
  }
  if (quick) {
    for (StabilityCase& k : c) {
      if (k.group != "units") k.ov.insert(k.ov.begin(), short_run.begin(), short_run.end());
    }
  }
  return c;
}

}  // namespace vsx
