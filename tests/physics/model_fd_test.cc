// Finite-difference checks of the assembled forming models with every nodal term active: punch
// contact with Coulomb friction, the force blank holder and its friction on the flange, a squeezed
// (ironed) node with the second tool's friction and the squeeze penalty (axisymmetric), the
// fixed-gap holder penalty (axisymmetric), and in 3D the friction along the slip vector; each with
// the tangential contact on the mid-surface and on the touching face (numerics.friction_surface).
// What each model claims (model/axisym_model.h, model/forming_model.h):
//   - residual = gradient of the flow potential with the normal forces lagged (frozen);
//   - axisymmetric: the kTangent matrix at weight 1 is the derivative of the residual, also with
//     consistent friction (the Coulomb limit following the current normal reaction), and the
//     friction's own stiffness is the law's tangent (the lagged matrix is the derivative of the
//     lagged residual);
//   - 3D: the friction stiffness is the derivative of the friction force along the slip vector,
//     and the force is mu N 2/pi atan(|s|/v0) s/|s| (closed form, computed here); the element
//     part of the 3D matrix is the primal-dual tangent, not the residual's derivative at the
//     iterate, so the whole 3D matrix is not compared (printed only).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "model/axisym_model.h"
#include "model/forming_model.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

Scene scene(const std::string& name) {
  return load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/" + name + ".toml");
}

int tool_named(const std::vector<RigidTool>& tools, const std::string& name) {
  for (std::size_t k = 0; k < tools.size(); ++k) {
    if (tools[k].name() == name) return static_cast<int>(k);
  }
  return -1;
}

// ---------------------------------------------------------------------------------------------
// Axisymmetric model.

struct AxisymCase {
  Scene scene;
  bool gap_holder = false;
};

double sc_gap_mm(const AxisymModel& m) {
  for (const ToolSpec& t : m.scene().tools) {
    if (t.gap_mm > 0.0) return t.gap_mm;
  }
  return 0.0;
}

// A generic state of the cup: bent meridian, uneven thickness, the punch touching the nodes near
// the axis, the die face touching the flange (with the holder's share, or for the fixed gap the
// holder face too), one node on the die wall squeezed against the punch.
AxisymState cup_state(const AxisymModel& m, bool gap_holder) {
  AxisymState s = m.initial_state();
  const int nn = m.num_nodes();
  for (int i = 0; i < nn; ++i) s.x[i].y() += 0.05 * std::sin(0.7 * i);
  for (int e = 0; e < m.num_elements(); ++e) s.thickness[e] *= 1.0 + 0.04 * std::cos(1.3 * e);
  const int punch = m.punch_index(), die = tool_named(m.tools(), "die");
  EXPECT_GE(punch, 0);
  EXPECT_GE(die, 0);
  for (int i = 0; i < 3; ++i) {
    NodeContact& c = s.contact[i];
    c.tool = punch;
    c.normal = Eigen::Vector2d(0.0, 1.0);
    c.normal_force_N = 40.0 + 10.0 * i;
  }
  const int wall = nn / 2;
  NodeContact& w = s.contact[wall];
  w.tool = die;
  w.normal = Eigen::Vector2d(-0.6, 0.8);
  w.normal_force_N = 25.0;
  w.squeeze_tool = punch;
  w.clearance_mm = 0.9 * m.initial_thickness();
  w.squeeze_force_N = 60.0;
  for (int i = nn - 4; i < nn; ++i) {
    NodeContact& c = s.contact[i];
    c.tool = die;
    c.normal = Eigen::Vector2d(0.0, -1.0);
    c.on_die_face = true;
    c.normal_force_N = 70.0;
  }
  if (gap_holder) {
    const int holder = tool_named(m.tools(), "holder");
    EXPECT_GE(holder, 0);
    NodeContact& c = s.contact[nn - 5];
    c.tool = holder;
    c.normal = Eigen::Vector2d(0.0, 1.0);
    c.on_holder_face = true;
    c.normal_force_N = 30.0;
    for (int i = nn - 5; i < nn; ++i) s.contact[i].holder_force_N = 55.0;
    // The flange has reached the gap: any thickening rate presses the holder.
    for (int e = nn - 6; e < nn - 1; ++e) s.thickness[e] = 1.01 * sc_gap_mm(m);
  }
  m.update_holder(&s);
  return s;
}

// A generic local-frame velocity: the punch speed's scale, with the slips of the contact nodes
// within a few regularisation widths (where the friction law bends).
Eigen::VectorXd generic_velocity(const AxisymModel& m, const AxisymState& s, double v0) {
  const double speed = m.punch_speed();
  Eigen::VectorXd v(m.num_dofs());
  for (int k = 0; k < v.size(); ++k) v(k) = speed * (0.3 * std::sin(1.7 * k) - 0.1 * (k % 3));
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (s.contact[i].tool >= 0) v(3 * i) = v0 * (1.5 * std::sin(2.3 * i) + 0.2);
  }
  return v;
}

class AxisymModelFd : public ::testing::TestWithParam<std::tuple<bool, FrictionSurface>> {};

TEST_P(AxisymModelFd, TangentIsTheResidualsDerivativeAndResidualThePotentialsGradient) {
  const bool gap = std::get<0>(GetParam());
  Scene sc = scene(gap ? "ex3_flat_punch_cup_fixed_gap" : "ex3_flat_punch_cup");
  sc.blank.elements = 16;
  sc.numerics.friction_surface = std::get<1>(GetParam());
  AxisymModel m(sc);
  AxisymState s = cup_state(m, gap);
  m.place_tools(s);
  m.freeze_material(s, 0.01);
  m.set_squeeze_correction_time(0.0);
  const double v0 = sc.numerics.friction_regularisation * m.punch_speed();
  const Eigen::VectorXd v = generic_velocity(m, s, v0);

  for (bool consistent : {false, true}) {
    SCOPED_TRACE(consistent ? "consistent friction" : "lagged friction");
    m.set_consistent_friction(consistent);
    AxisymSystem sys;
    m.evaluate(s, v, StiffnessKind::kTangent, &sys, 1.0);
    // Every term is active at this velocity.
    double squeeze = 0.0, gap_p = 0.0;
    for (double p : sys.squeeze_pressure) squeeze += p;
    for (double p : sys.gap_pressure) gap_p += p;
    EXPECT_GT(squeeze, 0.0) << "the squeeze penalty is inactive: the test would be hollow";
    if (gap) {
      EXPECT_GT(gap_p, 0.0) << "the gap penalty is inactive";
    }
    double friction = 0.0;
    for (double f : sys.squeeze_friction) friction += std::abs(f);
    EXPECT_GT(friction, 0.0);

    const Eigen::VectorXd r = sys.residual;
    const std::vector<char> fixed = sys.fixed;
    const int n = m.num_dofs();
    Eigen::MatrixXd K(n, n), Kfd(n, n);
    Eigen::VectorXd grad_fd = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < n; ++j) {
      K.col(j) = sys.K.multiply(Eigen::VectorXd::Unit(n, j));
      Kfd.col(j).setZero();
      if (fixed[j]) continue;
      const int node = j / 3;
      const bool slip = j % 3 == 0 && s.contact[node].tool >= 0;
      const double h = slip ? 1e-3 * v0 : 1e-6 * m.punch_speed();
      AxisymSystem p, q;
      Eigen::VectorXd vp = v, vm = v;
      vp(j) += h;
      vm(j) -= h;
      m.evaluate(s, vp, StiffnessKind::kNone, &p);
      m.evaluate(s, vm, StiffnessKind::kNone, &q);
      Kfd.col(j) = (p.residual - q.residual) / (2 * h);
      grad_fd(j) = (p.potential - q.potential) / (2 * h);
    }
    double scale = 0.0, err = 0.0;
    for (int i = 0; i < n; ++i) {
      if (fixed[i]) continue;
      for (int j = 0; j < n; ++j) {
        if (fixed[j]) continue;
        scale = std::max(scale, std::abs(Kfd(i, j)));
        err = std::max(err, std::abs(K(i, j) - Kfd(i, j)));
      }
    }
    EXPECT_LT(err, 1e-6 * scale) << "max |K - dr/dv| " << err << " of " << scale;
    if (!consistent) {
      // The flow potential's gradient is the residual (lagged normal forces).
      double rs = 0.0, ge = 0.0;
      for (int i = 0; i < n; ++i) {
        if (fixed[i]) continue;
        rs = std::max(rs, std::abs(r(i)));
        ge = std::max(ge, std::abs(grad_fd(i) - r(i)));
      }
      EXPECT_LT(ge, 1e-6 * rs) << "max |dP/dv - r| " << ge << " of " << rs;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ForceAndGapHolder, AxisymModelFd,
                         ::testing::Combine(::testing::Values(false, true),
                                            ::testing::Values(FrictionSurface::kMid,
                                                              FrictionSurface::kFace)));

// The friction force of a sliding punch node is the closed form mu N 2/pi atan(v_t / v0) (the
// residual's tangential component with and without the normal force), and the holder adds its
// own coefficient times the node's share on the die face.
TEST(AxisymModelFriction, TangentialForceIsTheClosedForm) {
  Scene sc = scene("ex3_flat_punch_cup");
  sc.blank.elements = 16;
  AxisymModel m(sc);
  AxisymState s = cup_state(m, false);
  m.place_tools(s);
  m.freeze_material(s, 0.01);
  m.set_consistent_friction(false);
  const double v0 = sc.numerics.friction_regularisation * m.punch_speed();
  const Eigen::VectorXd v = generic_velocity(m, s, v0);
  AxisymSystem with, without;
  m.evaluate(s, v, StiffnessKind::kNone, &with);
  AxisymState bare = s;
  for (auto& c : bare.contact) {
    c.normal_force_N = 0.0;
    c.holder_force_N = 0.0;
    c.squeeze_force_N = 0.0;
  }
  m.evaluate(bare, v, StiffnessKind::kNone, &without);
  const double pi = std::numbers::pi;
  const int die = tool_named(m.tools(), "die");
  int checked = 0;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const NodeContact& c = s.contact[i];
    if (c.tool < 0 || c.squeeze_tool >= 0 || with.fixed[3 * i]) continue;
    const RigidTool& t = m.tools()[c.tool];
    const double vt = v(3 * i) - t.velocity().dot(Eigen::Vector2d(c.normal.y(), -c.normal.x()));
    double limit = t.friction() * c.normal_force_N;
    if (c.on_die_face) limit += sc.tools.back().friction * c.holder_force_N;
    const double f = limit * 2.0 / pi * std::atan(vt / v0);
    EXPECT_NEAR(with.residual(3 * i) - without.residual(3 * i), f, 1e-9 * limit) << "node " << i;
    ++checked;
    if (c.on_die_face) {
      EXPECT_GT(c.holder_force_N, 0.0);
    }
  }
  EXPECT_EQ(checked, 6);  // 3 punch nodes less the axis node, 4 flange nodes
  EXPECT_EQ(sc.tools.back().name, "holder");
  EXPECT_GT(die, 0);
}

// ---------------------------------------------------------------------------------------------
// 3D model.

using shell3d::FormingModel;
using shell3d::FormingState;
using shell3d::FormingSystem;

Eigen::MatrixXd dense(const SparseMatrix& K) {
  Eigen::MatrixXd d = Eigen::MatrixXd(K);
  // Stored as the full matrix or as its lower triangle (the Cholesky solvers read the lower one).
  if (d.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().norm() == 0.0) {
    d = d.selfadjointView<Eigen::Lower>();
  }
  return d;
}

struct Shell3dSetup {
  Scene sc;
  std::vector<int> punch_nodes, flange_nodes;
};

// The deep-drawing quarter disc (punch, die, force holder, Coulomb friction on every tool) on 2
// divisions: punch contact at the nodes within 8 mm of the axis that are off the symmetry planes,
// the die face at the nodes beyond 0.9 of the radius.
void touch(const FormingModel& m, FormingState* s, Shell3dSetup* setup) {
  const int die = m.die_index();
  double rmax = 0.0;
  for (int i = 0; i < m.num_nodes(); ++i)
    rmax = std::max(rmax, m.initial_position(i).head<2>().norm());
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Eigen::Vector3d& p = m.initial_position(i);
    const double r = p.head<2>().norm();
    if (!m.contact_eligible(i) || m.on_axis(i)) continue;
    if (r < 0.4 * rmax && p.x() > 1e-9 && p.y() > 1e-9) {
      s->contact[i].tool = m.punch_index();
      s->contact[i].normal = Eigen::Vector3d::UnitZ();
      s->contact[i].normal_force_N = 20.0 + r;
      setup->punch_nodes.push_back(i);
    } else if (r > 0.9 * rmax) {
      s->contact[i].tool = die;
      s->contact[i].normal = -Eigen::Vector3d::UnitZ();
      s->contact[i].on_die_face = true;
      s->contact[i].normal_force_N = 15.0;
      setup->flange_nodes.push_back(i);
    }
  }
  m.update_holder(s);
}

Eigen::VectorXd shell_velocity(const FormingModel& m, double v0) {
  Eigen::VectorXd x(m.num_dofs());
  const double speed = m.scene().process.punch_speed_mm_per_s;
  for (int k = 0; k < x.size(); ++k) x(k) = speed * 0.2 * std::sin(1.3 * k + 0.4);
  for (int i = 0; i < m.num_nodes(); ++i) {
    if (m.initial_position(i).head<2>().norm() < 1e-9) continue;
    const int d = m.shell_model().dof(i, 0);
    x(d) = v0 * (1.2 * std::sin(0.9 * i) + 0.3);
    x(d + 1) = v0 * (0.8 * std::cos(1.1 * i) - 0.2);
  }
  for (int k = 0; k < x.size(); ++k) {
    if (m.prescribed_mask()[static_cast<std::size_t>(k)])
      x(k) = m.prescribed_value()[static_cast<std::size_t>(k)];
  }
  return x;
}

class Shell3dModelFd : public ::testing::TestWithParam<FrictionSurface> {
 protected:
  Shell3dModelFd() : setup_{scene("ex2_quarter_disc_deep_drawing_3d"), {}, {}} {
    setup_.sc.blank.divisions = 2;
    setup_.sc.numerics.friction_surface = GetParam();
    setup_.sc.tools.at(0).friction = 0.2;
    m_ = std::make_unique<FormingModel>(setup_.sc);
    s_ = m_->initial_state();
    m_->place_tools(s_);
    for (std::size_t i = 0; i < s_.x.size(); ++i)
      s_.x[i].z() += 0.02 * std::sin(0.5 * static_cast<double>(i));
    m_->freeze_material(s_, 0.01);
    touch(*m_, &s_, &setup_);
    m_->prepare(s_);
    v0_ = setup_.sc.numerics.friction_regularisation * setup_.sc.process.punch_speed_mm_per_s;
    x_ = shell_velocity(*m_, v0_);
  }
  // The central-difference points of unknown j, x_ -+ h e_j with h = 1e-3 v0; returns h.
  double central_points(int j, Eigen::VectorXd* xm, Eigen::VectorXd* xp) const {
    const double h = 1e-3 * v0_;
    *xm = x_;
    *xp = x_;
    (*xm)(j) -= h;
    (*xp)(j) += h;
    return h;
  }
  Shell3dSetup setup_;
  std::unique_ptr<FormingModel> m_;
  FormingState s_;
  double v0_ = 0.0;
  Eigen::VectorXd x_;
};

// The friction force on each contact node, from the residual with and without its normal force,
// is mu N 2/pi atan(|s|/v0) along the slip s (the tools move along z, the nodal frame's third
// axis is the contact normal: s is the node's first two local velocities); the die-face nodes add
// the holder's coefficient times their share of the holder force.
TEST_P(Shell3dModelFd, FrictionForceIsTheClosedFormAlongTheSlip) {
  ASSERT_GE(setup_.punch_nodes.size(), 2u);
  ASSERT_GE(setup_.flange_nodes.size(), 2u);
  FormingSystem with, without;
  m_->evaluate(s_, x_, shell3d::Shell9Stiffness::kNone, 0.0, &with);
  FormingState bare = s_;
  for (auto& c : bare.contact) {
    c.normal_force_N = 0.0;
    c.holder_force_N = 0.0;
  }
  m_->evaluate(bare, x_, shell3d::Shell9Stiffness::kNone, 0.0, &without);
  const double pi = std::numbers::pi;
  double holder_total = 0.0;
  for (int i : setup_.flange_nodes) holder_total += s_.contact[i].holder_force_N;
  // The meshed quarter carries a quarter of the whole-blank holder force.
  EXPECT_NEAR(holder_total, setup_.sc.tools.back().force_N / 4.0, 1e-9 * holder_total);
  std::vector<int> nodes = setup_.punch_nodes;
  nodes.insert(nodes.end(), setup_.flange_nodes.begin(), setup_.flange_nodes.end());
  for (int i : nodes) {
    const auto& c = s_.contact[i];
    const int d = m_->shell_model().dof(i, 0);
    const Eigen::Vector2d slip(x_(d), x_(d + 1));
    double limit = setup_.sc.tools.at(static_cast<std::size_t>(c.tool)).friction * c.normal_force_N;
    if (c.on_die_face) limit += setup_.sc.tools.back().friction * c.holder_force_N;
    const Eigen::Vector2d f = limit * 2.0 / pi * std::atan(slip.norm() / v0_) * slip.normalized();
    for (int p = 0; p < 2; ++p) {
      if (m_->prescribed_mask()[static_cast<std::size_t>(d + p)]) continue;
      EXPECT_NEAR(with.residual(d + p) - without.residual(d + p), f(p), 1e-9 * limit)
          << "node " << i << " component " << p;
    }
  }
  // Its potential: L 2/pi (|s| atan(|s|/v0) - v0/2 ln(1 + |s|^2/v0^2)) summed over the nodes.
  double phi = 0.0;
  for (int i : nodes) {
    const auto& c = s_.contact[i];
    const int d = m_->shell_model().dof(i, 0);
    const double a = Eigen::Vector2d(x_(d), x_(d + 1)).norm() / v0_;
    double limit = setup_.sc.tools.at(static_cast<std::size_t>(c.tool)).friction * c.normal_force_N;
    if (c.on_die_face) limit += setup_.sc.tools.back().friction * c.holder_force_N;
    phi += limit * 2.0 / pi * v0_ * (a * std::atan(a) - 0.5 * std::log1p(a * a));
  }
  EXPECT_NEAR(with.potential - without.potential, phi, 1e-9 * std::abs(phi));
}

// Residual = gradient of the potential; the consistent matrix = derivative of the residual; the
// friction stiffness (difference of the matrices with and without normal forces) = derivative
// of the friction force.
TEST_P(Shell3dModelFd, ResidualPotentialAndTangentAgreeWithFiniteDifferences) {
  const int n = m_->num_dofs();
  const auto& mask = m_->prescribed_mask();
  auto tangent = [&](const FormingState& s, FormingSystem* out) {
    for (int k = 0; k < 3; ++k) m_->evaluate(s, x_, shell3d::Shell9Stiffness::kTangent, 1.0, out);
    return dense(m_->matrix());
  };
  FormingState bare = s_;
  for (auto& c : bare.contact) {
    c.normal_force_N = 0.0;
    c.holder_force_N = 0.0;
  }
  FormingSystem sys, sys_bare, sys_consistent;
  const Eigen::MatrixXd K = tangent(s_, &sys);
  const Eigen::MatrixXd K_bare = tangent(bare, &sys_bare);
  m_->set_primal_dual(false);
  const Eigen::MatrixXd K_consistent = tangent(s_, &sys_consistent);
  m_->set_primal_dual(true);
  double c_err = 0.0;
  double k_scale = 0.0, k_err = 0.0, f_scale = 0.0, f_err = 0.0, r_scale = 0.0, g_err = 0.0;
  for (int j = 0; j < n; ++j) {
    if (mask[static_cast<std::size_t>(j)]) continue;
    Eigen::VectorXd xm, xp;
    const double h = central_points(j, &xm, &xp);
    FormingSystem p, q, pb, qb;
    m_->evaluate(s_, xp, shell3d::Shell9Stiffness::kNone, 0.0, &p);
    m_->evaluate(s_, xm, shell3d::Shell9Stiffness::kNone, 0.0, &q);
    m_->evaluate(bare, xp, shell3d::Shell9Stiffness::kNone, 0.0, &pb);
    m_->evaluate(bare, xm, shell3d::Shell9Stiffness::kNone, 0.0, &qb);
    const Eigen::VectorXd col = (p.residual - q.residual) / (2 * h);
    const Eigen::VectorXd fcol = col - (pb.residual - qb.residual) / (2 * h);
    const double g = (p.potential - q.potential) / (2 * h);
    r_scale = std::max(r_scale, std::abs(sys.residual(j)));
    g_err = std::max(g_err, std::abs(g - sys.residual(j)));
    for (int i = 0; i < n; ++i) {
      if (mask[static_cast<std::size_t>(i)]) continue;
      k_scale = std::max(k_scale, std::abs(col(i)));
      k_err = std::max(k_err, std::abs(K(i, j) - col(i)));
      c_err = std::max(c_err, std::abs(K_consistent(i, j) - col(i)));
      f_scale = std::max(f_scale, std::abs(fcol(i)));
      f_err = std::max(f_err, std::abs(K(i, j) - K_bare(i, j) - fcol(i)));
    }
  }
  EXPECT_GT(f_scale, 0.0);
  EXPECT_LT(g_err, 1e-6 * r_scale) << "max |dP/dx - r| " << g_err << " of " << r_scale;
  EXPECT_LT(f_err, 1e-6 * f_scale) << "friction stiffness: " << f_err << " of " << f_scale;
  // The whole consistent matrix (set_primal_dual(false)) is dr/dx: elements (MITC9, flow points,
  // hardening viscosity, transverse shear, drilling), friction, holder (measured 31 of 7.5e6, the
  // central differences' own error).
  EXPECT_LT(c_err, 1e-5 * k_scale)
      << "consistent tangent: max |K - dr/dx| " << c_err << " of " << k_scale;
  // Not asserted: the primal-dual matrix (the default) against dr/dx. Its rank-one part follows
  // the dual history and not this iterate (measured after three evaluations at x: max |K - dr/dx|
  // = 1.3 max |dr/dx|). Printed for the record.
  fmt::print("3D model: max |K - dr/dx| {:.3g} of {:.3g} (primal-dual element tangent)\n", k_err,
             k_scale);
}

// The implicit update's geometry coupling (FormingModel::add_coupling) acts on the nodes'
// mid-surface velocities: its potential is (1/2) sum_ab (v_a - v_ref,a) . k_ab (v_b - v_ref,b)
// with v the global velocities of to_global() (with friction_surface = face, the map from the
// face unknowns back to the mid-surface, G = Q [I, -C]) and k the element's membrane
// initial-stress stiffness times the scale, summed over the elements; its force is the
// potential's gradient.
TEST_P(Shell3dModelFd, GeometryCouplingActsOnTheMidSurfaceVelocities) {
  const FormingModel& m = *m_;
  const int ne = m.num_elements();
  const int np = shell3d::shell9_inplane_points(shell3d::Shell9Rule::kMitc9);
  shell3d::GeometryCoupling3 coupling;
  coupling.scale_s = 0.01;
  coupling.membrane.assign(static_cast<std::size_t>(ne), {});
  for (int e = 0; e < ne; ++e) {
    for (int p = 0; p < np; ++p) {
      shell3d::Mat3 N = shell3d::Mat3::Zero();
      N(0, 0) = 80.0 + 5.0 * p;
      N(1, 1) = 60.0 + 3.0 * e;
      N(0, 1) = N(1, 0) = 10.0;
      coupling.membrane[static_cast<std::size_t>(e)].push_back(N);
    }
  }
  coupling.v_ref.resize(static_cast<std::size_t>(m.num_nodes()));
  for (int i = 0; i < m.num_nodes(); ++i)
    coupling.v_ref[static_cast<std::size_t>(i)] = shell3d::Vec3(0.1 * std::sin(i), 0.0, 0.5);
  FormingSystem without, with;
  m_->evaluate(s_, x_, shell3d::Shell9Stiffness::kNone, 0.0, &without);
  m_->set_geometry_coupling(&coupling);
  m_->prepare(s_);
  m_->evaluate(s_, x_, shell3d::Shell9Stiffness::kNone, 0.0, &with);
  std::vector<shell3d::Vec3> v, w;
  m.to_global(x_, &v, &w);
  double expected = 0.0;
  for (int e = 0; e < ne; ++e) {
    const auto& conn = m.mesh().elements[static_cast<std::size_t>(e)];
    const Eigen::Matrix<double, 9, 9> k =
        coupling.scale_s *
        shell3d::shell9_stress_stiffness(m.geometry(s_, e), shell3d::Shell9Rule::kMitc9,
                                         coupling.membrane[static_cast<std::size_t>(e)]);
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b) {
        const auto ia = static_cast<std::size_t>(conn[static_cast<std::size_t>(a)]);
        const auto ib = static_cast<std::size_t>(conn[static_cast<std::size_t>(b)]);
        expected += 0.5 * k(a, b) * (v[ia] - coupling.v_ref[ia]).dot(v[ib] - coupling.v_ref[ib]);
      }
  }
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(with.potential - without.potential, expected, 1e-9 * expected);
  // Its force is the potential's gradient (at the free unknowns).
  const int n = m.num_dofs();
  const auto& mask = m.prescribed_mask();
  double scale = 0.0, err = 0.0;
  for (int j = 0; j < n; ++j) {
    if (mask[static_cast<std::size_t>(j)]) continue;
    Eigen::VectorXd xm, xp;
    const double h = central_points(j, &xm, &xp);
    FormingSystem p, q;
    m_->evaluate(s_, xp, shell3d::Shell9Stiffness::kNone, 0.0, &p);
    m_->evaluate(s_, xm, shell3d::Shell9Stiffness::kNone, 0.0, &q);
    scale = std::max(scale, std::abs(with.residual(j)));
    err = std::max(err, std::abs((p.potential - q.potential) / (2 * h) - with.residual(j)));
  }
  EXPECT_LT(err, 1e-6 * scale);
  // Its matrix is the derivative of its force (the force is linear in x: the difference of the
  // matrices with and without the coupling against central differences of the residuals; the
  // consistent element tangent, which has no history, in both).
  m_->set_primal_dual(false);
  auto matrix = [&](FormingSystem* out) {
    m_->evaluate(s_, x_, shell3d::Shell9Stiffness::kTangent, 1.0, out);
    return dense(m_->matrix());
  };
  FormingSystem sys_with, sys_without;
  const Eigen::MatrixXd K_with = matrix(&sys_with);
  m_->set_geometry_coupling(nullptr);
  m_->prepare(s_);
  const Eigen::MatrixXd K_without = matrix(&sys_without);
  m_->set_geometry_coupling(&coupling);
  m_->prepare(s_);
  double k_scale = 0.0, k_err = 0.0;
  for (int j = 0; j < n; ++j) {
    if (mask[static_cast<std::size_t>(j)]) continue;
    // A step 1 000 times the other tests': the coupling is linear in x (no truncation error),
    // the elements' force is the same at the same x with and without it (it cancels), and what
    // is left is the round-off of the sums, relative to the step.
    Eigen::VectorXd xm = x_, xp = x_;
    const double h = 1e3 * central_points(j, &xm, &xp);
    xm(j) = x_(j) - h;
    xp(j) = x_(j) + h;
    FormingSystem p, q, pb, qb;
    m_->evaluate(s_, xp, shell3d::Shell9Stiffness::kNone, 0.0, &p);
    m_->evaluate(s_, xm, shell3d::Shell9Stiffness::kNone, 0.0, &q);
    m_->set_geometry_coupling(nullptr);
    m_->prepare(s_);
    m_->evaluate(s_, xp, shell3d::Shell9Stiffness::kNone, 0.0, &pb);
    m_->evaluate(s_, xm, shell3d::Shell9Stiffness::kNone, 0.0, &qb);
    m_->set_geometry_coupling(&coupling);
    m_->prepare(s_);
    const Eigen::VectorXd col = (p.residual - q.residual - pb.residual + qb.residual) / (2 * h);
    for (int i = 0; i < n; ++i) {
      if (mask[static_cast<std::size_t>(i)]) continue;
      k_scale = std::max(k_scale, std::abs(col(i)));
      k_err = std::max(k_err, std::abs(K_with(i, j) - K_without(i, j) - col(i)));
    }
  }
  ASSERT_GT(k_scale, 0.0);
  EXPECT_LT(k_err, 1e-6 * k_scale) << "coupling matrix: " << k_err << " of " << k_scale;
  m_->set_primal_dual(true);
  m_->set_geometry_coupling(nullptr);
}

INSTANTIATE_TEST_SUITE_P(MidAndFace, Shell3dModelFd,
                         ::testing::Values(FrictionSurface::kMid, FrictionSurface::kFace));

}  // namespace
}  // namespace vs
