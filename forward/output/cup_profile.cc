#include "output/cup_profile.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace vs {

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrap_deg(double a) {
  double w = std::fmod(a, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

bool on_outline(const BlankSpec& b, const Eigen::Vector3d& x0, double tol) {
  if (b.shape == BlankShape::kCircle) return std::abs(x0.head<2>().norm() - b.radius_mm) < tol;
  return std::abs(std::max(std::abs(x0.x()), std::abs(x0.y())) - b.radius_mm) < tol;
}

// Whether `deg` is a whole multiple of 90 (to round-off).
bool along_axis(double deg) {
  const double q = deg / 90.0;
  return std::abs(q - std::round(q)) < 1e-12;
}

}  // namespace

CupProfileResult rim_cup_profile(const Scene& scene, const ShellFields& shell,
                                 const ShellStage& stage, double rolling_direction_deg) {
  CupProfileResult out;
  const BlankSpec& b = scene.blank;
  const shell3d::ShellMesh& mesh = shell.mesh;
  if (b.edge != EdgeCondition::kFree) {
    out.reason = "the blank edge is not free";
    return out;
  }
  if (stage.x.empty() || stage.x.size() != mesh.nodes.size() ||
      stage.thickness_mm.size() != mesh.nodes.size()) {
    out.reason = "the stage has no nodal fields";
    return out;
  }
  const bool quarter = b.symmetry == BlankSymmetry::kQuarter;
  if (quarter && !along_axis(rolling_direction_deg)) {
    out.reason = fmt::format(
        "a quarter model cannot be unfolded to 360 deg with the rolling direction at {} deg from "
        "x (orthotropic symmetry about x = 0 and y = 0 needs RD along x or y)",
        rolling_direction_deg);
    return out;
  }
  const double tol = 1e-6 * b.radius_mm;
  int axis = -1;
  std::vector<int> rim;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d& x0 = mesh.nodes[static_cast<std::size_t>(i)];
    if (axis < 0 && x0.head<2>().norm() < tol) axis = i;
    if (on_outline(b, x0, tol)) rim.push_back(i);
  }
  if (axis < 0 || rim.empty()) {
    out.reason = axis < 0 ? "the mesh has no node at the blank centre"
                          : "the mesh has no node on the blank outline";
    return out;
  }
  const auto ax = static_cast<std::size_t>(axis);
  const double bottom_mm = stage.x[ax].z() + 0.5 * stage.thickness_mm[ax];

  CupProfile& p = out.profile;
  p.punch_travel_mm = stage.punch_travel_mm;
  p.rolling_direction_deg = rolling_direction_deg;
  p.unfolded = quarter;
  std::vector<double> angle, height;
  std::vector<Eigen::Vector3d> where;
  auto add = [&](const Eigen::Vector3d& x) {
    angle.push_back(wrap_deg(std::atan2(x.y(), x.x()) * 180.0 / kPi - rolling_direction_deg));
    height.push_back(bottom_mm - x.z());
    where.push_back(x);
  };
  for (int i : rim) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d& x = stage.x[k];
    add(x);
    if (!quarter) continue;
    // Mirror images; a node on a symmetry plane (initially, and kept there by the plane's
    // condition) is its own image in that plane.
    const bool on_x0 = std::abs(mesh.nodes[k].x()) < tol;  // on the plane x = 0
    const bool on_y0 = std::abs(mesh.nodes[k].y()) < tol;  // on the plane y = 0
    if (!on_x0) add({-x.x(), x.y(), x.z()});
    if (!on_y0) add({x.x(), -x.y(), x.z()});
    if (!on_x0 && !on_y0) add({-x.x(), -x.y(), x.z()});
  }
  std::vector<std::size_t> order(angle.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return angle[i] < angle[j]; });
  for (std::size_t k : order) {
    p.angle_from_rd_deg.push_back(angle[k]);
    p.height_mm.push_back(height[k]);
    p.x_mm.push_back(where[k]);
  }
  out.available = true;
  return out;
}

}  // namespace vs
