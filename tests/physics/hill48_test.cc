// Plane-stress Hill 1948 with planar anisotropy (forward/material/hill48.h): identification from
// r-values or yield stresses reproduces its data, closed-form Hill identities, derivatives, the
// closed-form dual against the general local solve, and equality with the normal-anisotropy
// ViscousLaw for r0 = r45 = r90 = R.
#include "material/hill48.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/error.h"
#include "material/anisotropic_viscous_law.h"
#include "material/dual_potential.h"
#include "material/viscous_law.h"

namespace vs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Hill48, FromRValuesReproducesRValuesAndRdStress) {
  for (const auto& r : {std::array{0.526, 0.253, 0.601}, std::array{1.8, 1.2, 2.4},
                        std::array{0.21, 1.58, 0.69}, std::array{1.0, 1.0, 1.0}}) {
    const Hill48 hill(hill48_from_r_values(r[0], r[1], r[2]));
    EXPECT_NEAR(uniaxial_response(hill, 0.0).stress, 1.0, 1e-14);
    EXPECT_NEAR(uniaxial_response(hill, 0.0).r_value, r[0], 1e-12);
    EXPECT_NEAR(uniaxial_response(hill, 45 * kDeg).r_value, r[1], 1e-12);
    EXPECT_NEAR(uniaxial_response(hill, 90 * kDeg).r_value, r[2], 1e-12);
    // Hill's closed forms: sigma90^2 = 1/(F+H) = r90 (1+r0) / (r0 (1+r90)),
    // sigma_b^2 = 1/(F+G) = r90 (1+r0) / (r0 + r90).
    EXPECT_NEAR(uniaxial_response(hill, 90 * kDeg).stress,
                std::sqrt(r[2] * (1 + r[0]) / (r[0] * (1 + r[2]))), 1e-12);
    EXPECT_NEAR(equibiaxial_response(hill).stress, std::sqrt(r[2] * (1 + r[0]) / (r[0] + r[2])),
                1e-12);
  }
}

TEST(Hill48, FromStressesReproducesStresses) {
  const double s45 = 0.908, s90 = 0.983, sb = 1.0;
  const Hill48 hill(hill48_from_stresses(s45, s90, sb));
  EXPECT_NEAR(uniaxial_response(hill, 0.0).stress, 1.0, 1e-14);
  EXPECT_NEAR(uniaxial_response(hill, 45 * kDeg).stress, s45, 1e-12);
  EXPECT_NEAR(uniaxial_response(hill, 90 * kDeg).stress, s90, 1e-12);
  EXPECT_NEAR(equibiaxial_response(hill).stress, sb, 1e-12);

  const double r0 = 0.526;
  const Hill48 hill_r0(hill48_from_stresses_and_r0(s45, s90, r0));
  EXPECT_NEAR(uniaxial_response(hill_r0, 0.0).stress, 1.0, 1e-14);
  EXPECT_NEAR(uniaxial_response(hill_r0, 0.0).r_value, r0, 1e-12);
  EXPECT_NEAR(uniaxial_response(hill_r0, 45 * kDeg).stress, s45, 1e-12);
  EXPECT_NEAR(uniaxial_response(hill_r0, 90 * kDeg).stress, s90, 1e-12);
}

TEST(Hill48, NormalAnisotropyClosedForms) {
  for (double R : {0.4, 1.0, 1.9}) {
    const Hill48 hill = Hill48::NormalAnisotropy(R);
    // Planar isotropy: every direction yields at 1 with Lankford value R.
    for (double theta : {0.0, 20.0, 45.0, 77.0, 90.0}) {
      EXPECT_NEAR(uniaxial_response(hill, theta * kDeg).stress, 1.0, 1e-12);
      EXPECT_NEAR(uniaxial_response(hill, theta * kDeg).r_value, R, 1e-12);
    }
    // literature.md 8.2: sigma_b = sqrt((1+R)/2); r_b = 1.
    EXPECT_NEAR(equibiaxial_response(hill).stress, std::sqrt((1 + R) / 2), 1e-12);
    EXPECT_NEAR(equibiaxial_response(hill).r_value, 1.0, 1e-12);
  }
}

TEST(Hill48, GradientAndHessianMatchFiniteDifferences) {
  const Hill48 hill(hill48_from_r_values(0.526, 0.253, 0.601));
  const PlaneVector s(130.0, -40.0, 55.0);
  const YieldPoint p = hill.evaluate(s);
  const double h = 1e-5;
  for (int j = 0; j < 3; ++j) {
    PlaneVector sp = s, sm = s;
    sp(j) += h;
    sm(j) -= h;
    EXPECT_NEAR((hill.effective_stress(sp) - hill.effective_stress(sm)) / (2 * h), p.gradient(j),
                1e-8);
    const PlaneVector dg = (hill.evaluate(sp).gradient - hill.evaluate(sm).gradient) / (2 * h);
    EXPECT_LT((dg - p.hessian.col(j)).norm(), 1e-8 * p.hessian.norm());
  }
}

TEST(Hill48, ClosedFormDualEqualsLocalSolve) {
  const Hill48 hill(hill48_from_r_values(0.21, 1.58, 0.69));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const PlaneVector d(u(rng), u(rng), u(rng));
    const DualPoint closed = hill.dual(d);
    const DualPoint solved = solve_dual(hill, d);
    ASSERT_TRUE(solved.converged);
    EXPECT_NEAR(solved.rate, closed.rate, 1e-12 * closed.rate);
    EXPECT_LT((solved.direction - closed.direction).norm(), 1e-11);
    EXPECT_LT((solved.hessian - closed.hessian).norm(), 1e-10 * closed.hessian.norm());
  }
}

TEST(Hill48, EqualsNormalAnisotropyViscousLawToRoundOff) {
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.02;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double R : {0.41, 1.0, 1.7}) {
    const ViscousLaw law(rate, 1e-3, R);
    const Hill48 hill(hill48_from_r_values(R, R, R));
    const AnisotropicViscousLaw aniso(hill, law, 0.3);  // any RD angle: planar isotropy
    for (int i = 0; i < 40; ++i) {
      const double scale = std::pow(10.0, 4.0 * u(rng));
      const Eigen::Vector2d d2 = scale * Eigen::Vector2d(u(rng), u(rng));
      const ViscousLaw::Point ref = law.evaluate(250.0, 30.0, d2);
      const AnisotropicViscousLaw::Point p =
          aniso.evaluate(250.0, 30.0, PlaneVector(d2(0), d2(1), 0.0));
      const Eigen::Matrix2d D_ref =
          ref.mu * law.A() + ref.tangent_coef * (law.A() * d2) * (law.A() * d2).transpose();
      EXPECT_NEAR(p.rate, ref.rate, 1e-13 * ref.rate);
      EXPECT_NEAR(p.potential, ref.potential, 1e-12 * std::abs(ref.potential));
      EXPECT_LT((p.stress.head<2>() - ref.stress).norm(), 1e-12 * ref.stress.norm());
      EXPECT_NEAR(p.stress(2), 0.0, 1e-12 * ref.stress.norm());
      EXPECT_LT((p.tangent.topLeftCorner<2, 2>() - D_ref).norm(), 1e-11 * D_ref.norm());
    }
    // With shear: the 3x3 A(R) of shell3d/hill_plane_stress.h, s = mu A d.
    const double f = 3 * (1 + R) / (1 + 2 * R);
    PlaneMatrix A3;
    A3 << f * (1 + R), f * R, 0, f * R, f * (1 + R), 0, 0, 0, 0.5 * f;
    const PlaneVector d(0.3, -0.1, 0.25);
    const AnisotropicViscousLaw::Point p = aniso.evaluate(250.0, 30.0, d);
    EXPECT_LT((p.stress - p.mu * A3 * d).norm(), 1e-12 * p.stress.norm());
  }
}

TEST(Hill48, BadDataThrowInputError) {
  EXPECT_THROW(hill48_from_r_values(-0.5, 1.0, 1.0), InputError);
  EXPECT_THROW(hill48_from_r_values(1.0, 0.0, 1.0), InputError);
  EXPECT_THROW(hill48_from_stresses(1.0, 1.0, -1.0), InputError);
  // sigma_b = 0.4 sigma_0 gives F = G = 3.125, H = -2.125: an indefinite quadratic (FG + GH + HF <
  // 0).
  EXPECT_THROW(Hill48(hill48_from_stresses(1.0, 1.0, 0.4)), InputError);
  Hill48Coefficients c;
  c.N = -1.0;
  EXPECT_THROW((Hill48(c)), InputError);
}

}  // namespace
}  // namespace vs
