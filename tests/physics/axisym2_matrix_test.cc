// The element's written-out strain rates, forces and matrices (element/axisym2.cc) against the
// generic products of the definition, B^T D B with B = axisym2_B and D from ViscousLaw::evaluate
// at every thickness point; and the primal-dual tangent (material/flow_direction.h) against its
// two limits, Newton (n = m) and the direct iteration (n = 0).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "element/axisym2.h"

namespace vs {
namespace {

struct Reference {
  Vec6 force;
  Mat6 secant, tangent;
  double potential = 0.0;
};

// The definition with generic Eigen products (the element before it was written out).
Reference reference(const Axisym2Geometry& g, const Axisym2Section& sec, const ThicknessRule& rule,
                    const ViscousLaw& law, const Vec6& d, const std::vector<double>* n = nullptr) {
  const Mat56 B = axisym2_B(g);
  const Vec5 e = B * d;
  const double h = sec.thickness_mm;
  const Eigen::Matrix2d& A = law.A();
  Eigen::Matrix<double, 5, 5> Ds = Eigen::Matrix<double, 5, 5>::Zero(), Dt = Ds;
  Vec5 S = Vec5::Zero();
  double phi = 0.0;
  for (std::size_t k = 0; k < rule.zeta.size(); ++k) {
    const double z = rule.zeta[k] * h, w = rule.weight[k] * h;
    const Eigen::Vector2d dk(e(0) + z * e(2), e(1) + z * e(3));
    const ViscousLaw::Point p = law.evaluate((*sec.sigma_y)[k], (*sec.hardening_viscosity)[k], dk);
    const Eigen::Vector2d Ad = A * dk;
    const Eigen::Matrix2d Dsec = p.mu * A;
    Eigen::Matrix2d Dtan = Dsec + p.tangent_coef * Ad * Ad.transpose();
    if (n != nullptr) {
      const double eh = std::sqrt(dk.dot(Ad) / 3.0 + law.cutoff_rate() * law.cutoff_rate());
      const Eigen::Vector2d nk((*n)[2 * k], (*n)[2 * k + 1]);
      const Eigen::Matrix2d R = nk * Ad.transpose();
      Dtan = Dsec + 3.0 * eh * p.tangent_coef * 0.5 * (R + R.transpose());
    }
    for (int a = 0; a < 2; ++a) {
      S(a) += w * p.stress(a);
      S(2 + a) += w * z * p.stress(a);
    }
    phi += w * p.potential;
    Ds.block<2, 2>(0, 0) += w * Dsec;
    Ds.block<2, 2>(0, 2) += w * z * Dsec;
    Ds.block<2, 2>(2, 0) += w * z * Dsec;
    Ds.block<2, 2>(2, 2) += w * z * z * Dsec;
    Dt.block<2, 2>(0, 0) += w * Dtan;
    Dt.block<2, 2>(0, 2) += w * z * Dtan;
    Dt.block<2, 2>(2, 0) += w * z * Dtan;
    Dt.block<2, 2>(2, 2) += w * z * z * Dtan;
  }
  const double Gs = kShearCorrection * sec.shear_viscosity * h;
  S(4) = Gs * e(4);
  Ds(4, 4) = Dt(4, 4) = Gs;
  phi += 0.5 * Gs * e(4) * e(4);
  const double W = 2.0 * std::numbers::pi * g.mid_radius() * g.length();
  return {W * B.transpose() * S, W * B.transpose() * Ds * B, W * B.transpose() * Dt * B, W * phi};
}

class Axisym2Matrix : public ::testing::Test {
 protected:
  Axisym2Matrix() : law_(RateSpec{}, 2e-6, 1.7), rule_(simpson_rule(5)) {
    sy_ = {310.0, 305.0, 300.0, 296.0, 290.0};
    hv_ = {80.0, 85.0, 90.0, 95.0, 100.0};
    sec_ = Axisym2Section{0.8, &sy_, &hv_, 4000.0};
  }
  // A bent, stretched element away from the axis with a generic velocity.
  Axisym2Geometry g_{12.0, 3.0, 13.1, 3.4};
  Vec6 d_ = (Vec6() << 0.02, 0.9, -0.004, 0.05, 0.85, 0.003).finished();
  ViscousLaw law_;
  ThicknessRule rule_;
  std::vector<double> sy_, hv_;
  Axisym2Section sec_;
};

double rel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

TEST_F(Axisym2Matrix, StrainRatesAreBd) {
  const Vec5 ref = axisym2_B(g_) * d_;
  EXPECT_LT((axisym2_strain_rates(g_, d_) - ref).norm(), 1e-13 * ref.norm());
}

TEST_F(Axisym2Matrix, SecantTangentForceAndPotentialMatchTheGenericProducts) {
  const Reference ref = reference(g_, sec_, rule_, law_, d_);
  Axisym2Output s, t, p;
  axisym2_evaluate(g_, sec_, rule_, law_, d_, StiffnessKind::kSecant, &s);
  axisym2_evaluate(g_, sec_, rule_, law_, d_, StiffnessKind::kTangent, &t, 1.0);
  axisym2_evaluate(g_, sec_, rule_, law_, d_, StiffnessKind::kNone, &p);
  EXPECT_LT(rel(s.stiffness, ref.secant), 1e-12);
  EXPECT_LT(rel(t.stiffness, ref.tangent), 1e-12);
  EXPECT_LT(rel(t.tangent_part, ref.tangent - ref.secant), 1e-12);
  EXPECT_LT(rel(s.force, ref.force), 1e-12);
  EXPECT_NEAR(p.potential, ref.potential, 1e-12 * std::abs(ref.potential));
  EXPECT_NEAR(t.potential, ref.potential, 1e-12 * std::abs(ref.potential));
  // Blending: secant + weight * tangent part.
  Axisym2Output b;
  axisym2_evaluate(g_, sec_, rule_, law_, d_, StiffnessKind::kTangent, &b, 0.3);
  EXPECT_LT(rel(b.stiffness, ref.secant + 0.3 * (ref.tangent - ref.secant)), 1e-12);
}

TEST_F(Axisym2Matrix, ConstantViscosityMatchesTheGenericProducts) {
  const ViscousLaw constant = ViscousLaw::Constant(2.5, 1.3);
  const Reference ref = reference(g_, sec_, rule_, constant, d_);
  Axisym2Output t;
  axisym2_evaluate(g_, sec_, rule_, constant, d_, StiffnessKind::kTangent, &t);
  EXPECT_LT(rel(t.stiffness, ref.secant), 1e-12);
  EXPECT_LT(rel(t.stiffness, ref.tangent), 1e-12);
  EXPECT_EQ(t.tangent_part.norm(), 0.0);
}

TEST_F(Axisym2Matrix, PrimalDualTangentSpansSecantToNewton) {
  Axisym2Output t;
  axisym2_evaluate(g_, sec_, rule_, law_, d_, StiffnessKind::kTangent, &t);
  const Reference ref = reference(g_, sec_, rule_, law_, d_);
  // n = m (the element's own flow directions): Newton's tangent.
  std::vector<double> m = t.point_direction;
  Axisym2Section dual = sec_;
  dual.flow_direction = m.data();
  Axisym2Output tm;
  axisym2_evaluate(g_, dual, rule_, law_, d_, StiffnessKind::kTangent, &tm);
  EXPECT_LT(rel(tm.stiffness, ref.tangent), 1e-12);
  // n = 0: the secant matrix of the direct iteration.
  std::vector<double> zero(m.size(), 0.0);
  dual.flow_direction = zero.data();
  Axisym2Output t0;
  axisym2_evaluate(g_, dual, rule_, law_, d_, StiffnessKind::kTangent, &t0);
  EXPECT_LT(rel(t0.stiffness, ref.secant), 1e-12);
  // Any n: the symmetrised form of the header comment.
  std::vector<double> n = {0.3, -0.2, 0.1, 0.4, -0.5, 0.2, 0.0, 0.6, 0.25, -0.25};
  dual.flow_direction = n.data();
  Axisym2Output tn;
  axisym2_evaluate(g_, dual, rule_, law_, d_, StiffnessKind::kTangent, &tn);
  EXPECT_LT(rel(tn.stiffness, reference(g_, sec_, rule_, law_, d_, &n).tangent), 1e-12);
  EXPECT_LT((tn.stiffness - tn.stiffness.transpose()).norm(), 1e-14 * tn.stiffness.norm());
}

}  // namespace
}  // namespace vs
