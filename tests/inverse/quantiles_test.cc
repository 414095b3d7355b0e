#include "quantiles.h"

#include <gtest/gtest.h>

namespace vs {
namespace {

// Reference values from standard tables (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.2).
TEST(Quantiles, StudentTTwoSided95) {
  EXPECT_NEAR(student_t_two_sided(0.95, 1), 12.7062047, 1e-6);
  EXPECT_NEAR(student_t_two_sided(0.95, 2), 4.30265273, 1e-7);
  EXPECT_NEAR(student_t_two_sided(0.95, 10), 2.22813885, 1e-7);
  EXPECT_NEAR(student_t_two_sided(0.95, 100), 1.98397152, 1e-7);
  EXPECT_NEAR(student_t_two_sided(0.99, 5), 4.03214298, 1e-7);
}

TEST(Quantiles, NormalTwoSided) {
  EXPECT_NEAR(normal_two_sided(0.95), 1.95996398, 1e-8);
  EXPECT_NEAR(normal_two_sided(0.6826894921), 1.0, 1e-8);
}

TEST(Quantiles, StudentTCdfIsSymmetric) {
  EXPECT_NEAR(student_t_cdf(0.0, 3), 0.5, 1e-15);
  EXPECT_NEAR(student_t_cdf(-1.3, 7) + student_t_cdf(1.3, 7), 1.0, 1e-14);
}

}  // namespace
}  // namespace vs
