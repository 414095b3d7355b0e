// The cup-height (earing) profile of a 3D deep-drawing run: the height of every rim node (the free
// outer edge of the initial blank) against its angle from the rolling direction RD.
//
// Axes as experiments/04_esaform_cup/cup_height.h: the punch moves +z from below and the die sits
// above, so the cup bottom ends highest and the wall hangs down to the rim. For a rim node,
//   angle from RD = atan2(y, x) - rolling_direction_deg   (current position, modulo 360),
//   cup height H = (z_axis + h_axis / 2) - z_rim,
// with z_axis, h_axis the current height and thickness of the node at the blank centre (the
// outer bottom surface, facing the die) and z_rim the rim node's mid-surface height.
//
// A quarter model (x, y >= 0) is unfolded to 0-360 deg by mirroring about x = 0 and y = 0: a rim
// node at angle theta from x gives theta, 180 - theta, 180 + theta and 360 - theta (a node on a
// symmetry plane only once). That is the whole cup only when the material is symmetric about both
// planes: orthotropic with RD along x or y (rolling_direction_deg a multiple of 90); for another
// RD the quarter is refused (the quarter model itself is then not valid either).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct CupProfile {
  double punch_travel_mm = 0.0;
  double rolling_direction_deg = 0.0;  // RD angle from the x axis
  bool unfolded = false;               // a quarter model mirrored to 0-360 deg
  // One entry per rim node (after unfolding), by increasing angle from RD in [0, 360).
  std::vector<double> angle_from_rd_deg;
  std::vector<double> height_mm;
  std::vector<Eigen::Vector3d> x_mm;  // current mid-surface position of the rim node
};

struct CupProfileResult {
  bool available = false;
  std::string reason;  // why there is no profile ("" when available)
  CupProfile profile;
};

// The profile of `stage` (a stage of `shell`, whose mesh gives the initial positions). No profile
// (with the reason) when the blank edge is not free, the stage has no nodes, the mesh has no node
// at the blank centre or on the blank outline, or a quarter model with RD not along x or y.
// The rim is the initial outline: |x0| = radius for a circle, max(|x0|, |y0|) = half side for a
// square.
CupProfileResult rim_cup_profile(const Scene& scene, const ShellFields& shell,
                                 const ShellStage& stage, double rolling_direction_deg);

}  // namespace vs
