// Work-precision measurement for one scene: a set of discretisation settings, a reference from a
// three-level combined refinement (Richardson on the scalars, finest run for the curves), and the
// errors of every setting against it. Header-only (shared with the quick CTest variant).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "harness.h"
#include "metrics.h"

namespace vsx {

struct Setting {
  std::string family;  // which knob was varied ("elements", "tolerance", ..., "refined")
  std::string label;   // short value text for legends
  Overrides ov;        // on top of the scene's own overrides
};

struct Errors {
  double peak = kNaN;         // |P - Pref| / Pref
  double curve = kNaN;        // relative L2 of the load curve on a fixed travel grid
  double strain_abs = kNaN;   // max abs thickness-strain difference over the output travels
  double strain_rel = kNaN;   // strain_abs / max |eps_t| of the reference
  double position_mm = kNaN;  // |r0_thinnest - ref| at the final travel
  double combined = kNaN;     // max(peak, curve, strain_rel): the accuracy the report ranks by
};

struct Outcome {
  Setting setting;
  TimedRun run;
  double peak_N = kNaN;
  double thinnest_r0_mm = kNaN;
  Errors err;
  bool pareto = false;
  bool is_reference = false;  // the run curves and profiles are compared with
};

// Scalars of the reference: Richardson over the three refined levels.
struct Reference {
  std::vector<const Outcome*> levels;  // coarse to fine
  Richardson peak, thinnest;
  std::vector<double> output_travels;
  double travel_mm = 0.0;
  const vs::RunResult* finest = nullptr;
  double eps_scale = 1.0;  // max |eps_t| of the finest run over the output travels
  bool ok = false;
  std::string note;
};

// Largest element count whose (uniform) elements are not shorter than the sheet thickness: finer
// shell meshes are outside the thin-shell model (the solver warns, RunResult.warnings) and their
// contact reactions are noisy, so they are neither studied nor used as references.
inline int max_valid_elements(const vs::Scene& scene) {
  return std::max(
      4, static_cast<int>(std::floor(scene.blank.radius_mm / scene.blank.thickness_mm + 1e-9)));
}

// The settings: one knob at a time around the scene's bundled numerics, a few coarse
// combinations, and the combined refinement levels k = 0, 1, 2 (elements n0 x 2^k with
// n0 = max_elements / 4, so the finest level is the finest valid mesh; travel cap 0.1, 0.05,
// 0.025 mm (the time-integration study shows Heun's thickness-strain error is ~1e-4 at 0.025 mm)
// and strain cap 0.02, 0.01, 0.005; 9 thickness points, tolerance 1e-8) that define the
// reference.
inline std::vector<Setting> work_precision_settings(int base_elements, int max_elements,
                                                    bool quick) {
  std::vector<Setting> s;
  auto el = [&](double f) {
    return std::to_string(std::min(max_elements, std::max(4, static_cast<int>(base_elements * f))));
  };
  s.push_back({"bundled", "bundled", {}});
  {
    std::vector<int> meshes =
        quick ? std::vector<int>{max_elements / 4, max_elements / 2}
              : std::vector<int>{max_elements / 4, max_elements / 2, max_elements};
    for (int n : meshes) {
      if (n == base_elements || n < 4) continue;
      s.push_back({"elements", std::to_string(n), {{"blank.elements", std::to_string(n)}}});
    }
  }
  for (const char* v :
       quick ? std::vector<const char*>{"2"} : std::vector<const char*>{"2", "1", "0.5", "0.125"}) {
    s.push_back({"travel cap",
                 v,
                 {{"numerics.max_travel_increment_mm", v},
                  {"numerics.max_travel_increment_per_length", "1e9"}}});
  }
  for (const char* v : quick ? std::vector<const char*>{"0.08"}
                             : std::vector<const char*>{"0.08", "0.04", "0.01", "0.005"}) {
    s.push_back({"strain cap", v, {{"numerics.max_strain_increment", v}}});
  }
  for (const char* v :
       quick ? std::vector<const char*>{"0.5"} : std::vector<const char*>{"0.5", "0.25", "0.1"}) {
    s.push_back({"step fraction", v, {{"numerics.step_fraction", v}}});
  }
  for (const char* v :
       quick ? std::vector<const char*>{"3"} : std::vector<const char*>{"3", "7", "9"}) {
    s.push_back({"thickness points", v, {{"numerics.thickness_points", v}}});
  }
  for (const char* v : quick ? std::vector<const char*>{"1e-3"}
                             : std::vector<const char*>{"1e-2", "1e-3", "1e-4", "1e-8"}) {
    s.push_back({"tolerance", v, {{"numerics.tolerance", v}}});
  }
  s.push_back({"time integration", "euler", {{"numerics.time_integration", "euler"}}});
  // Indices 0-4 are edited below; the relative travel cap is switched off (last) so that the
  // absolute cap sets the grid.
  const Overrides coarse{{"blank.elements", el(0.5)},
                         {"numerics.max_travel_increment_mm", "2"},
                         {"numerics.max_strain_increment", "0.08"},
                         {"numerics.thickness_points", "3"},
                         {"numerics.tolerance", "1e-3"},
                         {"numerics.max_travel_increment_per_length", "1e9"}};
  s.push_back({"coarse combo", "A", coarse});
  if (!quick) {
    Overrides b = coarse;
    b[1].value = "1";
    b[2].value = "0.04";
    b[4].value = "1e-4";
    s.push_back({"coarse combo", "B", b});
    b[0].value = el(1);
    s.push_back({"coarse combo", "C", b});
  }
  const int n0 = std::max(4, max_elements / 4);
  for (int k = 0; k < 3; ++k) {
    const double f = std::ldexp(1.0, k);
    s.push_back({"refined",
                 fmt::format("L{}", k),
                 {{"blank.elements", std::to_string(n0 << k)},
                  {"numerics.max_travel_increment_mm", fmt::format("{}", 0.1 / f)},
                  {"numerics.max_travel_increment_per_length", "1e9"},
                  {"numerics.max_strain_increment", fmt::format("{}", 0.02 / f)},
                  {"numerics.thickness_points", "9"},
                  {"numerics.tolerance", "1e-8"}}});
  }
  return s;
}

// The reference run is excluded from the Pareto front and the recommendations (its own error
// would read zero).
inline bool is_reference(const Outcome& o) { return o.is_reference; }

inline void measure(Outcome* o) {
  o->peak_N = peak_load(o->run.result).force_N;
  if (!o->run.result.profiles.empty())
    o->thinnest_r0_mm = thinnest_r0(o->run.result.profiles.back());
}

// Builds the reference from the "refined" outcomes (in level order).
// Builds the reference from the completed "refined" outcomes (in level order) and marks the
// finest completed one as the reference run. With all three levels the scalars are Richardson
// extrapolations; otherwise the finest completed level is the reference as is (said in `note`).
inline Reference make_reference(std::vector<Outcome>* all,
                                const std::vector<double>& output_travels, double travel_mm) {
  Reference ref;
  ref.output_travels = output_travels;
  ref.travel_mm = travel_mm;
  for (Outcome& o : *all) {
    if (o.setting.family != "refined") continue;
    if (o.run.result.completed()) {
      ref.levels.push_back(&o);
    } else {
      ref.note += fmt::format("refinement level {} did not complete ({}). ", o.setting.label,
                              o.run.result.message);
    }
  }
  if (ref.levels.empty()) return ref;
  const auto& l = ref.levels;
  const Outcome* fine = l.back();
  if (l.size() == 3) {
    ref.peak = richardson(l[0]->peak_N, l[1]->peak_N, l[2]->peak_N);
    ref.thinnest = richardson(l[0]->thinnest_r0_mm, l[1]->thinnest_r0_mm, l[2]->thinnest_r0_mm);
  } else {
    ref.peak.value = fine->peak_N;
    ref.thinnest.value = fine->thinnest_r0_mm;
    if (l.size() == 2) {
      ref.peak.error_est = std::abs(l[1]->peak_N - l[0]->peak_N);
      ref.thinnest.error_est = std::abs(l[1]->thinnest_r0_mm - l[0]->thinnest_r0_mm);
    }
    ref.note += fmt::format("The finest completed level {} is the reference (no Richardson). ",
                            fine->setting.label);
  }
  for (Outcome& o : *all) o.is_reference = &o == fine;
  ref.finest = &fine->run.result;
  ref.eps_scale = 0.0;
  for (double t : output_travels) {
    if (const vs::Profile* p = profile_at(*ref.finest, t)) {
      ref.eps_scale = std::max(ref.eps_scale, max_abs(p->eps_thickness));
    }
  }
  ref.ok = ref.eps_scale > 0.0;
  return ref;
}

inline Errors errors_against(const Outcome& o, const Reference& ref) {
  Errors e;
  if (!ref.ok || o.run.result.steps.empty()) return e;
  e.peak = rel(o.peak_N, ref.peak.value);
  const double reach = std::min(final_travel(o.run.result), ref.travel_mm);
  e.curve = load_curve_rel_l2(o.run.result, *ref.finest, reach);
  double worst = 0.0;
  bool any = false;
  for (double t : ref.output_travels) {
    const vs::Profile* a = profile_at(o.run.result, t);
    const vs::Profile* b = profile_at(*ref.finest, t);
    if (a && b) {
      worst = std::max(worst, thickness_strain_max_abs(*a, *b));
      any = true;
    }
  }
  if (any) {
    e.strain_abs = worst;
    e.strain_rel = worst / ref.eps_scale;
  }
  e.position_mm = std::abs(o.thinnest_r0_mm - ref.thinnest.value);
  e.combined = std::max({e.peak, e.curve, e.strain_rel});
  return e;
}

// Marks the Pareto front (completed runs only): no other run is both faster and more accurate.
inline void mark_pareto(std::vector<Outcome>* all) {
  std::vector<Outcome*> ok;
  for (Outcome& o : *all) {
    if (o.run.result.completed() && o.err.combined == o.err.combined && !is_reference(o)) {
      ok.push_back(&o);
    }
  }
  std::sort(ok.begin(), ok.end(),
            [](const Outcome* a, const Outcome* b) { return a->run.cpu_s < b->run.cpu_s; });
  double best = std::numeric_limits<double>::infinity();
  for (Outcome* o : ok) {
    if (o->err.combined < best) {
      o->pareto = true;
      best = o->err.combined;
    }
  }
}

// The fastest completed run with combined error <= target (nullptr if none).
inline const Outcome* fastest_within(const std::vector<Outcome>& all, double target) {
  const Outcome* best = nullptr;
  for (const Outcome& o : all) {
    if (!o.run.result.completed() || !(o.err.combined <= target) || is_reference(o)) continue;
    if (!best || o.run.cpu_s < best->run.cpu_s) best = &o;
  }
  return best;
}

}  // namespace vsx
