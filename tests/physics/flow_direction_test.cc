// The primal-dual flow directions (material/flow_direction.h): the dual update is the first-order
// change of m = A d / (3 eh), the ball projection, and the point matrix D(n) is positive
// semi-definite for directions in the ball.
#include "material/flow_direction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "material/viscous_law.h"

namespace vs {
namespace {

constexpr double kCut = 1e-4;

Eigen::Vector2d direction(const Eigen::Matrix2d& A, const Eigen::Vector2d& d, double* eh) {
  *eh = std::sqrt(d.dot(A * d) / 3.0 + kCut * kCut);
  return A * d / (3.0 * *eh);
}

TEST(FlowDirection, UpdateFromTheConsistentDirectionIsItsFirstOrderChange) {
  const Eigen::Matrix2d A = anisotropy_matrix(1.6);
  const Eigen::Vector2d d(0.03, -0.01), dd(0.4e-3, 0.9e-3);
  double eh = 0.0, eh2 = 0.0;
  const Eigen::Vector2d m = direction(A, d, &eh);
  const Eigen::Vector2d exact = direction(A, d + dd, &eh2);
  const Eigen::Vector2d predicted = m + flow_direction_increment(A, m, eh, m, dd);
  // Error O(|dd|^2 / |d|^2) against the O(|dd| / |d|) change (|dd| / |d| = 0.03 here), and
  // quartered when dd is halved.
  EXPECT_LT((predicted - exact).norm(), 0.1 * (exact - m).norm());
  const Eigen::Vector2d half = m + flow_direction_increment(A, m, eh, m, 0.5 * dd);
  double eh3 = 0.0;
  const Eigen::Vector2d exact_half = direction(A, d + 0.5 * dd, &eh3);
  EXPECT_NEAR((half - exact_half).norm() / (predicted - exact).norm(), 0.25, 0.05);
}

TEST(FlowDirection, ProjectionOntoTheDualBall) {
  const Eigen::Matrix2d A = anisotropy_matrix(0.7);
  const FlowDirectionBall ball(A);
  const Eigen::Matrix2d Ainv = A.inverse();
  auto norm = [&](const Eigen::Vector2d& n) { return std::sqrt(3.0 * n.dot(Ainv * n)); };
  const Eigen::Vector2d inside(0.2, 0.1), outside(3.0, -1.0);
  EXPECT_EQ(ball.project(inside), inside);
  const Eigen::Vector2d p = ball.project(outside);
  EXPECT_NEAR(norm(p), 1.0, 1e-14);
  EXPECT_NEAR(p.normalized().dot(outside.normalized()), 1.0, 1e-14);
  // The current direction of any rate lies inside (|m|_* = e / eh < 1).
  double eh = 0.0;
  EXPECT_LT(norm(direction(A, Eigen::Vector2d(1.0, -0.3), &eh)), 1.0);
}

TEST(FlowDirection, PointMatrixIsPositiveSemiDefiniteInsideTheBall) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double R : {0.5, 1.0, 2.5}) {
    const ViscousLaw law(RateSpec{}, kCut, R);
    const Eigen::Matrix2d& A = law.A();
    const FlowDirectionBall ball(A);
    for (int trial = 0; trial < 200; ++trial) {
      const Eigen::Vector2d d(u(rng), u(rng));
      const ViscousLaw::Point p = law.evaluate(280.0, 0.0, d);  // no hardening: the worst case
      double eh = 0.0;
      direction(A, d, &eh);
      const Eigen::Vector2d n = ball.project(Eigen::Vector2d(u(rng), u(rng)) * 2.0);
      const Eigen::Vector2d Ad = A * d;
      const Eigen::Matrix2d Rn = n * Ad.transpose();
      const Eigen::Matrix2d D = p.mu * A + 3.0 * eh * p.tangent_coef * 0.5 * (Rn + Rn.transpose());
      const double lmin = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(D).eigenvalues()(0);
      EXPECT_GE(lmin, -1e-12 * D.norm()) << "R=" << R << " trial " << trial;
    }
  }
}

}  // namespace
}  // namespace vs
