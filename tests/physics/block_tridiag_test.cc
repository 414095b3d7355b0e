#include "linalg/block_tridiag.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <random>

namespace vs {
namespace {

// A random symmetric positive definite chain: pivot blocks A A^T + shift(i) I with A uniform in
// [-1, 1], coupling blocks `coupling` times uniform in [-1, 1].
BlockTridiag random_chain(int n, std::mt19937& rng, const std::function<double(int)>& shift,
                          double coupling) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BlockTridiag K(n);
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix3d A;
    for (int a = 0; a < 9; ++a) A(a / 3, a % 3) = u(rng);
    K.diag(i) = A * A.transpose() + shift(i) * Eigen::Matrix3d::Identity();
    if (i + 1 < n) {
      for (int a = 0; a < 9; ++a) K.lower(i)(a / 3, a % 3) = coupling * u(rng);
    }
  }
  return K;
}

// The matrix as a dense one, column by column through multiply().
Eigen::MatrixXd dense(const BlockTridiag& K) {
  const int m = 3 * K.blocks();
  Eigen::MatrixXd D(m, m);
  for (int j = 0; j < m; ++j) D.col(j) = K.multiply(Eigen::VectorXd::Unit(m, j));
  return D;
}

TEST(BlockTridiag, SolvesLikeADenseCholesky) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 7;
  BlockTridiag K = random_chain(
      n, rng, [](int) { return 8.0; }, 1.0);
  K.fix_dof(2, 1);
  const Eigen::MatrixXd D = dense(K);
  EXPECT_NEAR((D - D.transpose()).norm(), 0.0, 1e-14);
  Eigen::VectorXd b(3 * n);
  for (int i = 0; i < 3 * n; ++i) b(i) = u(rng);
  ASSERT_TRUE(K.factorize());
  const Eigen::VectorXd x = K.solve(b);
  EXPECT_NEAR((D * x - b).norm(), 0.0, 1e-12);
  EXPECT_NEAR(x(3 * 2 + 1), b(3 * 2 + 1), 1e-14);
  Eigen::VectorXd y = b;
  K.solve_in_place(&y);
  EXPECT_EQ(y, x);
  // The factor of the first pivot block is its Cholesky factor: the solve matches Eigen's LLT.
  const Eigen::VectorXd dense = Eigen::LLT<Eigen::MatrixXd>(D).solve(b);
  EXPECT_NEAR((x - dense).norm(), 0.0, 1e-12 * dense.norm());
}

TEST(BlockTridiag, ConditionEstimateIsALowerBoundAndIgnoresFixedDofs) {
  // Diagonal SPD matrix: the estimate is exact, (max / min) of the diagonal; a fixed dof
  // (identity row) does not enter it.
  BlockTridiag K(2);
  K.diag(0) = Eigen::Vector3d(1e4, 4e4, 9e4).asDiagonal();
  K.diag(1) = Eigen::Vector3d(1e6, 2.5e5, 1e8).asDiagonal();
  K.fix_dof(1, 2);
  ASSERT_TRUE(K.factorize());
  EXPECT_NEAR(K.condition_estimate(), 1e6 / 1e4, 1e-6);
  // A random SPD chain: the estimate never exceeds the true 2-norm condition number.
  std::mt19937 rng(3);
  BlockTridiag M = random_chain(
      5, rng, [](int i) { return i + 1.0; }, 0.3);
  const Eigen::MatrixXd D = dense(M);
  ASSERT_TRUE(M.factorize());
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D).eigenvalues();
  EXPECT_LE(M.condition_estimate(), ev.maxCoeff() / ev.minCoeff() * (1.0 + 1e-12));
  EXPECT_GT(M.condition_estimate(), 1.0);
}

TEST(BlockTridiag, ReportsIndefiniteMatrices) {
  BlockTridiag K(2);
  K.diag(0) = Eigen::Matrix3d::Identity();
  K.diag(1) = -Eigen::Matrix3d::Identity();
  EXPECT_FALSE(K.factorize());
  // Indefinite only through the coupling (a later pivot), and a NaN entry.
  K.diag(1) = Eigen::Matrix3d::Identity();
  K.lower(0) = 2.0 * Eigen::Matrix3d::Identity();
  EXPECT_FALSE(K.factorize());
  K.lower(0).setZero();
  EXPECT_TRUE(K.factorize());
  K.diag(0)(2, 2) = std::nan("");
  EXPECT_FALSE(K.factorize());
}

TEST(BlockTridiag, UnsymmetricSolvesLikeADenseLU) {
  // A symmetric positive definite chain plus a non-symmetric part in some rows (as the friction
  // coupling adds): block LU against a dense LU, with a fixed dof.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 6;
  BlockTridiag K = random_chain(
      n, rng, [](int) { return 8.0; }, 1.0);
  K.unsymmetric();
  EXPECT_FALSE(K.symmetric());
  for (int i = 0; i + 1 < n; i += 2) {
    K.diag(i).row(0) += 0.3 * K.diag(i).row(1);
    K.upper(i).row(0) += 0.3 * K.upper(i).row(1);
    if (i > 0) K.lower(i - 1).row(0) += 0.3 * K.lower(i - 1).row(1);
  }
  K.fix_dof(3, 2);
  const Eigen::MatrixXd D = dense(K);
  EXPECT_GT((D - D.transpose()).norm(), 0.1);
  EXPECT_EQ(D.row(3 * 3 + 2).norm(), 1.0);  // fixed: identity row and column
  EXPECT_EQ(D.col(3 * 3 + 2).norm(), 1.0);
  Eigen::VectorXd b(3 * n);
  for (int i = 0; i < 3 * n; ++i) b(i) = u(rng);
  ASSERT_TRUE(K.factorize());
  const Eigen::VectorXd x = K.solve(b);
  const Eigen::VectorXd dense = Eigen::PartialPivLU<Eigen::MatrixXd>(D).solve(b);
  EXPECT_NEAR((x - dense).norm(), 0.0, 1e-12 * dense.norm());
  // Back to symmetric storage: the lower blocks alone define the matrix again.
  K.set_zero();
  EXPECT_TRUE(K.symmetric());
}

}  // namespace
}  // namespace vs
