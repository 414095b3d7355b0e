#include "fd_jacobian.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vs {
namespace {

// r(x) = [sin(x0) x1, x0^3, exp(x1)]
Eigen::VectorXd f(const Eigen::VectorXd& x) {
  Eigen::VectorXd r(3);
  r << std::sin(x[0]) * x[1], x[0] * x[0] * x[0], std::exp(x[1]);
  return r;
}

Eigen::MatrixXd exact(const Eigen::VectorXd& x) {
  Eigen::MatrixXd j(3, 2);
  j << std::cos(x[0]) * x[1], std::sin(x[0]), 3 * x[0] * x[0], 0, 0, std::exp(x[1]);
  return j;
}

BatchResiduals batch(int* count) {
  return [count](const std::vector<Eigen::VectorXd>& points) {
    std::vector<std::optional<Eigen::VectorXd>> out;
    for (const auto& p : points) out.emplace_back(f(p));
    *count += static_cast<int>(points.size());
    return out;
  };
}

const Eigen::Vector2d kX(0.7, 1.3);
const Eigen::Vector2d kScale(1.0, 1.0);
const Eigen::Vector2d kNoLower(-INFINITY, -INFINITY);
const Eigen::Vector2d kNoUpper(INFINITY, INFINITY);

TEST(FdJacobian, CentralIsSecondOrder) {
  int count = 0;
  FdOptions options;
  options.relative_step = 1e-3;
  const auto j = fd_jacobian(kX, f(kX), kNoLower, kNoUpper, kScale, options, batch(&count));
  ASSERT_TRUE(j.ok);
  EXPECT_LT((j.jacobian - exact(kX)).norm(), 1e-5);
  EXPECT_EQ(count, 4);
}

TEST(FdJacobian, RiddersIsMoreAccurateAtALargeStep) {
  int count = 0;
  FdOptions options;
  options.method = FdMethod::kRidders;
  options.relative_step = 0.1;
  options.ridders_levels = 4;
  const auto j = fd_jacobian(kX, f(kX), kNoLower, kNoUpper, kScale, options, batch(&count));
  ASSERT_TRUE(j.ok);
  EXPECT_LT((j.jacobian - exact(kX)).norm(), 1e-7);
  EXPECT_EQ(count, 16);
}

TEST(FdJacobian, StepsScaleWithTheParameterScale) {
  int count = 0;
  FdOptions options;
  const Eigen::Vector2d scale(1e-3, 1e-3);  // tiny steps are still accurate for this f
  const auto j = fd_jacobian(kX, f(kX), kNoLower, kNoUpper, scale, options, batch(&count));
  EXPECT_LT((j.jacobian - exact(kX)).norm(), 1e-6);
}

TEST(FdJacobian, OneSidedAtABoundNeverStepsOutside) {
  std::vector<Eigen::VectorXd> seen;
  BatchResiduals record = [&](const std::vector<Eigen::VectorXd>& points) {
    std::vector<std::optional<Eigen::VectorXd>> out;
    for (const auto& p : points) {
      seen.push_back(p);
      out.emplace_back(f(p));
    }
    return out;
  };
  FdOptions options;
  options.relative_step = 1e-3;
  const Eigen::Vector2d lower(0.7, -INFINITY);  // x0 sits on its lower bound
  const Eigen::Vector2d upper(INFINITY, 1.3);   // x1 on its upper bound
  const auto j = fd_jacobian(kX, f(kX), lower, upper, kScale, options, record);
  ASSERT_TRUE(j.ok);
  EXPECT_LT((j.jacobian - exact(kX)).norm(), 1e-5);  // second order one-sided
  for (const auto& p : seen) {
    EXPECT_GE(p[0], 0.7);
    EXPECT_LE(p[1], 1.3);
  }
}

TEST(FdJacobian, FailureOnOneSideFallsBackToTheOtherSide) {
  BatchResiduals failing_above = [](const std::vector<Eigen::VectorXd>& points) {
    std::vector<std::optional<Eigen::VectorXd>> out;
    for (const auto& p : points) {
      out.push_back(p[1] > 1.3 ? std::nullopt : std::optional<Eigen::VectorXd>(f(p)));
    }
    return out;
  };
  FdOptions options;
  options.relative_step = 1e-3;
  const auto j = fd_jacobian(kX, f(kX), kNoLower, kNoUpper, kScale, options, failing_above);
  ASSERT_TRUE(j.ok) << j.message;
  EXPECT_LT((j.jacobian - exact(kX)).norm(), 1e-5);
}

TEST(FdJacobian, FailureOnBothSidesIsReported) {
  BatchResiduals failing = [](const std::vector<Eigen::VectorXd>& points) {
    std::vector<std::optional<Eigen::VectorXd>> out;
    for (const auto& p : points) {
      out.push_back(p[1] != 1.3 ? std::nullopt : std::optional<Eigen::VectorXd>(f(p)));
    }
    return out;
  };
  const auto j = fd_jacobian(kX, f(kX), kNoLower, kNoUpper, kScale, FdOptions{}, failing);
  EXPECT_FALSE(j.ok);
  EXPECT_NE(j.message.find("parameter 1 either way"), std::string::npos) << j.message;
}

}  // namespace
}  // namespace vs
