// Tool profiles: signed gaps, normals and the contact-event time against closed forms.
#include "contact/rigid_tool.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vs {
namespace {

Scene OneTool(ToolKind kind, double radius, double profile) {
  Scene s;
  s.blank.thickness_mm = 1.0;
  s.blank.radius_mm = 60.0;
  s.process.punch_travel_mm = 10.0;
  ToolSpec t;
  t.name = "t";
  t.kind = kind;
  t.radius_mm = radius;
  t.profile_radius_mm = profile;
  s.tools = {t};
  return s;
}

TEST(RigidTool, HemisphericalPunchGapAndNormal) {
  std::vector<RigidTool> tools = make_tools(OneTool(ToolKind::kHemisphericalPunch, 50.0, 0.0));
  const RigidTool& p = tools[0];
  // Apex touches the lower sheet surface: mid-surface node at the pole has zero gap.
  EXPECT_NEAR(p.gap({0.0, 0.0}, 1.0), 0.0, 1e-12);
  const Eigen::Vector2d c(0.0, -0.5 - 50.0);
  const Eigen::Vector2d x(20.0, 5.0);
  const ClosestPoint cp = p.closest(x);
  EXPECT_NEAR(cp.distance, (x - c).norm() - 50.0, 1e-12);
  EXPECT_NEAR((cp.normal - (x - c).normalized()).norm(), 0.0, 1e-12);
  // Below the equator the shank is a cylinder.
  EXPECT_NEAR(p.closest({53.0, -60.0}).distance, 3.0, 1e-12);
}

TEST(RigidTool, ContactTimeOfAFallingNodeOnTheSphere) {
  std::vector<RigidTool> tools = make_tools(OneTool(ToolKind::kHemisphericalPunch, 50.0, 0.0));
  RigidTool& p = tools[0];  // moves +z at 1 mm/s
  // Node at r = 30 on the flat sheet, at rest: touches when the sphere surface offset by h/2
  // (radius 50.5 about a centre starting at z = -50.5) reaches it: t = 50.5 - sqrt(50.5^2 - 30^2).
  const double t = p.contact_time({30.0, 0.0}, {0.0, 0.0}, 1.0, 100.0);
  EXPECT_NEAR(t, 50.5 - std::sqrt(50.5 * 50.5 - 900.0), 1e-9);
  // Moving away faster than the punch: never.
  EXPECT_TRUE(std::isinf(p.contact_time({30.0, 0.0}, {0.0, 2.0}, 1.0, 100.0)));
}

TEST(RigidTool, DieShoulderAndFace) {
  std::vector<RigidTool> tools = make_tools(OneTool(ToolKind::kDie, 52.83, 6.35));
  const RigidTool& d = tools[0];
  // Flat face at z = h0/2 for r >= 52.83 + 6.35, sheet below: gap of a node at z = 0 is zero.
  EXPECT_NEAR(d.gap({70.0, 0.0}, 1.0), 0.0, 1e-12);
  EXPECT_NEAR(d.closest({70.0, -1.0}).normal.y(), -1.0, 1e-12);
  EXPECT_EQ(d.closest({70.0, -1.0}).primitive, 0);
  // Under the shoulder: distance to the torus of centre (59.18, 0.5 + 6.35).
  const Eigen::Vector2d c(59.18, 6.85);
  const Eigen::Vector2d x(55.0, 0.0);
  EXPECT_NEAR(d.closest(x).distance, (x - c).norm() - 6.35, 1e-12);
  // Inside the opening, level with the wall: distance to the wall r = 52.83.
  EXPECT_NEAR(d.closest({50.0, 20.0}).distance, 2.83, 1e-12);
}

TEST(RigidTool, FlatPunchNoseRadius) {
  std::vector<RigidTool> tools = make_tools(OneTool(ToolKind::kFlatPunch, 30.0, 5.0));
  const RigidTool& p = tools[0];
  EXPECT_NEAR(p.gap({10.0, 0.0}, 1.0), 0.0, 1e-12);  // flat face touches the sheet
  EXPECT_NEAR(p.closest({10.0, 2.0}).normal.y(), 1.0, 1e-12);
  // Around the nose: centre (25, -0.5 - 5).
  const Eigen::Vector2d x(29.0, 1.0), c(25.0, -5.5);
  EXPECT_NEAR(p.closest(x).distance, (x - c).norm() - 5.0, 1e-12);
}

}  // namespace
}  // namespace vs
