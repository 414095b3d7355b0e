// numerics.friction_surface = face (issue 15; docs/contact_face.md): the tangential unknowns of a
// node touching one tool are the velocity of the face that touches it, in both geometries. The
// closed forms here are the shell kinematics themselves:
//   - axisymmetric (axisym2.h): a point at zeta along the element normal m = (-s, c) moves with
//     v - zeta beta t_e; the touching face is zeta = -(h/2) sign(m . n) (n: the tool's normal
//     into the sheet), and its velocity along the tool's tangent t = (n_z, -n_r) must be the
//     node's first local unknown;
//   - 3D (shell9_kinematics.h): a point at t along the director moves with u + t (h/2) dV3,
//     dV3 = -alpha V2 + beta V1; the touching face is t = -sign(n . V3), and its components along
//     the nodal frame's first two axes must be the node's first two local unknowns.
// Both must survive the round trip local -> global -> local, and with friction_surface = mid the
// frames must be what they were (the unknowns are the mid-surface's).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "model/axisym_model.h"
#include "model/forming_model.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

Scene scene(const std::string& name, FrictionSurface where) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/" + name + ".toml");
  s.numerics.friction_surface = where;
  return s;
}

// A bent meridian with its first nodes on the punch (tool normal tilted from the element normal)
// and the last ones on the die face under the holder.
AxisymState touched(const AxisymModel& m) {
  AxisymState s = m.initial_state();
  const int nn = m.num_nodes();
  for (int i = 0; i < nn; ++i) s.x[i].y() -= 0.002 * s.x[i].x() * s.x[i].x();
  for (int e = 0; e < m.num_elements(); ++e) s.thickness[e] *= 1.0 + 0.05 * std::sin(0.9 * e);
  for (int i = 0; i < 5; ++i) {
    s.contact[i].tool = m.punch_index();
    const double a = 0.004 * s.x[i].x() + 0.03;
    s.contact[i].normal = Eigen::Vector2d(-std::sin(a), std::cos(a));
  }
  int die = -1;
  for (std::size_t k = 0; k < m.tools().size(); ++k)
    if (m.tools()[k].name() == "die") die = static_cast<int>(k);
  EXPECT_GE(die, 0);
  for (int i = nn - 3; i < nn; ++i) {
    s.contact[i].tool = die;
    s.contact[i].normal = Eigen::Vector2d(0.0, -1.0);
    s.contact[i].on_die_face = true;
  }
  m.update_holder(&s);
  return s;
}

TEST(FrictionSurface, AxisymmetricTangentialUnknownIsTheTouchingFacesVelocity) {
  const Scene sc = scene("ex3_flat_punch_cup", FrictionSurface::kFace);
  AxisymModel m(sc);
  const AxisymState s = touched(m);
  Eigen::VectorXd local(m.num_dofs());
  for (int k = 0; k < local.size(); ++k) local(k) = std::sin(1.3 * k + 0.2) + 0.1 * k;
  const Eigen::VectorXd global = m.to_global(s, local);
  EXPECT_LT((m.to_local(s, global) - local).norm(), 1e-13 * local.norm());
  int held = 0;
  for (int i = 1; i < 5; ++i) {
    // The node's normal: the mean of its elements' normals.
    Eigen::Vector2d mn = Eigen::Vector2d::Zero();
    for (int e : {i - 1, i}) {
      const Eigen::Vector2d t = (s.x[e + 1] - s.x[e]).normalized();
      mn += Eigen::Vector2d(-t.y(), t.x());
    }
    mn.normalize();
    const Eigen::Vector2d te(mn.y(), -mn.x());  // t_e with m = (-t_y, t_x)
    const Eigen::Vector2d n = s.contact[i].normal;
    const double zeta = -0.5 * m.node_thickness(s, i) * (mn.dot(n) >= 0.0 ? 1.0 : -1.0);
    const Eigen::Vector2d v = global.segment<2>(3 * i);
    const double beta = global(3 * i + 2);
    const Eigen::Vector2d face = v - zeta * beta * te;
    const Eigen::Vector2d t(n.y(), -n.x());
    EXPECT_NEAR(face.dot(t), local(3 * i), 1e-12 * std::abs(local(3 * i)) + 1e-14) << i;
    EXPECT_NEAR(v.dot(n), local(3 * i + 1), 1e-12) << i;  // the normal stays the mid-surface's
    EXPECT_GT(std::abs(face.dot(t) - v.dot(t)), 1e-3 * std::abs(beta)) << "no face term: hollow";
    ++held;
  }
  EXPECT_EQ(held, 4);
  // The axis node and the flange under the holder keep the mid-surface: an orthogonal frame.
  for (int i : {0, m.num_nodes() - 1}) {
    const Eigen::Matrix3d Q = m.frame(s, i);
    EXPECT_LT((Q.transpose() * Q - Eigen::Matrix3d::Identity()).norm(), 1e-14) << i;
  }
  // friction_surface = mid: every frame orthogonal, the unknowns the mid-surface's.
  AxisymModel mid(scene("ex3_flat_punch_cup", FrictionSurface::kMid));
  for (int i = 0; i < mid.num_nodes(); ++i) {
    const Eigen::Matrix3d Q = mid.frame(s, i);
    EXPECT_LT((Q.transpose() * Q - Eigen::Matrix3d::Identity()).norm(), 1e-14) << i;
  }
}

TEST(FrictionSurface, ShellTangentialUnknownsAreTheTouchingFacesVelocity) {
  using shell3d::FormingModel;
  using shell3d::FormingState;
  using shell3d::Vec3;
  Scene sc = scene("ex4a_quarter_disc_sticking", FrictionSurface::kFace);
  sc.blank.divisions = 2;
  FormingModel m(sc);
  FormingState s = m.initial_state();
  m.place_tools(s);
  // Tilted directors, a punch below (normal +z-ish) and one node pressed from above (normal -z):
  // both faces occur.
  int below = 0, above = 0;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Vec3& p = m.initial_position(i);
    s.director[i] = Vec3(0.05 * p.x() / 50.0, -0.03, 1.0).normalized();
    s.thickness[i] *= 1.0 + 0.03 * std::cos(0.7 * i);
    if (m.on_axis(i) || !m.contact_eligible(i) || p.head<2>().norm() > 40.0) continue;
    s.contact[i].tool = m.punch_index();
    const bool up = i % 2 == 0;
    // The tools are axisymmetric: the normal lies in the meridional plane.
    const Vec3 er = Vec3(p.x(), p.y(), 0.0).normalized();
    s.contact[i].normal = (0.03 * er + Vec3(0.0, 0.0, up ? 1.0 : -1.0)).normalized();
    ++(up ? below : above);
  }
  ASSERT_GT(below, 0);
  ASSERT_GT(above, 0);
  m.prepare(s);
  Eigen::VectorXd x(m.num_dofs());
  for (int k = 0; k < x.size(); ++k) x(k) = std::cos(0.7 * k + 0.1) + 0.05 * k;
  std::vector<Vec3> v, w;
  m.to_global(x, &v, &w);
  EXPECT_LT((m.to_local(v, w) - x).norm(), 1e-13 * x.norm());
  int held = 0;
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (s.contact[i].tool < 0) continue;
    const int d = m.shell_model().dof(i, 0);
    const Vec3& d3 = s.director[i];
    const double t = s.contact[i].normal.dot(d3) >= 0.0 ? -1.0 : 1.0;
    const Vec3 dV3 = -x(d + 3) * m.v2(i) + x(d + 4) * m.v1(i);
    EXPECT_LT((w[i].cross(d3) - dV3).norm(), 1e-12);  // dV3 = omega x V3
    const Vec3 face = v[i] + t * 0.5 * s.thickness[i] * dV3;
    const Eigen::Matrix3d& Q = m.frame(i);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(Q.col(k).dot(face), x(d + k), 1e-12) << i << " " << k;
    EXPECT_NEAR(Q.col(2).dot(v[i]), x(d + 2), 1e-12) << i;  // the normal stays the mid-surface's
    EXPECT_GT((Q.leftCols<2>().transpose() * (face - v[i])).norm(), 1e-3) << "hollow";
    ++held;
  }
  EXPECT_EQ(held, below + above);
  // friction_surface = mid: the local unknowns are the mid-surface velocity in the frame.
  sc.numerics.friction_surface = FrictionSurface::kMid;
  FormingModel mid(sc);
  mid.prepare(s);
  mid.to_global(x, &v, &w);
  for (int i = 0; i < mid.num_nodes(); ++i) {
    const int d = mid.shell_model().dof(i, 0);
    EXPECT_LT((mid.frame(i).transpose() * v[i] - x.segment<3>(d)).norm(), 1e-12) << i;
  }
}

}  // namespace
}  // namespace vs
