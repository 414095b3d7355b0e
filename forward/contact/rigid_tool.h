// Rigid axisymmetric tools as meridian profiles made of straight segments and circular arcs, in
// the (r, z) half plane. Each primitive carries the side the sheet is on, so the closest-point
// query returns a signed distance (positive = separated) and the unit normal pointing from the
// tool into the sheet. Conventions: the sheet mid-surface starts at z = 0, the punch moves in +z
// from below, the die sits above the sheet, the blank holder presses the flange up against the die.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace vs {

struct ProfilePrimitive {
  enum class Kind { kSegment, kArc };
  Kind kind = Kind::kSegment;
  // Segment p0 -> p1 with the sheet on the side of `normal`.
  Eigen::Vector2d p0 = Eigen::Vector2d::Zero(), p1 = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  // Arc: centre, radius, counter-clockwise from angle0 to angle1 (radians, angle1 > angle0);
  // convex = sheet outside the circle.
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0, angle0 = 0.0, angle1 = 0.0;
  bool convex = true;
};

struct ClosestPoint {
  double distance = 0.0;  // signed: > 0 separated, < 0 penetrated
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();  // from the tool into the sheet
  int primitive = -1;
};

class RigidTool {
 public:
  RigidTool(std::string name, ToolKind kind, std::vector<ProfilePrimitive> profile,
            Eigen::Vector2d velocity, double friction);

  const std::string& name() const { return name_; }
  ToolKind kind() const { return kind_; }
  bool is_punch() const {
    return kind_ == ToolKind::kHemisphericalPunch || kind_ == ToolKind::kFlatPunch;
  }
  double friction() const { return friction_; }
  bool sticking() const;
  const Eigen::Vector2d& velocity() const { return velocity_; }  // [mm/s]
  const Eigen::Vector2d& offset() const { return offset_; }      // rigid displacement so far
  void set_offset(const Eigen::Vector2d& o) { offset_ = o; }
  const std::vector<ProfilePrimitive>& profile() const { return profile_; }

  // Closest point of the (current, offset) tool surface to the point x.
  ClosestPoint closest(const Eigen::Vector2d& x) const;
  // Gap of a sheet node of thickness h: distance from the mid-surface minus h/2.
  double gap(const Eigen::Vector2d& x, double h) const { return closest(x).distance - 0.5 * h; }

  // Earliest time in (0, horizon] at which a node at x moving with velocity v (thickness h)
  // touches this tool (the root of paper eq. 53 generalised to any profile); +inf if none.
  double contact_time(const Eigen::Vector2d& x, const Eigen::Vector2d& v, double h,
                      double horizon) const;

 private:
  std::string name_;
  ToolKind kind_;
  std::vector<ProfilePrimitive> profile_;
  Eigen::Vector2d velocity_;
  Eigen::Vector2d offset_ = Eigen::Vector2d::Zero();
  double friction_;
};

// The surface tools of a scene (punch, die), positioned for a sheet of initial thickness h0 with
// its mid-surface at z = 0; flat faces and walls extend a few blank radii. A force blank holder is
// not a surface (the model applies it as a force on the flange); a fixed-gap holder is a flat face
// gap_mm below the die face.
std::vector<RigidTool> make_tools(const Scene& scene);

}  // namespace vs
