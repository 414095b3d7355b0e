#include "uncertainty.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "quantiles.h"

namespace vs {
namespace {

const std::vector<std::string> kNames = {"a", "b", "c"};

Eigen::VectorXd unbounded(double sign, Eigen::Index n) {
  return Eigen::VectorXd::Constant(n, sign * INFINITY);
}

TEST(Uncertainty, ReproducesTheLinearLeastSquaresCovarianceExactly) {
  // Straight-line-plus-quadratic fit y = a + b t + c t^2, unit weights.
  const int m = 12;
  Eigen::MatrixXd j(m, 3);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) {
    const double t = 0.5 * i;
    j.row(i) << 1.0, t, t * t;
    r[i] = 0.1 * std::sin(3.0 * i);  // residuals at the optimum
  }
  const double cost = 0.5 * r.squaredNorm();
  const Eigen::Vector3d values(1.0, 2.0, 3.0);
  const Eigen::Vector3d scale(1.0, 0.5, 0.1);
  const auto u = estimate_uncertainty(j, cost, values, scale, unbounded(-1, 3), unbounded(1, 3),
                                      kNames, UncertaintyOptions{});
  const double s2 = r.squaredNorm() / (m - 3);
  const Eigen::MatrixXd expected = (j.transpose() * j).inverse() * s2;
  EXPECT_LT((u.covariance - expected).norm(), 1e-12 * expected.norm());
  EXPECT_NEAR(u.residual_variance, s2, 1e-15);
  EXPECT_EQ(u.rank, 3);
  EXPECT_EQ(u.degrees_of_freedom, 9);
  const double q = student_t_two_sided(0.95, 9);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(u.parameters[k].std_error, std::sqrt(expected(k, k)), 1e-12);
    EXPECT_NEAR(u.parameters[k].interval_upper - values[k], q * std::sqrt(expected(k, k)), 1e-12);
    EXPECT_NEAR(u.correlation(k, k), 1.0, 1e-14);
  }
}

TEST(Uncertainty, AnEliminatedOffsetCountsInTheDegreesOfFreedom) {
  // The same fit with the intercept a eliminated (variable projection, as the shape-only cup
  // profile does): the Jacobian of b and c is that of the full fit with its columns centred, and
  // the covariance of (b, c) must be the (b, c) block of the full fit's, s^2 = |r|^2 / (m - 3).
  const int m = 12;
  Eigen::MatrixXd full(m, 3);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) {
    const double t = 0.5 * i;
    full.row(i) << 1.0, t, t * t;
    r[i] = 0.1 * std::sin(3.0 * i);
  }
  const double s2 = r.squaredNorm() / (m - 3);
  const Eigen::MatrixXd expected = (full.transpose() * full).inverse() * s2;
  Eigen::MatrixXd centred = full.rightCols(2);
  centred.rowwise() -= centred.colwise().mean();
  UncertaintyOptions options;
  options.eliminated_parameters = 1;
  const auto u = estimate_uncertainty(centred, 0.5 * r.squaredNorm(), Eigen::Vector2d(2.0, 3.0),
                                      Eigen::Vector2d(0.5, 0.1), unbounded(-1, 2), unbounded(1, 2),
                                      {"b", "c"}, options);
  EXPECT_EQ(u.degrees_of_freedom, 9);
  EXPECT_EQ(u.num_parameters, 2);
  EXPECT_NEAR(u.residual_variance, s2, 1e-15);
  EXPECT_LT((u.covariance - expected.bottomRightCorner(2, 2)).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(u.quantile_kind, "student_t(9)");
}

TEST(Uncertainty, UnscaledUsesTheStatedSigmasAndTheNormalQuantile) {
  Eigen::MatrixXd j(4, 1);
  j << 1, 1, 1, 1;
  UncertaintyOptions options;
  options.scale_by_residual_variance = false;
  const auto u = estimate_uncertainty(j, 123.0, Eigen::VectorXd::Ones(1), Eigen::VectorXd::Ones(1),
                                      unbounded(-1, 1), unbounded(1, 1), {"a"}, options);
  EXPECT_DOUBLE_EQ(u.covariance(0, 0), 0.25);
  EXPECT_EQ(u.quantile_kind, "normal");
}

TEST(Uncertainty, ZeroColumnIsNotDetermined) {
  Eigen::MatrixXd j(5, 3);
  j << 1, 0, 0.5, 2, 0, 1, 3, 0, -1, 4, 0, 2, 5, 0, 0.1;
  const auto u =
      estimate_uncertainty(j, 1e-6, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 1),
                           unbounded(-1, 3), unbounded(1, 3), kNames, UncertaintyOptions{});
  EXPECT_EQ(u.rank, 2);
  EXPECT_TRUE(std::isinf(u.condition_number));
  EXPECT_TRUE(u.parameters[0].determined);
  EXPECT_FALSE(u.parameters[1].determined);
  EXPECT_TRUE(u.parameters[2].determined);
  ASSERT_FALSE(u.statements.empty());
  EXPECT_NE(u.statements[0].find("b is not determined"), std::string::npos);
}

TEST(Uncertainty, NearlyCollinearColumnsAreFlagged) {
  Eigen::MatrixXd j(6, 2);
  for (int i = 0; i < 6; ++i) j.row(i) << 1.0 + i, (1.0 + i) * (1.0 + 1e-3 * (i % 2));
  const auto u =
      estimate_uncertainty(j, 1e-4, Eigen::Vector2d(1, 1), Eigen::Vector2d(1, 1), unbounded(-1, 2),
                           unbounded(1, 2), {"a", "b"}, UncertaintyOptions{});
  EXPECT_EQ(u.rank, 2);
  EXPECT_GT(std::abs(u.correlation(0, 1)), 0.95);
  EXPECT_FALSE(u.parameters[0].determined);
  EXPECT_FALSE(u.well_determined());
}

TEST(Uncertainty, ParameterOnABoundIsFlagged) {
  Eigen::MatrixXd j(3, 1);
  j << 1, 2, 3;
  const auto u =
      estimate_uncertainty(j, 0.01, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1),
                           Eigen::VectorXd::Zero(1), unbounded(1, 1), {"mu"}, UncertaintyOptions{});
  EXPECT_TRUE(u.parameters[0].at_bound);
}

// A parameter identified at 0 (a friction on its bound): its relative error is judged against
// the scale, and no statement prints a 300-digit percentage.
TEST(Uncertainty, ValueAtZeroIsJudgedAgainstItsScale) {
  Eigen::MatrixXd j(3, 1);
  j << 1, 2, 3;
  const auto precise =
      estimate_uncertainty(j, 1e-8, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.1),
                           unbounded(-1, 1), unbounded(1, 1), {"mu"}, UncertaintyOptions{});
  EXPECT_TRUE(precise.parameters[0].determined);
  EXPECT_TRUE(precise.statements.empty());
  const auto vague =
      estimate_uncertainty(j, 10.0, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 0.1),
                           unbounded(-1, 1), unbounded(1, 1), {"mu"}, UncertaintyOptions{});
  ASSERT_EQ(vague.statements.size(), 1u);
  EXPECT_FALSE(vague.parameters[0].determined);
  EXPECT_NE(vague.statements[0].find("of its scale 0.1 (the value 0 is near zero)"),
            std::string::npos)
      << vague.statements[0];
  EXPECT_LT(vague.statements[0].size(), 150u) << vague.statements[0];
}

}  // namespace
}  // namespace vs
