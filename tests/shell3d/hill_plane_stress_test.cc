// The 3-component Hill point law (forward/shell3d/hill_plane_stress.h): closed-form stress states,
// Lankford ratio, planar isotropy, agreement with the axisymmetric 2x2 law, consistent tangent.
#include "material/hill_plane_stress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vs::shell3d {
namespace {

ViscousLaw plastic_law(double r_value) { return ViscousLaw(RateSpec{}, 1e-9, r_value); }

TEST(HillPlaneStress, IsotropicMatrixIsThePapersD1) {
  Mat3 expected;
  expected << 4, 2, 0, 2, 4, 0, 0, 0, 1;
  EXPECT_LT((anisotropy_matrix3(1.0) - expected).norm(), 1e-14);
}

TEST(HillPlaneStress, BlockMatchesAxisymmetricLaw) {
  for (double R : {0.5, 1.0, 1.8}) {
    EXPECT_LT((anisotropy_matrix3(R).topLeftCorner<2, 2>() - anisotropy_matrix(R)).norm(), 1e-13);
    EXPECT_NEAR(r_value_of(ViscousLaw::Constant(1.0, R)), R, 1e-13);
  }
}

TEST(HillPlaneStress, UniaxialTensionGivesFlowStressAndLankfordRatio) {
  for (double R : {0.6, 1.0, 2.0}) {
    const ViscousLaw law = plastic_law(R);
    const HillPlaneStressLaw hill(law);
    // s2 = 0 requires A21 d1 + A22 d2 = 0, i.e. d2 = -R/(1+R) d1.
    const Vec3 d(2.0, -2.0 * R / (1.0 + R), 0.0);
    const InPlanePoint p = hill.evaluate(150.0, 0.0, d);
    EXPECT_NEAR(p.stress(0), 150.0, 1e-6);
    EXPECT_NEAR(p.stress(1), 0.0, 1e-6);
    const double thickness_rate = -(d(0) + d(1));
    EXPECT_NEAR(d(1) / thickness_rate, R, 1e-12);
    // Plastic work identity s . d = sigma_bar * e.
    EXPECT_NEAR(p.stress.dot(d), 150.0 * p.rate, 1e-6);
  }
}

TEST(HillPlaneStress, PureShearMatchesHillForm) {
  for (double R : {0.5, 1.0, 2.5}) {
    const ViscousLaw law = plastic_law(R);
    const HillPlaneStressLaw hill(law);
    const InPlanePoint p = hill.evaluate(100.0, 0.0, Vec3(0.0, 0.0, 1e-2));
    // sigma_bar^2 = 2(1+2R)/(1+R) s12^2 with s11 = s22 = 0.
    EXPECT_NEAR(p.stress(0), 0.0, 1e-9);
    EXPECT_NEAR(p.stress(2), 100.0 / std::sqrt(2.0 * (1.0 + 2.0 * R) / (1.0 + R)), 1e-6);
  }
  // R = 1: von Mises, shear yield sigma_y / sqrt(3).
  const ViscousLaw law = plastic_law(1.0);
  EXPECT_NEAR(HillPlaneStressLaw(law).evaluate(100.0, 0.0, Vec3(0, 0, 1)).stress(2),
              100.0 / std::sqrt(3.0), 1e-6);
}

TEST(HillPlaneStress, PlanarIsotropyUnderInPlaneRotation) {
  const ViscousLaw law = plastic_law(1.7);
  const HillPlaneStressLaw hill(law);
  const Vec3 d(1.0, -0.3, 0.4);
  const Eigen::Matrix2d D{{d(0), 0.5 * d(2)}, {0.5 * d(2), d(1)}};
  const InPlanePoint p = hill.evaluate(80.0, 0.0, d);
  const Eigen::Matrix2d S{{p.stress(0), p.stress(2)}, {p.stress(2), p.stress(1)}};
  const double a = 0.37;
  const Eigen::Matrix2d Q{{std::cos(a), -std::sin(a)}, {std::sin(a), std::cos(a)}};
  const Eigen::Matrix2d Dr = Q * D * Q.transpose();
  const InPlanePoint pr = hill.evaluate(80.0, 0.0, Vec3(Dr(0, 0), Dr(1, 1), 2.0 * Dr(0, 1)));
  const Eigen::Matrix2d Sr = Q * S * Q.transpose();
  EXPECT_NEAR(pr.rate, p.rate, 1e-12);
  EXPECT_NEAR(pr.stress(0), Sr(0, 0), 1e-9);
  EXPECT_NEAR(pr.stress(1), Sr(1, 1), 1e-9);
  EXPECT_NEAR(pr.stress(2), Sr(0, 1), 1e-9);
}

TEST(HillPlaneStress, TangentMatchesFiniteDifferences) {
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.05;
  const ViscousLaw law(rate, 1e-4, 1.4);
  const HillPlaneStressLaw hill(law);
  const Vec3 d(0.7, -0.2, 0.3);
  const InPlanePoint p = hill.evaluate(120.0, 5.0, d);
  const Vec3 Ad = hill.A() * d;
  const Mat3 Dt = p.mu * hill.A() + p.tangent_coef * Ad * Ad.transpose();
  for (int j = 0; j < 3; ++j) {
    const double h = 1e-6;
    Vec3 dp = d, dm = d;
    dp(j) += h;
    dm(j) -= h;
    const Vec3 fd =
        (hill.evaluate(120.0, 5.0, dp).stress - hill.evaluate(120.0, 5.0, dm).stress) / (2.0 * h);
    EXPECT_LT((fd - Dt.col(j)).norm(), 1e-5 * Dt.col(j).norm());
    // The stress derives from the potential.
    const double dphi =
        (hill.evaluate(120.0, 5.0, dp).potential - hill.evaluate(120.0, 5.0, dm).potential) /
        (2.0 * h);
    EXPECT_NEAR(dphi, p.stress(j), 1e-5 * p.stress.norm());
  }
}

}  // namespace
}  // namespace vs::shell3d
