// Closed-form checks of the viscous-shell constitutive law (material/viscous_law, hardening):
// uniaxial, plane-strain and equibiaxial stresses at any rate magnitude, Hill normal anisotropy
// identities, potential and tangent consistency, Perzyna eq. (7), hardening laws.
#include <gtest/gtest.h>

#include <cmath>

#include "material/hardening.h"
#include "material/viscous_law.h"

namespace vs {
namespace {

constexpr double kSy = 250.0;   // flow stress [MPa]
constexpr double kCut = 1e-12;  // negligible cut-off: rate-independent limit

ViscousLaw RateIndependent(double R) { return ViscousLaw(RateSpec{}, kCut, R); }

Eigen::Vector2d Stress(const ViscousLaw& law, Eigen::Vector2d d) {
  return law.evaluate(kSy, 0.0, d).stress;
}

TEST(Constitutive, IsotropicMatrixIsPaperEq21) {
  const Eigen::Matrix2d A = anisotropy_matrix(1.0);
  EXPECT_DOUBLE_EQ(A(0, 0), 4.0);
  EXPECT_DOUBLE_EQ(A(0, 1), 2.0);
  EXPECT_DOUBLE_EQ(A(1, 0), 2.0);
  EXPECT_DOUBLE_EQ(A(1, 1), 4.0);
}

class ClosedForms : public ::testing::TestWithParam<double> {};

TEST_P(ClosedForms, UniaxialTensionGivesFlowStressAndLankfordRatio) {
  const double R = GetParam();
  const ViscousLaw law = RateIndependent(R);
  // Hill flow rule in uniaxial tension: width rate / length rate = -R / (1 + R).
  for (double scale : {1e-3, 1.0, 1e3}) {
    const Eigen::Vector2d d = scale * Eigen::Vector2d(1.0, -R / (1.0 + R));
    const Eigen::Vector2d s = Stress(law, d);
    EXPECT_NEAR(s(0), kSy, 1e-9 * kSy) << "R=" << R << " scale=" << scale;
    EXPECT_NEAR(s(1), 0.0, 1e-9 * kSy);
    // Width / thickness strain-rate ratio equals R (incompressibility gives the thickness rate).
    const double thickness_rate = -(d(0) + d(1));
    EXPECT_NEAR(d(1) / thickness_rate, R, 1e-12);
    // Plastic work: sigma_bar * e = s . d.
    EXPECT_NEAR(kSy * law.effective_rate(d), s.dot(d), 1e-9 * kSy * scale);
  }
}

TEST_P(ClosedForms, EquibiaxialAndPlaneStrainMatchHill48) {
  const double R = GetParam();
  const ViscousLaw law = RateIndependent(R);
  const Eigen::Vector2d sb = Stress(law, {1.0, 1.0});
  EXPECT_NEAR(sb(0), kSy * std::sqrt((1.0 + R) / 2.0), 1e-9 * kSy);
  EXPECT_NEAR(sb(1), sb(0), 1e-9 * kSy);
  const Eigen::Vector2d sp = Stress(law, {1.0, 0.0});
  EXPECT_NEAR(sp(0), kSy * (1.0 + R) / std::sqrt(1.0 + 2.0 * R), 1e-9 * kSy);
  EXPECT_NEAR(sp(1), sp(0) * R / (1.0 + R), 1e-9 * kSy);
  // Equibiaxial effective strain |eps_t| sqrt((1+R)/2) (literature.md 8.2).
  EXPECT_NEAR(law.effective_rate({1.0, 1.0}), 2.0 * std::sqrt((1.0 + R) / 2.0), 1e-12);
}

TEST_P(ClosedForms, StressesDoNotDependOnRateMagnitude) {
  const ViscousLaw law = RateIndependent(GetParam());
  const Eigen::Vector2d d(0.7, -0.2);
  const Eigen::Vector2d s1 = Stress(law, d);
  for (double k : {1e-6, 1e-2, 1e2, 1e6}) {
    EXPECT_NEAR((Stress(law, k * d) - s1).norm(), 0.0, 1e-9 * kSy) << k;
  }
}

TEST_P(ClosedForms, PotentialGradientIsStressAndTangentIsItsJacobian) {
  const ViscousLaw law(RateSpec{RateLaw::kPower, 1.0, 1.0, 0.02, 1.0}, 1e-3, GetParam());
  const double hv = 30.0;
  const Eigen::Vector2d d(0.31, -0.07);
  const ViscousLaw::Point p = law.evaluate(kSy, hv, d);
  const double h = 1e-6;
  Eigen::Matrix2d J;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d dp = d, dm = d;
    dp(j) += h;
    dm(j) -= h;
    const ViscousLaw::Point pp = law.evaluate(kSy, hv, dp), pm = law.evaluate(kSy, hv, dm);
    EXPECT_NEAR((pp.potential - pm.potential) / (2 * h), p.stress(j), 1e-6 * kSy);
    J.col(j) = (pp.stress - pm.stress) / (2 * h);
  }
  const Eigen::Vector2d Ad = law.A() * d;
  const Eigen::Matrix2d Dt = p.mu * law.A() + p.tangent_coef * Ad * Ad.transpose();
  EXPECT_NEAR((J - Dt).norm(), 0.0, 1e-5 * Dt.norm());
}

INSTANTIATE_TEST_SUITE_P(RValues, ClosedForms, ::testing::Values(0.2, 0.41, 1.0, 2.0, 5.0));

TEST(Constitutive, RIsOneIsVonMises) {
  const ViscousLaw law = RateIndependent(1.0);
  // von Mises plane stress: e^2 = 4/3 (d1^2 + d2^2 + d1 d2), sigma = 2 sigma_y/(3 e) (2d1 + d2,
  // ..).
  const Eigen::Vector2d d(0.4, 0.1);
  const double e = std::sqrt(4.0 / 3.0 * (d(0) * d(0) + d(1) * d(1) + d(0) * d(1)));
  EXPECT_NEAR(law.effective_rate(d), e, 1e-14);
  const Eigen::Vector2d s = Stress(law, d);
  EXPECT_NEAR(s(0), 2.0 * kSy / (3.0 * e) * (2 * d(0) + d(1)), 1e-9 * kSy);
  const double mises = std::sqrt(s(0) * s(0) + s(1) * s(1) - s(0) * s(1));
  EXPECT_NEAR(mises, kSy, 1e-9 * kSy);
}

TEST(Constitutive, EquibiaxialOverUniaxialYieldRatio) {
  for (double R : {0.5, 1.0, 2.0}) {
    const ViscousLaw law = RateIndependent(R);
    EXPECT_NEAR(Stress(law, {1.0, 1.0})(0) / kSy, std::sqrt((1.0 + R) / 2.0), 1e-10);
  }
  // The literature.md 8.2 numbers: R = 2 gives 1.2247 and plane strain 1.3416.
  const ViscousLaw law = RateIndependent(2.0);
  EXPECT_NEAR(Stress(law, {1.0, 1.0})(0) / kSy, 1.2247, 1e-4);
  EXPECT_NEAR(Stress(law, {1.0, 0.0})(0) / kSy, 1.3416, 1e-4);
}

TEST(Constitutive, PerzynaSatisfiesPaperEquation7) {
  // eq. (7): mu = (sigma_y + (e/gamma)^(1/n)) / (3 e), i.e. e = gamma (3 mu e - sigma_y)^n.
  const RateSpec r{RateLaw::kPerzyna, 0.5, 3.0, 0.0, 1.0};
  const ViscousLaw law(r, 1e-12, 1.0);
  for (double e : {1e-3, 0.1, 10.0}) {
    const Eigen::Vector2d d = e * Eigen::Vector2d(1.0, -0.5);  // uniaxial: effective rate e
    const ViscousLaw::Point p = law.evaluate(kSy, 0.0, d);
    EXPECT_NEAR(p.rate, e, 1e-12 * e);
    EXPECT_NEAR(p.mu, (kSy + std::pow(e / 0.5, 1.0 / 3.0)) / (3.0 * e), 1e-9 * p.mu);
    EXPECT_NEAR(r.gamma_per_s * std::pow(3.0 * p.mu * e - kSy, r.exponent), e, 1e-8 * e);
  }
}

TEST(Constitutive, CutOffCapsViscositySmoothly) {
  const double ec = 1e-4;
  const ViscousLaw law(RateSpec{}, ec, 1.0);
  const double mu0 = law.evaluate(kSy, 0.0, {0.0, 0.0}).mu;
  EXPECT_NEAR(mu0, kSy / (3.0 * ec), 1e-9 * mu0);
  for (double e : {1e-6, 1e-5, 1e-4, 1e-3}) {
    EXPECT_LE(law.evaluate(kSy, 0.0, {e, -0.5 * e}).mu, mu0 * (1 + 1e-12));
  }
  // Far above the cut-off the flow stress is recovered to O((ec/e)^2).
  EXPECT_NEAR(law.effective_stress(kSy, 1e-2), kSy, 1e-4 * kSy);
}

TEST(Constitutive, ConstantViscosityIsTheElasticAnalogy) {
  const ViscousLaw law = ViscousLaw::Constant(3.0);
  const ViscousLaw::Point p = law.evaluate(0.0, 0.0, {1.0, 2.0});
  EXPECT_DOUBLE_EQ(p.mu, 3.0);
  EXPECT_DOUBLE_EQ(p.stress(0), 3.0 * (4.0 + 4.0));
  EXPECT_DOUBLE_EQ(p.stress(1), 3.0 * (2.0 + 8.0));
}

TEST(Hardening, LawsMatchTheirFormulas) {
  HardeningSpec swift;
  swift.law = HardeningLaw::kSwift;
  swift.K_MPa = 589;
  swift.eps0 = 0.0032;
  swift.n = 0.216;
  const Hardening hs(swift);
  EXPECT_NEAR(hs.flow_stress(0.1), 589 * std::pow(0.1032, 0.216), 1e-9);
  EXPECT_NEAR(hs.slope(0.1), 589 * 0.216 * std::pow(0.1032, 0.216 - 1), 1e-9);

  HardeningSpec hol;
  hol.law = HardeningLaw::kHollomon;
  hol.K_MPa = 500;
  hol.n = 0.2;
  hol.sigma0_MPa = 200;
  const Hardening hh(hol);
  const double plateau = std::pow(200.0 / 500.0, 1.0 / 0.2);
  EXPECT_DOUBLE_EQ(hh.flow_stress(0.0), 200.0);
  EXPECT_DOUBLE_EQ(hh.flow_stress(0.5 * plateau), 200.0);
  EXPECT_NEAR(hh.flow_stress(0.3), 500 * std::pow(0.3, 0.2), 1e-9);

  HardeningSpec voce;
  voce.law = HardeningLaw::kVoce;
  voce.sigma0_MPa = 140.2;
  voce.Q_MPa = 190;
  voce.b = 12.4;
  const Hardening hv(voce);
  EXPECT_NEAR(hv.flow_stress(0.2), 330.2 - 190 * std::exp(-12.4 * 0.2), 1e-9);
  EXPECT_NEAR(hv.slope(0.2), 190 * 12.4 * std::exp(-12.4 * 0.2), 1e-9);

  HardeningSpec tab;
  tab.law = HardeningLaw::kTable;
  tab.table_strain = {0.0, 0.1, 0.3};
  tab.table_stress_MPa = {200.0, 260.0, 300.0};
  tab.table_scale = 1.5;
  const Hardening ht(tab);
  EXPECT_NEAR(ht.flow_stress(0.05), 1.5 * 230.0, 1e-9);
  EXPECT_NEAR(ht.flow_stress(0.5), 1.5 * 340.0, 1e-9);  // last slope extrapolated
  EXPECT_NEAR(ht.slope(0.2), 1.5 * 200.0, 1e-9);
}

TEST(Hardening, ConsidereStrainOfSwift) {
  // Load maximum in uniaxial tension where d sigma / d eps = sigma: eps* = n - eps0 (8.1).
  HardeningSpec swift;
  swift.K_MPa = 589;
  swift.eps0 = 0.0032;
  swift.n = 0.216;
  const Hardening hs(swift);
  const double e = 0.216 - 0.0032;
  EXPECT_NEAR(hs.slope(e), hs.flow_stress(e), 1e-9 * hs.flow_stress(e));
}

}  // namespace
}  // namespace vs
