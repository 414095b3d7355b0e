#include "solver/block_tridiag.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

namespace vs {
namespace {

TEST(BlockTridiag, SolvesLikeADenseCholesky) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 7;
  BlockTridiag K(n);
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix3d A;
    for (int a = 0; a < 9; ++a) A(a / 3, a % 3) = u(rng);
    K.diag(i) = A * A.transpose() + 8.0 * Eigen::Matrix3d::Identity();
    if (i + 1 < n) {
      for (int a = 0; a < 9; ++a) K.lower(i)(a / 3, a % 3) = u(rng);
    }
  }
  K.fix_dof(2, 1);
  Eigen::MatrixXd D(3 * n, 3 * n);
  for (int j = 0; j < 3 * n; ++j) D.col(j) = K.multiply(Eigen::VectorXd::Unit(3 * n, j));
  EXPECT_NEAR((D - D.transpose()).norm(), 0.0, 1e-14);
  Eigen::VectorXd b(3 * n);
  for (int i = 0; i < 3 * n; ++i) b(i) = u(rng);
  ASSERT_TRUE(K.factorize());
  const Eigen::VectorXd x = K.solve(b);
  EXPECT_NEAR((D * x - b).norm(), 0.0, 1e-12);
  EXPECT_NEAR(x(3 * 2 + 1), b(3 * 2 + 1), 1e-14);
}

TEST(BlockTridiag, ReportsIndefiniteMatrices) {
  BlockTridiag K(2);
  K.diag(0) = Eigen::Matrix3d::Identity();
  K.diag(1) = -Eigen::Matrix3d::Identity();
  EXPECT_FALSE(K.factorize());
}

}  // namespace
}  // namespace vs
