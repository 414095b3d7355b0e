// The viscous point law for planar anisotropy (forward/material/anisotropic_viscous_law.h) with
// Hill 1948 and Yld2000-2d: uniaxial stress at 0/45/90 degrees and the equibiaxial point reproduce
// the identification data through the dual (stress from rate), work conjugacy, consistent tangent
// and potential against finite differences, the near-rigid limit with the cut-off, warm starts,
// and the rotation to material axes (a 90-degree rotation swaps r0 and r90).
#include "material/anisotropic_viscous_law.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "material/hill48.h"
#include "material/yld2000.h"
#include "material/yld2000_fit.h"

namespace vs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kSy = 250.0;  // flow stress [MPa]

// ESAFORM 2021 AA6016-T4, TUAT lab (data/measured/esaform2021-aa6016t4-cup/; r_b not measured,
// 1 assumed).
AnisotropyData Tuat() {
  AnisotropyData d;
  d.sigma45 = 0.908;
  d.sigma90 = 0.983;
  d.sigma_b = 1.0;
  d.r0 = 0.526;
  d.r45 = 0.253;
  d.r90 = 0.601;
  d.r_b = 1.0;
  return d;
}

// The same material seen from TD: stresses in units of sigma90, r0 <-> r90, r_b -> 1 / r_b.
AnisotropyData SwapAxes(const AnisotropyData& d) {
  AnisotropyData s = d;
  s.sigma45 = d.sigma45 / d.sigma90;
  s.sigma90 = 1.0 / d.sigma90;
  s.sigma_b = d.sigma_b / d.sigma90;
  s.r0 = d.r90;
  s.r90 = d.r0;
  s.r_b = 1.0 / d.r_b;
  return s;
}

Yld2000Coefficients Fit(const AnisotropyData& d) {
  const Yld2000FitSummary fit = fit_yld2000(d);
  EXPECT_TRUE(fit.converged) << fit.message;
  return fit.coefficients;
}

ViscousLaw RateIndependent(double cutoff = 1e-12) { return ViscousLaw(RateSpec{}, cutoff, 1.0); }

ViscousLaw RateDependent(double cutoff) {
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.02;
  return ViscousLaw(rate, cutoff, 1.0);
}

// The laws under test: Hill48 from the r-values, Yld2000-2d a = 8 from all eight data.
struct Laws {
  Hill48 hill = Hill48(hill48_from_r_values(Tuat().r0, Tuat().r45, Tuat().r90));
  Yld2000 yld = Yld2000(Fit(Tuat()));
  std::vector<const PlaneStressYield*> all() const { return {&hill, &yld}; }
};

TEST(AnisotropicViscousLaw, UniaxialStressAt0_45_90ReproducesSigmaAndR) {
  const Laws laws;
  const ViscousLaw scalar = RateIndependent();
  const AnisotropyData data = Tuat();
  const double sigma[3] = {1.0, data.sigma45, data.sigma90};
  const double r[3] = {data.r0, data.r45, data.r90};
  for (const PlaneStressYield* yield : laws.all()) {
    const AnisotropicViscousLaw law(*yield, scalar);
    const bool is_yld = yield == &laws.yld;
    for (int k = 0; k < 3; ++k) {
      const double theta = 45.0 * k * kDeg;
      const PlaneVector u = uniaxial_stress_direction(theta);
      // The rate of uniaxial tension at theta: the normal of the yield surface there.
      const PlaneVector d = 0.01 * yield->evaluate(u).gradient;
      EXPECT_NEAR(lankford_ratio(d, theta), r[k], 1e-11);
      const AnisotropicViscousLaw::Point p = law.evaluate(kSy, 0.0, d);
      ASSERT_TRUE(p.converged);
      // Hill48 from r-values predicts its own sigma_theta; Yld2000 was fitted to the data.
      const double sigma_theta = is_yld ? sigma[k] : uniaxial_response(*yield, theta).stress;
      EXPECT_LT((p.stress - kSy * sigma_theta * u).norm(), 1e-9 * kSy) << "theta " << 45 * k;
    }
  }
  // Equibiaxial (Yld2000): sigma_b and r_b.
  const AnisotropicViscousLaw law(laws.yld, scalar);
  const PlaneVector d = laws.yld.evaluate(PlaneVector(1, 1, 0)).gradient;
  EXPECT_NEAR(d(1) / d(0), data.r_b, 1e-11);
  const AnisotropicViscousLaw::Point p = law.evaluate(kSy, 0.0, d);
  EXPECT_LT((p.stress - kSy * data.sigma_b * PlaneVector(1, 1, 0)).norm(), 1e-9 * kSy);
}

TEST(AnisotropicViscousLaw, WorkConjugacyAndStressOnTheYieldSurface) {
  const Laws laws;
  const ViscousLaw scalar = RateDependent(1e-4);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const PlaneStressYield* yield : laws.all()) {
    const AnisotropicViscousLaw law(*yield, scalar, 0.4);
    for (int i = 0; i < 30; ++i) {
      const PlaneVector d =
          std::pow(10.0, 2.0 * u(rng) - 1.0) * PlaneVector(u(rng), u(rng), u(rng));
      const AnisotropicViscousLaw::Point p = law.evaluate(kSy, 20.0, d);
      ASSERT_TRUE(p.converged);
      const double sigma_bar = scalar.effective_stress(kSy, p.rate, 20.0);
      EXPECT_NEAR(p.stress.dot(d), sigma_bar * p.rate, 1e-11 * sigma_bar * p.rate);
      // The stress lies on the yield surface of size sigma_bar (material axes).
      EXPECT_NEAR(yield->effective_stress(law.axes().stress_to_material(p.stress)), sigma_bar,
                  1e-11 * sigma_bar);
      EXPECT_NEAR(law.effective_rate(d), p.rate, 1e-13 * p.rate);
    }
  }
}

TEST(AnisotropicViscousLaw, StressesDoNotDependOnRateMagnitude) {
  const Laws laws;
  const ViscousLaw scalar = RateIndependent();
  const AnisotropicViscousLaw law(laws.yld, scalar, 0.2);
  const PlaneVector d(0.7, -0.2, 0.35);
  const PlaneVector s1 = law.evaluate(kSy, 0.0, d).stress;
  for (double k : {1e-6, 1e-2, 1e2, 1e6}) {
    EXPECT_LT((law.evaluate(kSy, 0.0, k * d).stress - s1).norm(), 1e-9 * kSy) << k;
  }
}

TEST(AnisotropicViscousLaw, TangentAndPotentialMatchFiniteDifferences) {
  const Laws laws;
  for (double cutoff : {1e-3, 1e-8}) {
    const ViscousLaw scalar = RateDependent(cutoff);
    for (const PlaneStressYield* yield : laws.all()) {
      const AnisotropicViscousLaw law(*yield, scalar, 0.3);
      for (const PlaneVector& d :
           {PlaneVector(0.31, -0.07, 0.12), PlaneVector(1, 1, 0), PlaneVector(1, 0, 0),
            PlaneVector(0.5, -0.5, 0), PlaneVector(0, 0, 1), PlaneVector(2e-3, 1e-3, -5e-4)}) {
        const AnisotropicViscousLaw::Point p = law.evaluate(kSy, 30.0, d);
        ASSERT_TRUE(p.converged);
        EXPECT_LT((p.tangent - p.tangent.transpose()).norm(), 1e-10 * p.tangent.norm());
        const double h = 1e-6 * d.norm();
        for (int j = 0; j < 3; ++j) {
          PlaneVector dp = d, dm = d;
          dp(j) += h;
          dm(j) -= h;
          const AnisotropicViscousLaw::Point a = law.evaluate(kSy, 30.0, dp);
          const AnisotropicViscousLaw::Point b = law.evaluate(kSy, 30.0, dm);
          const PlaneVector ds = (a.stress - b.stress) / (2 * h);
          EXPECT_LT((ds - p.tangent.col(j)).norm(), 1e-6 * p.tangent.norm())
              << "d=" << d.transpose() << " col " << j << " cutoff " << cutoff;
          EXPECT_NEAR((a.potential - b.potential) / (2 * h), p.stress(j), 1e-6 * p.stress.norm());
        }
      }
    }
  }
}

TEST(AnisotropicViscousLaw, NearRigidLimitIsLinearViscousAndSmooth) {
  const Laws laws;
  const double cutoff = 1e-6;
  const ViscousLaw scalar = RateIndependent(cutoff);
  const PlaneVector d0(0.6, -0.1, 0.3);
  for (const PlaneStressYield* yield : laws.all()) {
    const AnisotropicViscousLaw law(*yield, scalar, 0.5);
    // e << e_c: s = (f(e_c) / e_c) g(d), linear in d.
    const AnisotropicViscousLaw::Point tiny = law.evaluate(kSy, 0.0, 1e-15 * d0);
    const AnisotropicViscousLaw::Point small = law.evaluate(kSy, 0.0, 1e-12 * d0);
    ASSERT_TRUE(tiny.converged && small.converged);
    EXPECT_LT((small.stress - 1e3 * tiny.stress).norm(), 1e-5 * small.stress.norm());
    EXPECT_LT((small.tangent - tiny.tangent).norm(), 1e-5 * small.tangent.norm());
    // The stress grows monotonically to the flow stress through the cut-off.
    double previous = 0.0;
    for (double k = 1e-9; k < 1e-2; k *= 2.0) {
      const AnisotropicViscousLaw::Point p = law.evaluate(kSy, 0.0, k * d0);
      const double sigma_bar = yield->effective_stress(law.axes().stress_to_material(p.stress));
      EXPECT_GT(sigma_bar, previous);
      EXPECT_LT(sigma_bar, kSy * (1.0 + 1e-12));
      previous = sigma_bar;
    }
    EXPECT_NEAR(previous, kSy, 1e-6 * kSy);
    // d = 0: zero stress, finite symmetric positive definite tangent.
    const AnisotropicViscousLaw::Point zero = law.evaluate(kSy, 0.0, PlaneVector::Zero());
    EXPECT_EQ(zero.stress.norm(), 0.0);
    EXPECT_TRUE(zero.tangent.allFinite());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<PlaneMatrix>(zero.tangent).eigenvalues().minCoeff(),
              0.0);
  }
}

TEST(AnisotropicViscousLaw, FlowDirectionWarmStartsTheLocalSolve) {
  const Laws laws;
  const ViscousLaw scalar = RateDependent(1e-4);
  const AnisotropicViscousLaw law(laws.yld, scalar, 0.7);
  const PlaneVector d(0.4, 0.1, -0.2);
  const AnisotropicViscousLaw::Point first = law.evaluate(kSy, 5.0, d);
  const PlaneVector d_next = d + PlaneVector(0.004, -0.002, 0.003);  // a Newton update
  const AnisotropicViscousLaw::Point cold = law.evaluate(kSy, 5.0, d_next);
  const AnisotropicViscousLaw::Point warm = law.evaluate(kSy, 5.0, d_next, &first.flow_direction);
  EXPECT_LE(warm.iterations, 3);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LT((warm.stress - cold.stress).norm(), 1e-10 * cold.stress.norm());
  EXPECT_LT((warm.tangent - cold.tangent).norm(), 1e-9 * cold.tangent.norm());
}

TEST(AnisotropicViscousLaw, MaterialAxesConvention) {
  const double beta = 0.37;
  const MaterialAxes axes(beta);
  // Work invariance: T_s^T T = I.
  EXPECT_LT(
      (axes.stress_rotation().transpose() * axes.rate_rotation() - PlaneMatrix::Identity()).norm(),
      1e-15);
  // A unit stress and a unit stretching along RD = (cos beta, sin beta) are (1, 0, 0) in material
  // axes.
  const double c = std::cos(beta), s = std::sin(beta);
  EXPECT_LT(
      (axes.stress_to_material(PlaneVector(c * c, s * s, c * s)) - PlaneVector(1, 0, 0)).norm(),
      1e-15);
  EXPECT_LT(
      (axes.rate_to_material(PlaneVector(c * c, s * s, 2 * c * s)) - PlaneVector(1, 0, 0)).norm(),
      1e-15);
}

// Uniaxial tension along the local angle phi of a law: the local rate (normality in material axes,
// rotated back with T^-1 = T_s^T) and the resulting local stress.
struct LocalTension {
  PlaneVector d;
  PlaneVector stress;
};
LocalTension TensionAt(const AnisotropicViscousLaw& law, double phi) {
  const PlaneVector u_local = uniaxial_stress_direction(phi);
  const PlaneVector n = law.yield().evaluate(law.axes().stress_to_material(u_local)).gradient;
  const PlaneVector d = law.axes().stress_rotation().transpose() * n;
  return {d, law.evaluate(kSy, 0.0, d).stress};
}

TEST(AnisotropicViscousLaw, RotatedMaterialRespondsAtTheMaterialAngle) {
  const Laws laws;
  const ViscousLaw scalar = RateIndependent();
  for (const PlaneStressYield* yield : laws.all()) {
    // RD at 20 degrees to e1, tension at 50 degrees to e1: 30 degrees to RD (not -30 or 70).
    const AnisotropicViscousLaw law(*yield, scalar, 20 * kDeg);
    const LocalTension t = TensionAt(law, 50 * kDeg);
    const DirectionalResponse ref = uniaxial_response(*yield, 30 * kDeg);
    EXPECT_NEAR(lankford_ratio(t.d, 50 * kDeg), ref.r_value, 1e-11);
    EXPECT_LT((t.stress - kSy * ref.stress * uniaxial_stress_direction(50 * kDeg)).norm(),
              1e-9 * kSy);
    EXPECT_GT(std::abs(ref.r_value - uniaxial_response(*yield, 70 * kDeg).r_value), 0.05);
  }
}

TEST(AnisotropicViscousLaw, RotationBy90DegreesSwapsR0AndR90) {
  const ViscousLaw scalar = RateIndependent();
  const AnisotropyData data = Tuat();
  const AnisotropyData swapped = SwapAxes(data);
  const Hill48 hill(hill48_from_r_values(data.r0, data.r45, data.r90));
  const Hill48 hill_swapped(hill48_from_r_values(swapped.r0, swapped.r45, swapped.r90));
  const Yld2000 yld(Fit(data));
  const Yld2000 yld_swapped(Fit(swapped));
  const double hill_sigma90 = uniaxial_response(hill, 90 * kDeg).stress;
  const struct {
    const PlaneStressYield* law;
    const PlaneStressYield* swapped;
    double sigma90;
  } cases[] = {{&hill, &hill_swapped, hill_sigma90}, {&yld, &yld_swapped, data.sigma90}};
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto& c : cases) {
    const AnisotropicViscousLaw rotated(*c.law, scalar, 90 * kDeg);  // RD along e2
    const AnisotropicViscousLaw reference(*c.swapped, scalar, 0.0);
    // Tension along e1 (= TD of the rotated material) shows r90, along e2 r0.
    EXPECT_NEAR(lankford_ratio(TensionAt(rotated, 0.0).d, 0.0), data.r90, 1e-11);
    EXPECT_NEAR(lankford_ratio(TensionAt(rotated, 90 * kDeg).d, 90 * kDeg), data.r0, 1e-11);
    // The same law as the one identified from the swapped data, up to the unit of stress.
    for (int i = 0; i < 20; ++i) {
      const PlaneVector d(u(rng), u(rng), u(rng));
      const PlaneVector s_rot = rotated.evaluate(kSy, 0.0, d).stress;
      const PlaneVector s_ref = c.sigma90 * reference.evaluate(kSy, 0.0, d).stress;
      EXPECT_LT((s_rot - s_ref).norm(), 1e-9 * kSy) << d.transpose();
    }
  }
}

}  // namespace
}  // namespace vs
