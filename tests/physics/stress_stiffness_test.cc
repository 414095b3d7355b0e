// The membrane initial-stress stiffness of the implicit geometry update (element/axisym2.h,
// element/shell9.h) against closed forms: the second-order work of a membrane force on a
// displacement field, 1/2 Delta^T K Delta = 1/2 int N_ab (dDelta/dx_a).(dDelta/dx_b) dA.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "element/axisym2.h"
#include "element/lagrange9.h"
#include "element/shell9.h"

namespace vs {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(StressStiffness, AxisymRigidAxialTranslationCostsNothing) {
  const Axisym2Geometry g{10.0, 0.0, 12.0, 1.0};
  const Mat6 k = axisym2_stress_stiffness(g, 30.0, 20.0);
  Vec6 d = Vec6::Zero();
  d(1) = d(4) = 1.0;  // w at both nodes
  EXPECT_LT((k * d).norm(), 1e-12 * k.norm());
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
}

TEST(StressStiffness, AxisymMeridianRotationAndHoopStretchMatchTheirSecondOrderWork) {
  // Flat element from r = 10 to 12 (length 2, mid radius 11).
  const Axisym2Geometry g{10.0, 0.0, 12.0, 0.0};
  const double Ns = 30.0, Nt = 20.0, L = 2.0, r = 11.0;
  // Node b moves normal to the meridian by delta: (dDelta/ds)^2 = (delta / L)^2 over the
  // element: work 1/2 Ns (delta/L)^2 2 pi r L.
  const double delta = 0.1;
  Vec6 d = Vec6::Zero();
  d(4) = delta;
  EXPECT_NEAR(0.5 * d.dot(axisym2_stress_stiffness(g, Ns, 0.0) * d),
              0.5 * Ns * (delta / L) * (delta / L) * 2.0 * kPi * r * L, 1e-12);
  // Uniform radial motion u: the meridian gradient vanishes, the hoop term
  // 1/2 Nt (u / r)^2 2 pi r L.
  const double u = 0.2;
  d.setZero();
  d(0) = d(3) = u;
  EXPECT_NEAR(0.5 * d.dot(axisym2_stress_stiffness(g, Ns, Nt) * d),
              0.5 * Nt * (u / r) * (u / r) * 2.0 * kPi * r * L, 1e-12);
  // The rotation rates (beta) get nothing.
  d.setZero();
  d(2) = d(5) = 1.0;
  EXPECT_EQ((axisym2_stress_stiffness(g, Ns, Nt) * d).norm(), 0.0);
}

TEST(StressStiffness, AxisymCompressionIsDropped) {
  const Axisym2Geometry g{10.0, 0.0, 12.0, 0.5};
  EXPECT_EQ(axisym2_stress_stiffness(g, -30.0, -20.0).norm(), 0.0);
  // Tension in one direction only: the other term alone.
  EXPECT_NEAR(
      (axisym2_stress_stiffness(g, 30.0, -20.0) - axisym2_stress_stiffness(g, 30.0, 0.0)).norm(),
      0.0, 1e-14);
}

// A flat square 9-node element [0, a]^2 at z = 0, its nodes in lagrange9 order.
shell3d::Shell9Geometry flat_square(double a) {
  shell3d::Shell9Geometry g;
  for (int n = 0; n < 9; ++n) {
    const auto rs = shell3d::lagrange9_node(n);
    g.x[n] = shell3d::Vec3(0.5 * a * (1.0 + rs[0]), 0.5 * a * (1.0 + rs[1]), 0.0);
    g.director[n] = shell3d::Vec3::UnitZ();
    g.thickness[n] = 1.0;
    g.n_rot[n] = 2;
  }
  return g;
}

// Delta^T K Delta for the out-of-plane field w(x, y) (k acts the same on each component).
double work2(const Eigen::Matrix<double, 9, 9>& k, const shell3d::Shell9Geometry& g, double wx,
             double wy) {
  Eigen::Matrix<double, 9, 1> w;
  for (int n = 0; n < 9; ++n) w(n) = wx * g.x[n].x() + wy * g.x[n].y();
  return w.dot(k * w);
}

TEST(StressStiffness, Shell9UniformMembraneForceOnLinearFields) {
  const double a = 3.0;
  const shell3d::Shell9Geometry g = flat_square(a);
  const double N11 = 5.0, N22 = 2.0, N12 = 1.0;  // principal values both positive
  const std::vector<shell3d::Vec3> N(9, shell3d::Vec3(N11, N22, N12));
  for (auto rule : {shell3d::Shell9Rule::kMitc9, shell3d::Shell9Rule::kSelective}) {
    const auto k = shell3d::shell9_stress_stiffness(g, rule, N);
    EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
    // Delta^T K Delta = int N_ab w_,a w_,b dA for w = wx x + wy y.
    EXPECT_NEAR(work2(k, g, 1.0, 0.0), N11 * a * a, 1e-10);
    EXPECT_NEAR(work2(k, g, 0.0, 1.0), N22 * a * a, 1e-10);
    EXPECT_NEAR(work2(k, g, 1.0, 1.0), (N11 + N22 + 2.0 * N12) * a * a, 1e-10);
    // A rigid translation costs nothing.
    EXPECT_LT((k * Eigen::Matrix<double, 9, 1>::Ones()).norm(), 1e-12 * k.norm());
  }
}

TEST(StressStiffness, Shell9DropsTheCompressivePrincipalPart) {
  const double a = 2.0;
  const shell3d::Shell9Geometry g = flat_square(a);
  // N = diag(-1, 4): only the tension along y remains.
  const std::vector<shell3d::Vec3> N(9, shell3d::Vec3(-1.0, 4.0, 0.0));
  const auto k = shell3d::shell9_stress_stiffness(g, shell3d::Shell9Rule::kMitc9, N);
  EXPECT_NEAR(work2(k, g, 1.0, 0.0), 0.0, 1e-12);
  EXPECT_NEAR(work2(k, g, 0.0, 1.0), 4.0 * a * a, 1e-10);
  const std::vector<shell3d::Vec3> C(9, shell3d::Vec3(-1.0, -4.0, 0.5));
  EXPECT_EQ(shell3d::shell9_stress_stiffness(g, shell3d::Shell9Rule::kMitc9, C).norm(), 0.0);
  // Positive semi-definite for any membrane state.
  const std::vector<shell3d::Vec3> M(9, shell3d::Vec3(-3.0, 2.0, 2.5));
  const auto km = shell3d::shell9_stress_stiffness(g, shell3d::Shell9Rule::kMitc9, M);
  using Eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>;
  EXPECT_GT(Eig(km).eigenvalues().minCoeff(), -1e-12 * km.norm());
}

// The membrane tensors in global axes (the implicit update's coupling, GeometryCoupling3): on a
// flat element the same as the local components, and on a curved element independent of the node
// numbering (mirror-image elements see the same tensor; issue 14).
TEST(StressStiffness, Shell9GlobalTensorsEqualTheLocalComponentsOnAFlatElement) {
  const shell3d::Shell9Geometry g = flat_square(2.0);  // e1 = x, e2 = y
  std::vector<shell3d::Vec3> local;
  std::vector<shell3d::Mat3> global;
  for (int p = 0; p < 9; ++p) {
    const double N11 = 3.0 + p, N22 = -1.0 + 0.5 * p, N12 = 0.3 * p - 1.0;
    local.emplace_back(N11, N22, N12);
    shell3d::Mat3 m = shell3d::Mat3::Zero();
    m.topLeftCorner<2, 2>() << N11, N12, N12, N22;
    global.push_back(m);
  }
  const auto kl = shell3d::shell9_stress_stiffness(g, shell3d::Shell9Rule::kMitc9, local);
  const auto kg = shell3d::shell9_stress_stiffness(g, shell3d::Shell9Rule::kMitc9, global);
  EXPECT_GT(kl.norm(), 1.0);
  EXPECT_LT((kl - kg).norm(), 1e-13 * kl.norm());
}

TEST(StressStiffness, Shell9GlobalTensorsAreIndependentOfTheNodeNumbering) {
  // A skewed element on z = 0.5 x y, numbered in lagrange9 order and with r and s exchanged.
  auto element = [](bool transposed) {
    shell3d::Shell9Geometry g;
    for (int n = 0; n < 9; ++n) {
      auto rs = shell3d::lagrange9_node(n);
      if (transposed) std::swap(rs[0], rs[1]);
      const double x = 1.0 + 0.5 * (1.0 + rs[0]) + 0.15 * rs[1];
      const double y = 0.5 + 0.4 * (1.0 + rs[1]) + 0.1 * rs[0] * rs[0];
      g.x[n] = shell3d::Vec3(x, y, 0.5 * x * y);
      g.n_rot[n] = 2;
    }
    return g;
  };
  // A tensor field of the position (a global one, tangent or not; the element projects it).
  auto tensor = [](const shell3d::Vec3& x) {
    shell3d::Mat3 m;
    m << 4.0 + x.x(), 1.0 - x.y(), 0.3, 1.0 - x.y(), 2.0 + x.x() * x.y(), -0.2, 0.3, -0.2, 0.5;
    return m;
  };
  const double g3 = std::sqrt(0.6);
  const double xs[3] = {-g3, 0.0, g3};
  std::array<std::vector<shell3d::Mat3>, 2> field;
  std::array<shell3d::Shell9Geometry, 2> geo = {element(false), element(true)};
  for (int t = 0; t < 2; ++t)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const shell3d::Shape9 sh = shell3d::lagrange9(xs[i], xs[j]);
        shell3d::Vec3 x = shell3d::Vec3::Zero();
        for (int n = 0; n < 9; ++n) x += sh.N(n) * geo[static_cast<std::size_t>(t)].x[n];
        field[static_cast<std::size_t>(t)].push_back(tensor(x));
      }
  const auto ka = shell3d::shell9_stress_stiffness(geo[0], shell3d::Shell9Rule::kMitc9, field[0]);
  const auto kb = shell3d::shell9_stress_stiffness(geo[1], shell3d::Shell9Rule::kMitc9, field[1]);
  auto transposed_node = [](int n) {
    const auto rs = shell3d::lagrange9_node(n);
    int m = 0;
    while (shell3d::lagrange9_node(m)[0] != rs[1] || shell3d::lagrange9_node(m)[1] != rs[0]) ++m;
    return m;
  };
  double diff = 0.0;
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b)
      diff = std::max(diff, std::abs(ka(a, b) - kb(transposed_node(a), transposed_node(b))));
  EXPECT_GT(ka.norm(), 1.0);
  EXPECT_LT(diff, 1e-12 * ka.norm());
}

}  // namespace
}  // namespace vs
