#include "output/fld.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/forming_fields.h"
#include "output/number_format.h"
#include "output/profile_csv.h"

namespace vs {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double at(const std::vector<double>& v, std::size_t i) { return i < v.size() ? v[i] : kNaN; }

PrincipalStrains principal_at(const Profile& p, std::size_t i) {
  return in_plane_principal(at(p.eps_meridional, i), at(p.eps_circumferential, i));
}

// Step number of each history entry, matched by punch travel (both come from the same double,
// so equality is exact); history and steps are both in travel order, so one sweep suffices.
std::vector<int> history_steps(const RunResult& result) {
  std::vector<int> steps(result.history.size());
  std::size_t k = 0;
  for (std::size_t h = 0; h < result.history.size(); ++h) {
    const double travel = result.history[h].punch_travel_mm;
    while (k < result.steps.size() && result.steps[k].punch_travel_mm < travel) ++k;
    const bool match = k < result.steps.size() && result.steps[k].punch_travel_mm == travel;
    steps[h] = match ? result.steps[k].step : static_cast<int>(h);
  }
  return steps;
}

}  // namespace

PrincipalStrains in_plane_principal(double eps_meridional, double eps_circumferential) {
  if (std::isnan(eps_meridional) || std::isnan(eps_circumferential)) return {kNaN, kNaN};
  return {std::max(eps_meridional, eps_circumferential),
          std::min(eps_meridional, eps_circumferential)};
}

const Profile* final_state(const RunResult& result) {
  const Profile* last_profile = nullptr;
  if (!result.profiles.empty()) {
    const std::string& first_line = result.profiles.front().line;
    for (auto it = result.profiles.rbegin(); it != result.profiles.rend(); ++it) {
      if (it->line == first_line) {
        last_profile = &*it;
        break;
      }
    }
  }
  const Profile* last_history = result.history.empty() ? nullptr : &result.history.back();
  if (last_profile == nullptr) return last_history;
  if (last_history == nullptr) return last_profile;
  return last_history->punch_travel_mm > last_profile->punch_travel_mm ? last_history
                                                                       : last_profile;
}

std::vector<FldPoint> fld_points(const Profile* state) {
  std::vector<FldPoint> points;
  if (state == nullptr) return points;
  const std::size_t n = profile_rows(*state);
  for (std::size_t i = 0; i < n; ++i) {
    const PrincipalStrains e = principal_at(*state, i);
    FldPoint p;
    p.element = i;
    p.r0_mm = p.x0_mm = at(state->r0_mm, i);
    p.r_mm = at(state->r_mm, i);
    p.eps_major = e.major;
    p.eps_minor = e.minor;
    p.eps_thickness = at(state->eps_thickness, i);
    p.eps_effective = at(state->eps_effective, i);
    p.thinning_percent = thinning_percent(p.eps_thickness);
    p.flc_eps_major = p.flc_margin = kNaN;
    points.push_back(p);
  }
  return points;
}

std::vector<FldPoint> fld_points(const RunResult& result) {
  if (!result.shell) return fld_points(final_state(result));
  std::vector<FldPoint> points;
  if (result.shell->stages.empty()) return points;
  const shell3d::ShellMesh& mesh = result.shell->mesh;
  const ShellStage& stage = result.shell->stages.back();
  const shell3d::ElementStrains e = shell3d::element_strains(mesh, stage);
  for (std::size_t k = 0; k < e.major.size(); ++k) {
    const int centre = mesh.elements[k][8];
    const Eigen::Vector3d& x0 = mesh.nodes[static_cast<std::size_t>(centre)];
    const Eigen::Vector3d& x = stage.x[static_cast<std::size_t>(centre)];
    FldPoint p;
    p.element = k;
    p.x0_mm = x0.x();
    p.y0_mm = x0.y();
    p.r0_mm = e.r0_mm[k];
    p.r_mm = std::hypot(x.x(), x.y());
    p.eps_major = e.major[k];
    p.eps_minor = e.minor[k];
    p.eps_thickness = e.thickness[k];
    p.eps_effective = e.effective[k];
    p.thinning_percent = thinning_percent(p.eps_thickness);
    p.flc_eps_major = p.flc_margin = kNaN;
    points.push_back(p);
  }
  return points;
}

void apply_forming_limit(const FormingLimitCurve& flc, std::vector<FldPoint>* points) {
  for (FldPoint& p : *points) {
    const FormingMargin m = forming_margin(flc, p.eps_major, p.eps_minor);
    p.flc_eps_major = flc.major_limit(p.eps_minor);
    p.flc_margin = m.margin;
    p.zone = m.zone;
  }
}

const FldPoint* least_margin_point(const std::vector<FldPoint>& points) {
  const FldPoint* least = nullptr;
  for (const FldPoint& p : points) {
    if (std::isnan(p.flc_margin)) continue;
    if (least == nullptr || p.flc_margin < least->flc_margin) least = &p;
  }
  return least;
}

std::string fld_points_csv(const std::vector<FldPoint>& points) {
  // Without a forming-limit curve (model "none") or where a point has no minor strain, the FLC
  // columns are empty: no written file carries NaN (issue 16).
  auto flc_number = [](double v) { return std::isfinite(v) ? format_number(v) : std::string(); };
  std::string out =
      "element,x0_mm,y0_mm,r0_mm,r_mm,eps_major,eps_minor,eps_thickness,thinning_percent,"
      "eps_effective,flc_eps_major,flc_margin,flc_zone\n";
  for (const FldPoint& p : points) {
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{}\n", p.element, format_number(p.x0_mm),
        format_number(p.y0_mm), format_number(p.r0_mm), format_number(p.r_mm),
        format_number(p.eps_major), format_number(p.eps_minor), format_number(p.eps_thickness),
        format_number(p.thinning_percent), format_number(p.eps_effective),
        flc_number(p.flc_eps_major), flc_number(p.flc_margin), forming_zone_name(p.zone));
  }
  return out;
}

std::vector<std::size_t> strain_path_elements(const Profile& state, std::size_t count) {
  const std::size_t n = profile_rows(state);
  std::vector<std::size_t> elements;
  if (n == 0 || count == 0) return elements;
  // Thinnest = smallest finite thickness (NaN never compares smaller).
  std::size_t thinnest = 0;
  double thinnest_mm = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < state.thickness_mm.size(); ++i) {
    if (state.thickness_mm[i] < thinnest_mm) {
      thinnest_mm = state.thickness_mm[i];
      thinnest = i;
    }
  }
  elements.push_back(thinnest);
  const std::size_t others = std::min(count - 1, n);
  for (std::size_t k = 0; k < others; ++k) {
    elements.push_back(others == 1 ? 0 : k * (n - 1) / (others - 1));
  }
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  return elements;
}

std::vector<StrainPath> strain_paths(const RunResult& result,
                                     const std::vector<std::size_t>& elements) {
  const std::vector<int> steps = history_steps(result);
  const Profile* state = final_state(result);
  std::vector<StrainPath> paths;
  for (std::size_t element : elements) {
    StrainPath path;
    path.element = element;
    path.r0_mm = state != nullptr ? at(state->r0_mm, element) : kNaN;
    for (std::size_t h = 0; h < result.history.size(); ++h) {
      const Profile& p = result.history[h];
      if (element >= profile_rows(p)) continue;
      const PrincipalStrains e = principal_at(p, element);
      path.step.push_back(steps[h]);
      path.punch_travel_mm.push_back(p.punch_travel_mm);
      path.eps_major.push_back(e.major);
      path.eps_minor.push_back(e.minor);
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

std::string strain_paths_csv(const std::vector<StrainPath>& paths) {
  std::string out = "step,punch_travel_mm,element,r0_mm,eps_major,eps_minor\n";
  for (const StrainPath& path : paths) {
    for (std::size_t k = 0; k < path.step.size(); ++k) {
      out +=
          fmt::format("{},{},{},{},{},{}\n", path.step[k], format_number(path.punch_travel_mm[k]),
                      path.element, format_number(path.r0_mm), format_number(path.eps_major[k]),
                      format_number(path.eps_minor[k]));
    }
  }
  return out;
}

}  // namespace vs
