// The fixed-gap blank holder of the 3D forming model (model/gap_holder3.h): the surface
// divergence operator against closed forms and the area rate of the interpolated surface, the
// penalty's force, matrix and nodal holder forces, and the ESAFORM cup (quarter blank, a few mm)
// with the holder keeping the flange at the gap, against the axisymmetric solver.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/axisym_comparison.h"
#include "element/lagrange9.h"
#include "model/gap_holder3.h"
#include "model/ironing.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

// A curved, distorted 9-node element: the square [0, 4] x [0, 3] with its nodes moved off the
// grid and lifted onto a doubly curved surface.
std::array<Vec3, 9> curved_element() {
  std::array<Vec3, 9> x;
  for (int a = 0; a < 9; ++a) {
    const auto rs = lagrange9_node(a);
    const double u = 2.0 + 2.0 * rs[0] + 0.3 * rs[0] * rs[1];
    const double v = 1.5 + 1.5 * rs[1] + 0.2 * rs[0] * rs[0];
    x[static_cast<std::size_t>(a)] = Vec3(u, v, 0.05 * u * u - 0.03 * u * v + 0.04 * v * v);
  }
  return x;
}

double area_jacobian(const std::array<Vec3, 9>& x, double r, double s) {
  double J = 0.0;
  surface_divergence(x, r, s, &J);
  return J;
}

TEST(GapHolderOperator, UniformInPlaneStretchOfAFlatSheetIsTwiceTheRate) {
  std::array<Vec3, 9> x = curved_element();
  for (Vec3& p : x) p.z() = 0.0;
  const double c = 0.37;  // v = c (x, y, 0): area rate 2 c
  for (double r : {-1.0, -0.3, 0.5, 1.0})
    for (double s : {-1.0, 0.2, 1.0}) {
      const Eigen::Matrix<double, 9, 3> b = surface_divergence(x, r, s);
      double div = 0.0;
      for (int a = 0; a < 9; ++a) {
        div += b.row(a).dot(c * Vec3(x[a].x(), x[a].y(), 0.0));
      }
      EXPECT_NEAR(div, 2.0 * c, 1e-12) << r << " " << s;
      // A uniform normal velocity does not change a flat sheet's area.
      double normal = 0.0;
      for (int a = 0; a < 9; ++a) normal += b.row(a).dot(Vec3(0.0, 0.0, 1.3));
      EXPECT_NEAR(normal, 0.0, 1e-12);
    }
}

TEST(GapHolderOperator, RigidMotionOfACurvedElementHasNoAreaRate) {
  const std::array<Vec3, 9> x = curved_element();
  const Vec3 omega(0.3, -1.1, 0.7), velocity(2.0, -0.5, 1.5);
  for (double r : {-1.0, 0.0, 0.6})
    for (double s : {-0.4, 1.0}) {
      const Eigen::Matrix<double, 9, 3> b = surface_divergence(x, r, s);
      double div = 0.0;
      for (int a = 0; a < 9; ++a) div += b.row(a).dot(velocity + omega.cross(x[a]));
      EXPECT_NEAR(div, 0.0, 1e-12);
    }
}

TEST(GapHolderOperator, IsTheRateOfTheAreaJacobian) {
  // dJ/dt = J div_s v for any nodal velocities: central differences of J along a velocity field.
  const std::array<Vec3, 9> x = curved_element();
  std::array<Vec3, 9> v;
  for (int a = 0; a < 9; ++a) {
    v[a] = Vec3(std::sin(1.0 + a), std::cos(2.0 * a), 0.5 * std::sin(3.0 * a + 0.2));
  }
  const double t = 1e-6;
  for (int a = 0; a < 9; ++a) {
    const auto rs = lagrange9_node(a);
    std::array<Vec3, 9> xp = x, xm = x;
    for (int b = 0; b < 9; ++b) {
      xp[b] += t * v[b];
      xm[b] -= t * v[b];
    }
    double J = 0.0;
    const Eigen::Matrix<double, 9, 3> B = surface_divergence(x, rs[0], rs[1], &J);
    double div = 0.0;
    for (int b = 0; b < 9; ++b) div += B.row(b).dot(v[b]);
    const double rate =
        (area_jacobian(xp, rs[0], rs[1]) - area_jacobian(xm, rs[0], rs[1])) / (2.0 * t * J);
    EXPECT_NEAR(div, rate, 1e-7 * (1.0 + std::abs(rate))) << a;
  }
}

TEST(GapHolderOperator, AreaSharesSumToTheArea) {
  std::array<Vec3, 9> x = curved_element();
  for (Vec3& p : x) p.z() = 0.0;
  const std::array<double, 9> share = element_area_shares(x);
  double sum = 0.0;
  for (double a : share) sum += a;
  // The plane element's area: 3 x 3 Gauss against a 200 x 200 midpoint sum.
  double fine = 0.0;
  const int n = 200;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double r = -1.0 + (2.0 * i + 1.0) / n, s = -1.0 + (2.0 * j + 1.0) / n;
      fine += area_jacobian(x, r, s) * (2.0 / n) * (2.0 / n);
    }
  EXPECT_NEAR(sum, fine, 1e-4 * fine);
  for (double a : share) EXPECT_GT(a, 0.0);
}

// One flat element of the flange, all nodes in the gap at thickness h, frames the identity.
struct OneElement {
  ShellMesh mesh;
  std::vector<Vec3> x;
  std::vector<double> thickness, viscosity{2.0};
  std::vector<char> in_gap;
  std::vector<Mat3> frame;
  GapHolder3 holder;
  OneElement(double h, double gap, double dt, char gap_flag = 1) {
    const std::array<Vec3, 9> xe = curved_element();
    mesh.elements.push_back({0, 1, 2, 3, 4, 5, 6, 7, 8});
    for (const Vec3& p : xe) {
      mesh.nodes.push_back(Vec3(p.x(), p.y(), 0.0));
      x.push_back(mesh.nodes.back());
    }
    thickness.assign(9, h);
    in_gap.assign(9, gap_flag);
    in_gap[8] = 1;
    // Nodal frames: a rotation about z (the solver's cylindrical frames on the flange).
    for (int a = 0; a < 9; ++a) {
      frame.push_back(Eigen::AngleAxisd(0.3 * a, Vec3::UnitZ()).toRotationMatrix());
    }
    GapHolderInput in;
    in.mesh = &mesh;
    in.x = &x;
    in.thickness = &thickness;
    in.in_gap = &in_gap;
    in.frame = &frame;
    in.viscosity = &viscosity;
    in.gap_mm = gap;
    in.dt_s = dt;
    holder.prepare(in);
  }
  // Element dofs (5 per node) of global nodal velocities.
  Eigen::VectorXd dofs(const std::vector<Vec3>& v) const {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(45);
    for (int a = 0; a < 9; ++a) q.segment<3>(5 * a) = frame[a].transpose() * v[a];
    return q;
  }
  ElementContribution evaluate(const Eigen::VectorXd& q) const {
    ElementContribution c;
    c.force = Eigen::VectorXd::Zero(45);
    c.stiffness = Eigen::MatrixXd::Zero(45, 45);
    holder.add(0, q, true, &c);
    return c;
  }
};

std::vector<Vec3> uniform_stretch(const std::vector<Vec3>& x, double c) {
  std::vector<Vec3> v;
  for (const Vec3& p : x) v.push_back(c * Vec3(p.x(), p.y(), 0.0));
  return v;
}

TEST(GapHolderPenalty, ThickeningAtTheGapIsResistedByThePressureTimesTheArea) {
  // At the gap (h = g) a uniform in-plane compression v = -c (x, y) thickens the sheet at the
  // rate 2 c: every node violates its bound by 2 c, the pressure is p = k 2 c with k = 1e3 times
  // the viscosity, and the nodal holder forces add up to p times the element's area.
  const double c = 0.01, dt = 0.1;
  const OneElement one(1.04, 1.04, dt);
  const Eigen::VectorXd q = one.dofs(uniform_stretch(one.x, -c));
  const std::vector<double> f = one.holder.nodal_forces(9, [&](int) { return q; });
  const std::array<double, 9> share = element_area_shares(
      {one.x[0], one.x[1], one.x[2], one.x[3], one.x[4], one.x[5], one.x[6], one.x[7], one.x[8]});
  double area = 0.0, total = 0.0;
  for (int a = 0; a < 9; ++a) {
    area += share[a];
    total += f[a];
    EXPECT_NEAR(f[a], 1e3 * 2.0 * 2.0 * c * share[a], 1e-9 * total + 1e-12) << a;
  }
  EXPECT_NEAR(total, 1e3 * 2.0 * 2.0 * c * area, 1e-9 * total);
  // Stretching (thinning) instead: nothing to resist.
  const Eigen::VectorXd thin = one.dofs(uniform_stretch(one.x, c));
  for (double v : one.holder.nodal_forces(9, [&](int) { return thin; })) EXPECT_EQ(v, 0.0);
  // Below the gap the sheet may thicken by ln(g / h) over the step before the holder acts.
  const double h = 1.0;
  const OneElement below(h, 1.04, dt);
  const double free_rate = std::log(1.04 / h) / dt / 2.0;  // c with 2 c dt = ln(g / h)
  const Eigen::VectorXd slow = below.dofs(uniform_stretch(below.x, -0.99 * free_rate));
  for (double v : below.holder.nodal_forces(9, [&](int) { return slow; })) EXPECT_EQ(v, 0.0);
  const Eigen::VectorXd fast = below.dofs(uniform_stretch(below.x, -1.01 * free_rate));
  for (double v : below.holder.nodal_forces(9, [&](int) { return fast; })) EXPECT_GT(v, 0.0);
}

TEST(GapHolderPenalty, ForceAndMatrixAreDerivativesOfThePotential) {
  const OneElement one(1.04, 1.04, 0.1);
  Eigen::VectorXd q = one.dofs(uniform_stretch(one.x, -0.02));
  for (int k = 0; k < 45; ++k) q(k) += 1e-3 * std::sin(0.7 * k);  // a generic field
  const ElementContribution c0 = one.evaluate(q);
  ASSERT_GT(c0.potential, 0.0);
  const double t = 1e-7;
  for (int k = 0; k < 45; ++k) {
    Eigen::VectorXd qp = q, qm = q;
    qp(k) += t;
    qm(k) -= t;
    const ElementContribution cp = one.evaluate(qp), cm = one.evaluate(qm);
    EXPECT_NEAR(c0.force(k), (cp.potential - cm.potential) / (2.0 * t),
                1e-6 * (1.0 + std::abs(c0.force(k))))
        << k;
    const Eigen::VectorXd column = (cp.force - cm.force) / (2.0 * t);
    EXPECT_LT((c0.stiffness.col(k) - column).norm(), 1e-5 * (1.0 + column.norm())) << k;
  }
  // Rotation dofs (3, 4 of each node) take no part.
  for (int a = 0; a < 9; ++a) {
    EXPECT_EQ(c0.force(5 * a + 3), 0.0);
    EXPECT_EQ(c0.force(5 * a + 4), 0.0);
  }
}

TEST(GapHolderPenalty, ANodeOutsideTheGapPassesItsForceToTheNodesInTheGap) {
  // Only the centre node in the gap: the element is constrained at every node, and the holder
  // force of all nine goes to the centre.
  const double c = 0.01;
  const OneElement edge(1.04, 1.04, 0.1, 0);
  const OneElement all(1.04, 1.04, 0.1, 1);
  const Eigen::VectorXd q = edge.dofs(uniform_stretch(edge.x, -c));
  const std::vector<double> f_edge = edge.holder.nodal_forces(9, [&](int) { return q; });
  const std::vector<double> f_all = all.holder.nodal_forces(9, [&](int) { return q; });
  double total = 0.0;
  for (double v : f_all) total += v;
  for (int a = 0; a < 8; ++a) EXPECT_EQ(f_edge[a], 0.0);
  EXPECT_NEAR(f_edge[8], total, 1e-12 * total);
}

// --- ironing between two tools (the penalty's ironing form; FormingModel::update_squeezed)

// One flat element squeezed at every node, thickness h, clearance g at node 8 and 1.2 mm
// elsewhere (the element's gap is the smallest), overshoot cap and correction as given.
struct OneIronedElement {
  ShellMesh mesh;
  std::vector<Vec3> x;
  std::vector<double> thickness, viscosity{2.0}, clearance;
  std::vector<char> squeezed;
  std::vector<Mat3> frame;
  GapHolder3 penalty;
  OneIronedElement(double h, double g, double dt, double cap, double correction) {
    const std::array<Vec3, 9> xe = curved_element();
    mesh.elements.push_back({0, 1, 2, 3, 4, 5, 6, 7, 8});
    for (const Vec3& p : xe) {
      mesh.nodes.push_back(Vec3(p.x(), p.y(), 0.0));
      x.push_back(mesh.nodes.back());
      frame.push_back(Mat3::Identity());
    }
    thickness.assign(9, h);
    clearance.assign(9, 1.2);
    clearance[8] = g;
    squeezed.assign(9, 1);
    GapHolderInput in;
    in.mesh = &mesh;
    in.x = &x;
    in.thickness = &thickness;
    in.in_gap = &squeezed;
    in.frame = &frame;
    in.viscosity = &viscosity;
    in.dt_s = dt;
    in.node_gap = &clearance;
    in.max_log_ratio = cap;
    in.correction = correction;
    penalty.prepare(in);
  }
  // Total squeeze force under the uniform in-plane stretch v = c (x, y, 0) (area rate 2 c).
  double force(double c) const {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(45);
    for (int a = 0; a < 9; ++a) q.segment<3>(5 * a) = c * Vec3(x[a].x(), x[a].y(), 0.0);
    double total = 0.0;
    for (double f : penalty.nodal_forces(9, [&](int) { return q; })) total += f;
    return total;
  }
};

TEST(IroningPenalty, AnOvershootIsIronedAtTheCappedAndCorrectedRate) {
  // h = 1.25 in a clearance g = 1.15 (the smallest of the element's, 1.2 elsewhere): the area
  // rate must reach c = min(ln(h / g), cap) correction / dt, and the penalty pushes with
  // k (c - 2 c0) on every node's volume below it: zero force just above, a force just below.
  const double h = 1.25, g = 1.15, dt = 0.05;
  const double log_ratio = std::log(h / g);  // 0.0834
  struct Case {
    double cap, correction;
  };
  for (const Case& k : {Case{1.0, 1.0}, Case{0.05, 1.0}, Case{0.05, 0.25}, Case{1.0, 0.5}}) {
    const OneIronedElement one(h, g, dt, k.cap, k.correction);
    ASSERT_FALSE(one.penalty.empty());
    const double bound = std::min(log_ratio, k.cap) * k.correction / dt;
    EXPECT_EQ(one.force(0.5 * bound * 1.001), 0.0) << k.cap << " " << k.correction;
    EXPECT_GT(one.force(0.5 * bound * 0.999), 0.0) << k.cap << " " << k.correction;
    // Linear in the violation: k V (bound - 2 c) summed, with V = h times the element's area.
    const double f1 = one.force(0.25 * bound), f2 = one.force(0.0);
    EXPECT_NEAR(f2 / f1, 2.0, 1e-9);
  }
  // A node below its clearance (h < g): thickening is allowed up to ln(g / h) over the step, as
  // the fixed-gap holder; thinning is never resisted.
  const OneIronedElement thin(1.1, 1.15, dt, 1.0, 1.0);
  const double allowed = (std::log(1.1 / 1.15) - kIroningSlack) / dt;  // < 0
  EXPECT_EQ(thin.force(0.5 * allowed * 0.999), 0.0);
  EXPECT_GT(thin.force(0.5 * allowed * 1.001), 0.0);
  EXPECT_EQ(thin.force(1.0), 0.0);
}

TEST(IroningTarget, CorrectsAnOvershootBeyondTheToleranceOnly) {
  // Below the clearance: thickening up to it over the step (unscaled); at it and within the
  // tolerance above it: only kept from thickening.
  EXPECT_DOUBLE_EQ(ironing_log_target(1.1, 1.2, 0.05, 0.5, kIroningTolerance),
                   std::log(1.1 / 1.2) - kIroningSlack);
  EXPECT_EQ(ironing_log_target(1.2, 1.2, 0.05, 0.5, kIroningTolerance), -kIroningSlack);
  const double inside = 1.2 * (1.0 + 0.5 * kIroningTolerance);
  EXPECT_EQ(ironing_log_target(inside, 1.2, 0.05, 0.5, kIroningTolerance), -kIroningSlack);
  EXPECT_LT(kIroningSlack, 1e-3 * kIroningTolerance);
  // Beyond it: the whole overshoot, capped, times the correction.
  const double h = 1.2 * (1.0 + 2.0 * kIroningTolerance);
  EXPECT_DOUBLE_EQ(ironing_log_target(h, 1.2, 0.05, 0.5, kIroningTolerance),
                   0.5 * std::log(h / 1.2));
  EXPECT_DOUBLE_EQ(ironing_log_target(1.4, 1.2, 0.05, 0.5, kIroningTolerance), 0.5 * 0.05);
  // Tolerance 0 (the axisymmetric model): min(ln(h / g), cap) correction everywhere.
  EXPECT_DOUBLE_EQ(ironing_log_target(1.1, 1.2, 0.05, 0.5, 0.0), 0.5 * std::log(1.1 / 1.2));
  EXPECT_DOUBLE_EQ(ironing_log_target(1.21, 1.2, 0.05, 0.5, 0.0), 0.5 * std::log(1.21 / 1.2));
}

TEST(IroningPenalty, NoSqueezedNodeNoConstraint) {
  OneIronedElement one(1.25, 1.15, 0.05, 1.0, 1.0);
  one.squeezed.assign(9, 0);
  GapHolderInput in;
  in.mesh = &one.mesh;
  in.x = &one.x;
  in.thickness = &one.thickness;
  in.in_gap = &one.squeezed;
  in.frame = &one.frame;
  in.viscosity = &one.viscosity;
  in.dt_s = 0.05;
  in.node_gap = &one.clearance;
  in.max_log_ratio = 1.0;
  one.penalty.prepare(in);
  EXPECT_TRUE(one.penalty.empty());
  EXPECT_EQ(one.force(-1.0), 0.0);
}

// --- the ESAFORM cup, quarter blank, a few mm

constexpr double kGapMm = 1.04;
constexpr double kTravelMm = 14.0;
constexpr int kTwinElements = 50;  // 1.08 mm meridian elements (the bundled fixed-gap scene's)

Scene cup_3d(double gap_mm) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/esaform_cup_3d_quarter.toml");
  s.blank.divisions = 4;
  s.numerics.max_travel_increment_mm =
      0.25;  // the default grid, on which the figures were measured
  s.process.punch_travel_mm = kTravelMm;
  s.process.output_travels_mm = {kTravelMm};
  for (ToolSpec& t : s.tools)
    if (t.kind == ToolKind::kBlankHolder) t.gap_mm = gap_mm;
  return s;
}

// Largest thickness of the flange: nodes flat on the die face (|z| < 0.1 mm, as
// tests/system/fixed_gap_holder_test.cc) outside the start of its flat face (41.2 mm).
double flange_max_thickness(const ShellStage& st) {
  double h = 0.0;
  for (std::size_t i = 0; i < st.x.size(); ++i) {
    if (std::abs(st.x[i].z()) < 0.1 && std::hypot(st.x[i].x(), st.x[i].y()) > 41.5) {
      h = std::max(h, st.thickness_mm[i]);
    }
  }
  return h;
}

// Initial minus current radius of the edge node on the symmetry line y = 0.
double draw_in_along_y0(const RunResult& r) {
  for (int node : r.shell->mesh.set("edge")) {
    const Eigen::Vector3d& p0 = r.shell->mesh.nodes[node];
    if (std::abs(p0.y()) > 1e-9 * p0.norm()) continue;
    const Eigen::Vector3d& x = r.shell->stages.back().x[node];
    return p0.norm() - std::hypot(x.x(), x.y());
  }
  ADD_FAILURE() << "no edge node on y = 0";
  return 0.0;
}

const RunResult& cup_run(double gap_mm) {
  static const RunResult at_gap = simulate_shell3d(cup_3d(kGapMm));
  static const RunResult wide = simulate_shell3d(cup_3d(2.0));
  return gap_mm == kGapMm ? at_gap : wide;
}

TEST(Forming3dGapHolder, FlangeThickensUpToTheGapAndNoFurther) {
  const RunResult& held = cup_run(kGapMm);
  const RunResult& free = cup_run(2.0);
  ASSERT_TRUE(held.completed()) << held.message;
  ASSERT_TRUE(free.completed()) << free.message;
  const double h_held = flange_max_thickness(held.shell->stages.back());
  const double h_free = flange_max_thickness(free.shell->stages.back());
  std::printf("flange max thickness at %.0f mm: gap %.2f mm %.5f mm, gap 2 mm %.5f mm\n", kTravelMm,
              kGapMm, h_held, h_free);
  // Held at the gap within the axisymmetric test's tolerance (the penalty lets ~1e-3 of a step's
  // strain through), and reached it; with a gap the flange never fills it thickens beyond.
  EXPECT_LE(h_held, kGapMm * 1.002);
  EXPECT_GT(h_held, kGapMm * 0.999);
  EXPECT_GT(h_free, kGapMm * 1.01);
}

// Tolerances, from the mesh: the quarter blank on 4 divisions has its rim nodes 4.5 mm apart, and
// against the 50-element axisymmetric twin (mean punch force over the last millimetre, rim
// draw-in along y = 0, at 14 mm) it deviates by +5.6 % / -5.6 % where the holder never presses
// (gap 2 mm): the mesh error of the cup itself. With the holder at 1.04 mm +3.3 % / -4.5 %, on 6
// divisions +1.1 % / -1.6 % (93 s). So 6 % and 7 %. The holder's effect (gap 1.04 mm against 2 mm)
// is +10.0 % force / -11.8 % draw-in in the axisymmetric solver and +7.6 % / -10.7 % in 3D on 4
// divisions: the 3D effect must have the same sign and at least 0.6 of the axisymmetric one (a
// holder that did nothing would have none).
TEST(Forming3dGapHolder, QuarterCupMatchesTheAxisymmetricSolver) {
  struct Pair {
    double f3, fa, d3, da;
  };
  auto compare = [](double gap) {
    const RunResult& shell = cup_run(gap);
    const RunResult axi = simulate(axisymmetric_twin(cup_3d(gap), kTwinElements));
    EXPECT_TRUE(shell.completed()) << shell.message;
    EXPECT_TRUE(axi.completed()) << axi.message;
    Pair p{mean_force(shell.steps, kTravelMm - 1.0, kTravelMm),
           mean_force(axi.steps, kTravelMm - 1.0, kTravelMm), draw_in_along_y0(shell),
           axi.steps.back().rim_draw_in_mm};
    std::printf(
        "gap %.2f mm at %.0f mm: mean force 3D %.1f N, axisym %.1f N (%+.2f %%); draw-in "
        "3D %.4f mm, axisym %.4f mm (%+.2f %%)\n",
        gap, kTravelMm, p.f3, p.fa, 100.0 * (p.f3 / p.fa - 1.0), p.d3, p.da,
        100.0 * (p.d3 / p.da - 1.0));
    return p;
  };
  const Pair held = compare(kGapMm), free = compare(2.0);
  ASSERT_TRUE(cup_run(kGapMm).completed() && cup_run(2.0).completed());
  EXPECT_LT(std::abs(held.f3 / held.fa - 1.0), 0.06);
  EXPECT_LT(std::abs(held.d3 / held.da - 1.0), 0.07);
  const double force_axi = held.fa / free.fa - 1.0, force_3d = held.f3 / free.f3 - 1.0;
  const double draw_axi = held.da / free.da - 1.0, draw_3d = held.d3 / free.d3 - 1.0;
  EXPECT_GT(force_axi, 0.05);  // the reference's holder does act
  EXPECT_LT(draw_axi, -0.05);
  EXPECT_GT(force_3d, 0.6 * force_axi);
  EXPECT_LT(draw_3d, 0.6 * draw_axi);
}

}  // namespace
}  // namespace vs::shell3d
