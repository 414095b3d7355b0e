// The one regularised Coulomb law of both geometries (contact/coulomb.h) against its closed forms:
// f = L 2/pi atan(v/v0), the secant f/v, the tangent df/dv and the potential P with P' = f, each
// checked against values computed here from the definition and against central differences.
#include "contact/coulomb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vs {
namespace {

constexpr double kPi = std::numbers::pi;

// Closed forms at points where they are known exactly: atan(1) = pi/4, atan(sqrt(3)) = pi/3.
TEST(Coulomb, ForceTakesItsClosedFormValues) {
  const double L = 120.0, v0 = 0.02;
  EXPECT_NEAR(regularised_coulomb(L, v0, v0).force, 0.5 * L, 1e-12 * L);  // 2/pi * pi/4
  EXPECT_NEAR(regularised_coulomb(L, std::sqrt(3.0) * v0, v0).force, 2.0 * L / 3.0, 1e-12 * L);
  EXPECT_NEAR(regularised_coulomb(L, -v0, v0).force, -0.5 * L, 1e-12 * L);
  EXPECT_EQ(regularised_coulomb(L, 0.0, v0).force, 0.0);
  // Far from the transition the force is the Coulomb limit with the slip's sign.
  EXPECT_NEAR(regularised_coulomb(L, 1e6 * v0, v0).force, L, 1e-6 * L);
  EXPECT_NEAR(regularised_coulomb(L, -1e6 * v0, v0).force, -L, 1e-6 * L);
  // The force is linear in the limit (mu N): doubling the normal force doubles it.
  EXPECT_NEAR(regularised_coulomb(2.0 * L, 0.3 * v0, v0).force,
              2.0 * regularised_coulomb(L, 0.3 * v0, v0).force, 1e-12 * L);
}

TEST(Coulomb, SecantTangentAndPotentialTakeTheirClosedFormValues) {
  const double L = 7.5, v0 = 3e-3;
  const CoulombTerms t = regularised_coulomb(L, v0, v0);
  EXPECT_NEAR(t.secant, 0.5 * L / v0, 1e-12 * L / v0);
  EXPECT_NEAR(t.tangent, L / (kPi * v0), 1e-12 * L / v0);  // 2/(pi v0) / (1 + 1)
  // P(v0) = L 2/pi (v0 pi/4 - v0/2 ln 2).
  EXPECT_NEAR(t.potential, L * 2.0 / kPi * (v0 * kPi / 4.0 - 0.5 * v0 * std::log(2.0)),
              1e-12 * L * v0);
  // At v -> 0 the secant and the tangent both tend to L 2/(pi v0).
  const CoulombTerms z = regularised_coulomb(L, 0.0, v0);
  EXPECT_NEAR(z.secant, 2.0 * L / (kPi * v0), 1e-12 * L / v0);
  EXPECT_NEAR(z.tangent, 2.0 * L / (kPi * v0), 1e-12 * L / v0);
  EXPECT_EQ(z.potential, 0.0);
  const CoulombTerms tiny = regularised_coulomb(L, 1e-12 * v0, v0);
  EXPECT_NEAR(tiny.secant, z.secant, 1e-9 * z.secant);
}

// f = P' and f' = tangent by central differences over six decades of slip, both signs; the
// secant is f / v; the potential is convex (tangent > 0) and even.
TEST(Coulomb, ForceIsThePotentialsDerivativeAndTangentIsTheForcesDerivative) {
  const double L = 250.0, v0 = 1e-3;
  for (double a : {-300.0, -4.0, -1.0, -0.2, 0.01, 0.2, 1.0, 3.0, 50.0, 1000.0}) {
    const double v = a * v0, h = 1e-5 * std::max(std::abs(v), v0);
    const CoulombTerms t = regularised_coulomb(L, v, v0);
    const CoulombTerms p = regularised_coulomb(L, v + h, v0), m = regularised_coulomb(L, v - h, v0);
    SCOPED_TRACE(a);
    EXPECT_NEAR((p.potential - m.potential) / (2 * h), t.force, 1e-7 * L);
    EXPECT_NEAR((p.force - m.force) / (2 * h), t.tangent, 1e-6 * t.tangent + 1e-9 * L / v0);
    EXPECT_NEAR(t.secant * v, t.force, 1e-12 * L);
    EXPECT_GT(t.tangent, 0.0);
    EXPECT_NEAR(regularised_coulomb(L, -v, v0).potential, t.potential, 1e-12 * L * std::abs(v));
    EXPECT_GE(t.potential, 0.0);
  }
}

// The transition width is v0: the force reaches 99 % of the limit at v = tan(0.99 pi/2) v0
// (63.66 v0) and not before.
TEST(Coulomb, TransitionWidthIsTheRegularisationVelocity) {
  const double L = 1.0, v0 = 0.5;
  const double v99 = std::tan(0.99 * kPi / 2.0) * v0;
  EXPECT_NEAR(regularised_coulomb(L, v99, v0).force, 0.99, 1e-12);
  EXPECT_LT(regularised_coulomb(L, 0.9 * v99, v0).force, 0.99);
  EXPECT_NEAR(v99 / v0, 63.657, 1e-3);
}

}  // namespace
}  // namespace vs
