#include "common/axisym_comparison.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "model/forming_fields.h"

namespace vs::shell3d {

Scene axisymmetric_twin(const Scene& shell3d_scene, int elements) {
  if (shell3d_scene.blank.shape != BlankShape::kCircle) {
    throw InputError(shell3d_scene.source + ": only a circular blank has an axisymmetric twin");
  }
  Scene s = shell3d_scene;
  s.geometry = Geometry::kAxisymmetric;
  s.blank.elements = elements;
  s.blank.grading = 1.0;
  // The twin is the reference, so its travel step stays converged (kTwinTravelIncrementPerLength)
  // whatever the 3D scene asks for: a scene that coarsens the (expensive) 3D step with a large
  // max_travel_increment_per_length must not coarsen the (cheap) reference with it. Measured on
  // ex4a sticking, 30 elements: with the 0.5 mm grid of the scene alone (0.25 element lengths)
  // the axisymmetric mean force is 1.3 % low at 10 mm and 6 % low at 20 mm, and the thinning at
  // the edge of the stuck cap is -0.71 instead of -0.58 at 30 mm (experiments/05_shell3d; Heun,
  // before the edge-node fix).
  s.numerics.max_travel_increment_per_length =
      std::min(s.numerics.max_travel_increment_per_length, kTwinTravelIncrementPerLength);
  // Likewise the strain-rate cut-off: a 3D scene run with a larger one (the speed setting) is
  // compared with the reference at the default cut-off, not with one that shares its error.
  s.numerics.strain_rate_cutoff =
      std::min(s.numerics.strain_rate_cutoff, NumericsSpec{}.strain_rate_cutoff);
  // And the axisymmetric defaults of the step grid: steps that end at contact events and no
  // graded start (a 3D scene's defaults are the opposite since 26 Nov 2026; experiments/06).
  s.numerics.contact_events = true;
  s.numerics.start_refinement = 0;
  // And two velocity solves per implicit step (the second-order update): a 3D run with the one-
  // solve speed setting is compared with the converged reference, not with one that shares it.
  s.numerics.implicit_solves = NumericsSpec{}.implicit_solves;
  // And the default solve for new contacts (numerics.contact_entry): the reference keeps its
  // defaults, so runs with either setting are measured against the same twin.
  s.numerics.contact_entry = NumericsSpec{}.contact_entry;
  return s;
}

double TravelComparison::max_eps_thickness_deviation() const {
  return std::max(
      {eps_thickness_deviation_y0, eps_thickness_deviation_x0, eps_thickness_deviation_diagonal});
}

namespace {

const StepRecord* step_at(const std::vector<StepRecord>& steps, double travel) {
  for (const StepRecord& r : steps) {
    if (std::abs(r.punch_travel_mm - travel) <= 1e-9 * (1.0 + travel)) return &r;
  }
  return nullptr;
}

double line_deviation(const RunResult& shell, const ShellStage& stage, const Profile& axi,
                      const std::string& line, double h0) {
  const LineProfile p = line_profile(shell.shell->mesh, stage, line, h0);
  double dev = 0.0;
  for (std::size_t i = 0; i < p.nodes.size(); ++i) {
    const double ref = interpolate(axi.r0_mm, axi.eps_thickness, p.r0_mm[i]);
    dev = std::max(dev, std::abs(p.eps_thickness[i] - ref));
  }
  return dev;
}

}  // namespace

double mean_force(const std::vector<StepRecord>& steps, double a, double b) {
  double work = 0.0, length = 0.0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const double t0 = steps[k - 1].punch_travel_mm, t1 = steps[k].punch_travel_mm;
    const double lo = std::max(a, t0), hi = std::min(b, t1);
    if (!(hi > lo) || !(t1 > t0)) continue;
    auto force = [&](double t) {
      const double w = (t - t0) / (t1 - t0);
      return (1.0 - w) * steps[k - 1].punch_force_N + w * steps[k].punch_force_N;
    };
    work += 0.5 * (force(lo) + force(hi)) * (hi - lo);
    length += hi - lo;
  }
  return length > 0.0 ? work / length : std::nan("");
}

std::vector<TravelComparison> compare_with_axisymmetric(const Scene& scene, const RunResult& shell,
                                                        const RunResult& axisym, double window_mm) {
  std::vector<TravelComparison> out;
  const double h0 = scene.blank.thickness_mm;
  for (double travel : scene.process.output_travels_mm) {
    const StepRecord* s3 = step_at(shell.steps, travel);
    const StepRecord* sa = step_at(axisym.steps, travel);
    auto stage = std::find_if(
        shell.shell->stages.begin(), shell.shell->stages.end(), [&](const ShellStage& st) {
          return std::abs(st.punch_travel_mm - travel) <= 1e-9 * (1.0 + travel);
        });
    auto prof = std::find_if(axisym.profiles.begin(), axisym.profiles.end(), [&](const Profile& p) {
      return std::abs(p.punch_travel_mm - travel) <= 1e-9 * (1.0 + travel);
    });
    if (!s3 || !sa || stage == shell.shell->stages.end() || prof == axisym.profiles.end()) continue;
    TravelComparison c;
    c.punch_travel_mm = travel;
    c.force_3d_N = s3->punch_force_N;
    c.force_axisym_N = sa->punch_force_N;
    c.force_deviation = (c.force_3d_N - c.force_axisym_N) / c.force_axisym_N;
    c.mean_force_3d_N = mean_force(shell.steps, travel - window_mm, travel);
    c.mean_force_axisym_N = mean_force(axisym.steps, travel - window_mm, travel);
    c.mean_force_deviation = (c.mean_force_3d_N - c.mean_force_axisym_N) / c.mean_force_axisym_N;
    c.eps_thickness_deviation_y0 = line_deviation(shell, *stage, *prof, "y0", h0);
    c.eps_thickness_deviation_x0 = line_deviation(shell, *stage, *prof, "x0", h0);
    c.eps_thickness_deviation_diagonal = line_deviation(shell, *stage, *prof, "diagonal", h0);
    for (double e : prof->eps_thickness) {
      c.max_abs_eps_thickness_axisym = std::max(c.max_abs_eps_thickness_axisym, std::abs(e));
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace vs::shell3d
