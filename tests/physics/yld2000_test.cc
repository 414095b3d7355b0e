// Barlat Yld2000-2d (forward/material/yld2000.h, yld2000_fit.h): isotropic reductions, derivatives
// against finite differences (including the series branch near equal principal values), a
// published coefficient set against its published input data, the identification recovering
// coefficient sets, and the local dual solve at many rate directions.
#include "material/yld2000.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/error.h"
#include "material/dual_potential.h"
#include "material/yld2000_fit.h"

namespace vs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// AA2090-T3, a = 8: Barlat et al. (2003), Int J Plasticity 19:1297-1319, section 5 (the
// coefficients of their Yld2000-2d fit and the experimental input data: yield stresses normalised
// by sigma0, r-values, balanced biaxial). The numbers were transcribed from the paper as widely
// reproduced; they are corroborated here independently: the coefficients predict the input data to
// the rounding of the published 4-digit coefficients (PublishedAa2090T3PredictsItsInputData).
Yld2000Coefficients Aa2090T3() {
  Yld2000Coefficients c;
  c.alpha = {0.4865, 1.3783, 0.7536, 1.0246, 1.0363, 0.9036, 1.2321, 1.4858};
  c.exponent = 8.0;
  return c;
}
AnisotropyData Aa2090T3Data() {
  AnisotropyData d;
  d.sigma45 = 0.811;
  d.sigma90 = 0.910;
  d.sigma_b = 1.035;
  d.r0 = 0.2115;
  d.r45 = 1.5769;
  d.r90 = 0.6923;
  d.r_b = 0.670;
  return d;
}

// Principal in-plane stresses.
Eigen::Vector2d Principal(const PlaneVector& s) {
  const double m = 0.5 * (s(0) + s(1));
  const double r = std::hypot(0.5 * (s(0) - s(1)), s(2));
  return {m + r, m - r};
}

TEST(Yld2000, IsotropicCoefficientsGiveHosfordAndVonMises) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-200.0, 200.0);
  for (double a : {2.0, 4.0, 6.0, 8.0, 7.3}) {
    Yld2000Coefficients c;
    c.exponent = a;
    const Yld2000 y(c);
    for (int i = 0; i < 20; ++i) {
      const PlaneVector s(u(rng), u(rng), u(rng));
      const Eigen::Vector2d p = Principal(s);
      const double hosford =
          std::pow(0.5 * (std::pow(std::abs(p(0) - p(1)), a) + std::pow(std::abs(p(0)), a) +
                          std::pow(std::abs(p(1)), a)),
                   1.0 / a);
      EXPECT_NEAR(y.effective_stress(s), hosford, 1e-12 * hosford) << "a=" << a;
      if (a == 2.0 || a == 4.0) {  // Hosford is von Mises for a = 2 and 4
        const double vm = std::sqrt(s(0) * s(0) + s(1) * s(1) - s(0) * s(1) + 3 * s(2) * s(2));
        EXPECT_NEAR(y.effective_stress(s), vm, 1e-12 * vm) << "a=" << a;
      }
    }
  }
}

// Stress directions covering the smooth and the series branches: uniaxial, equibiaxial (X'' with
// equal principal values), near-equibiaxial at several distances, shear, random.
std::vector<PlaneVector> TestStresses() {
  std::vector<PlaneVector> out = {{1, 0, 0},   {0, 1, 0},       {1, 1, 0},   {1, -1, 0},
                                  {0, 0, 1},   {0.5, 0.5, 0.5}, {-1, -1, 0}, {2, 1, 0},
                                  {1, 2, 0.3}, {-0.3, 1, -0.7}};
  for (double eps : {1e-9, 1e-6, 1e-3, 0.03, 0.1, 0.3}) {
    out.push_back({1.0, 1.0 + eps, 0.0});
    out.push_back({1.0, 1.0 - eps, 0.5 * eps});
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 20; ++i) out.push_back({u(rng), u(rng), u(rng)});
  return out;
}

TEST(Yld2000, GradientAndHessianMatchFiniteDifferences) {
  Yld2000Coefficients steel;  // an arbitrary anisotropic set, a = 6
  steel.alpha = {0.9, 1.15, 1.05, 0.95, 0.92, 1.1, 1.03, 0.97};
  steel.exponent = 6.0;
  Yld2000Coefficients odd = Aa2090T3();  // non-integer exponent: the general series
  odd.exponent = 7.3;
  for (const Yld2000Coefficients& c : {Aa2090T3(), steel, odd}) {
    const Yld2000 y(c);
    for (const PlaneVector& s0 : TestStresses()) {
      const PlaneVector s = 150.0 * s0;  // MPa-sized
      const YieldPoint p = y.evaluate(s);
      ASSERT_NEAR(p.value, y.effective_stress(s), 1e-12 * p.value);
      // Euler: s . n = sigma_bar, Hessian annihilates s.
      EXPECT_NEAR(s.dot(p.gradient), p.value, 1e-11 * p.value);
      EXPECT_LT((p.hessian * s).norm(), 1e-10 * p.hessian.norm() * s.norm());
      const double h = 1e-5 * s.norm();
      for (int j = 0; j < 3; ++j) {
        PlaneVector sp = s, sm = s;
        sp(j) += h;
        sm(j) -= h;
        const double dv = (y.effective_stress(sp) - y.effective_stress(sm)) / (2 * h);
        EXPECT_NEAR(dv, p.gradient(j), 1e-8 * p.gradient.norm()) << s0.transpose();
        const PlaneVector dg = (y.evaluate(sp).gradient - y.evaluate(sm).gradient) / (2 * h);
        EXPECT_LT((dg - p.hessian.col(j)).norm(), 1e-6 * p.hessian.norm())
            << "a=" << c.exponent << " s=" << s0.transpose() << " col " << j;
      }
    }
  }
}

TEST(Yld2000, SeriesAndClosedFormBranchesAgreeAcrossTheSwitch) {
  // X'' principal-value gap sqrt(q) = |x|/10 is the switch; scan through it continuously.
  const Yld2000 y(Aa2090T3());
  double previous = 0.0;
  PlaneVector previous_gradient = PlaneVector::Zero();
  for (int i = 0; i <= 400; ++i) {
    const double eps = 0.2 * i / 400.0;
    const PlaneVector s(1.0, 1.0 - eps, 0.0);
    const YieldPoint p = y.evaluate(s);
    if (i > 0) {
      EXPECT_LT(std::abs(p.value - previous), 1e-3);
      EXPECT_LT((p.gradient - previous_gradient).norm(), 1e-2);
    }
    previous = p.value;
    previous_gradient = p.gradient;
  }
}

TEST(Yld2000, PublishedAa2090T3PredictsItsInputData) {
  const AnisotropyData pred = predicted_anisotropy_data(Yld2000(Aa2090T3()));
  const AnisotropyData data = Aa2090T3Data();
  // 4-digit coefficients: the stresses to 1e-3, the r-values to 5e-3.
  EXPECT_NEAR(pred.sigma0, 1.0, 1e-3);
  EXPECT_NEAR(pred.sigma45, data.sigma45, 1e-3);
  EXPECT_NEAR(pred.sigma90, data.sigma90, 1e-3);
  EXPECT_NEAR(pred.sigma_b, data.sigma_b, 1e-3);
  EXPECT_NEAR(pred.r0, data.r0, 5e-3);
  EXPECT_NEAR(pred.r45, data.r45, 5e-3);
  EXPECT_NEAR(pred.r90, data.r90, 5e-3);
  EXPECT_NEAR(pred.r_b, data.r_b, 5e-3);
}

TEST(Yld2000, IdentificationRecoversPublishedCoefficients) {
  // Exact round trip: the data the published coefficients predict give back the coefficients.
  const Yld2000Coefficients published = Aa2090T3();
  const Yld2000FitSummary fit = fit_yld2000(predicted_anisotropy_data(Yld2000(published)));
  ASSERT_TRUE(fit.converged) << fit.message;
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(fit.coefficients.alpha[i], published.alpha[i], 1e-9) << "alpha" << i + 1;
  }
  // From the published (rounded) input data: the published coefficients to about their rounding
  // (measured: largest difference 1.1e-3, alpha1 0.4876 against 0.4865).
  const Yld2000FitSummary fit_data = fit_yld2000(Aa2090T3Data());
  ASSERT_TRUE(fit_data.converged) << fit_data.message;
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(fit_data.coefficients.alpha[i], published.alpha[i], 2e-3) << "alpha" << i + 1;
  }
  const AnisotropyData back = predicted_anisotropy_data(Yld2000(fit_data.coefficients));
  EXPECT_NEAR(back.sigma0, 1.0, 1e-11);
  EXPECT_NEAR(back.sigma45, 0.811, 1e-11);
  EXPECT_NEAR(back.r45, 1.5769, 1e-11);
  EXPECT_NEAR(back.r_b, 0.670, 1e-11);
}

TEST(Yld2000, IdentificationRoundTripsForSteelAndIsotropy) {
  Yld2000Coefficients steel;
  steel.alpha = {0.9, 1.15, 1.05, 0.95, 0.92, 1.1, 1.03, 0.97};
  steel.exponent = 6.0;
  const AnisotropyData data = predicted_anisotropy_data(Yld2000(steel));
  Yld2000FitOptions options;
  options.exponent = 6.0;
  const Yld2000FitSummary fit = fit_yld2000(data, options);
  ASSERT_TRUE(fit.converged) << fit.message;
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(fit.coefficients.alpha[i], steel.alpha[i], 1e-9);

  const Yld2000FitSummary iso = fit_yld2000(AnisotropyData{});
  ASSERT_TRUE(iso.converged);
  EXPECT_EQ(iso.iterations, 0);
  for (double a : iso.coefficients.alpha) EXPECT_EQ(a, 1.0);
}

TEST(Yld2000, BadDataThrowInputError) {
  AnisotropyData d;
  d.r45 = -0.2;
  EXPECT_THROW(fit_yld2000(d), InputError);
  Yld2000FitOptions options;
  options.exponent = 1.5;
  EXPECT_THROW(fit_yld2000(AnisotropyData{}, options), InputError);
  Yld2000Coefficients c;
  c.alpha[3] = std::nan("");
  EXPECT_THROW((Yld2000(c)), InputError);
}

// The local solve of the dual: normal parallel to d, on the unit surface, e = d . m.
void ExpectDualPoint(const Yld2000& y, const PlaneVector& d, const DualPoint& p) {
  ASSERT_TRUE(p.converged) << d.transpose();
  const YieldPoint at_m = y.evaluate(p.direction);
  EXPECT_NEAR(at_m.value, 1.0, 1e-12);
  EXPECT_LT((at_m.gradient.normalized() - d.normalized()).norm(), 1e-11) << d.transpose();
  EXPECT_NEAR(p.rate, d.dot(p.direction), 1e-12 * d.norm());
}

TEST(Yld2000, DualSolveConvergesAtManyDirections) {
  const Yld2000 y(Aa2090T3());
  int worst = 0;
  // Named states: uniaxial flow at 0/45/90, equibiaxial, plane strain, pure shear.
  std::vector<PlaneVector> rates = {{1, 1, 0},  {-1, -1, 0}, {1, 0, 0}, {0, 1, 0},
                                    {1, -1, 0}, {0, 0, 1},   {0, 0, -1}};
  for (double theta : {0.0, 45.0, 90.0}) {
    rates.push_back(y.evaluate(uniaxial_stress_direction(theta * kDeg)).gradient);
  }
  for (int i = 0; i < 360; ++i) {  // a circle in (d11, d22) at three shear levels
    const double t = i * kDeg;
    for (double shear : {0.0, 0.3, 2.0}) rates.push_back({std::cos(t), std::sin(t), shear});
  }
  for (const PlaneVector& d : rates) {
    const DualPoint p = y.dual(d);
    ExpectDualPoint(y, d, p);
    worst = std::max(worst, p.iterations);
  }
  EXPECT_LE(worst, 15);
}

TEST(Yld2000, DualSolveIsScaleFreeAndWarmStarts) {
  const Yld2000 y(Aa2090T3());
  const PlaneVector d0(0.8, -0.3, 0.45);
  const DualPoint ref = y.dual(d0);
  for (double k : {1e-300, 1e-20, 1e-9, 1e6, 1e200}) {
    const DualPoint p = y.dual(k * d0);
    ASSERT_TRUE(p.converged);
    EXPECT_NEAR(p.rate / k, ref.rate, 1e-12 * ref.rate) << k;
    EXPECT_LT((p.direction - ref.direction).norm(), 1e-12);
    EXPECT_LT((p.hessian - ref.hessian).norm(), 1e-10 * ref.hessian.norm());
  }
  // Warm start from a nearby direction: a few iterations.
  const PlaneVector d1 = d0 + PlaneVector(0.01, 0.02, -0.01);
  const DualPoint warm = y.dual(d1, &ref.direction);
  ExpectDualPoint(y, d1, warm);
  EXPECT_LE(warm.iterations, 3);
  EXPECT_LT(warm.iterations, y.dual(d1).iterations);
  // d = 0: no direction, finite symmetric positive definite H.
  const DualPoint zero = y.dual(PlaneVector::Zero());
  EXPECT_TRUE(zero.converged);
  EXPECT_EQ(zero.rate, 0.0);
  EXPECT_EQ(zero.direction.norm(), 0.0);
  EXPECT_TRUE(zero.hessian.allFinite());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<PlaneMatrix>(zero.hessian).eigenvalues().minCoeff(), 0.0);
}

TEST(Yld2000, DualHessianIsTheJacobianOfTheDualGradient) {
  // g(d) = e m = d(e^2/2)/dd, H = dg/dd.
  const Yld2000 y(Aa2090T3());
  for (const PlaneVector& d : {PlaneVector(1, 1, 0), PlaneVector(1, -0.2, 0.1),
                               PlaneVector(-0.3, 0.9, 0.6), PlaneVector(0.2, -0.7, -1.1)}) {
    const DualPoint p = y.dual(d);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      PlaneVector dp = d, dm = d;
      dp(j) += h;
      dm(j) -= h;
      const DualPoint a = y.dual(dp), b = y.dual(dm);
      const PlaneVector dg = (a.rate * a.direction - b.rate * b.direction) / (2 * h);
      EXPECT_LT((dg - p.hessian.col(j)).norm(), 1e-7 * p.hessian.norm()) << d.transpose();
      // and de/dd = m
      EXPECT_NEAR((a.rate - b.rate) / (2 * h), p.direction(j), 1e-8);
    }
  }
}

// The coefficients of the earing calibration's failed run (experiments/10_earing: UA yield-stress
// ratios, r0 0.525, r_b 1, r45 0.292, r90 0.724, a = 8) are not extreme and the local solve is
// sound over the whole sphere of rate directions: it converges (measured: at most 8 iterations),
// and its H is the Jacobian of g = e m. (That run's first step failed in the element's
// primal-dual tangent, shell9.h, not here.) What matters there: the unit ball sigma_bar(n) <= 1
// is not inside the ellipsoid n^T K(m) n <= 1 (K = H^-1 at m): at the equibiaxial point the
// pure-shear point of the ball has n^T K n > 5.
TEST(Yld2000, EaringCalibrationCoefficientsSolveEverywhere) {
  AnisotropyData data;
  data.sigma45 = 0.867;
  data.sigma90 = 0.926;
  data.sigma_b = 0.975;
  data.r0 = 0.525;
  data.r45 = 0.292;
  data.r90 = 0.724;
  data.r_b = 1.0;
  const Yld2000FitSummary fit = fit_yld2000(data);
  ASSERT_TRUE(fit.converged) << fit.message;
  for (double a : fit.coefficients.alpha) {
    EXPECT_GT(a, 0.75);
    EXPECT_LT(a, 1.5);
  }
  const Yld2000 y(fit.coefficients);
  int worst = 0;
  for (int i = 0; i < 72; ++i) {
    for (int j = 0; j <= 36; ++j) {
      const double t = 5.0 * i * kDeg, p = (5.0 * j - 90.0) * kDeg;
      const PlaneVector d(std::cos(p) * std::cos(t), std::cos(p) * std::sin(t), std::sin(p));
      const DualPoint dp = y.dual(d);
      ExpectDualPoint(y, d, dp);
      worst = std::max(worst, dp.iterations);
      if (i % 6 != 0 || j % 6 != 0) continue;
      const double h = 1e-6;
      for (int k = 0; k < 3; ++k) {
        PlaneVector a = d, b = d;
        a(k) += h;
        b(k) -= h;
        const DualPoint pa = y.dual(a), pb = y.dual(b);
        const PlaneVector dg = (pa.rate * pa.direction - pb.rate * pb.direction) / (2.0 * h);
        EXPECT_LT((dg - dp.hessian.col(k)).norm(), 1e-6 * dp.hessian.norm()) << d.transpose();
      }
    }
  }
  EXPECT_LE(worst, 15);
  const DualPoint eb = y.dual(PlaneVector(1.0, 1.0, 0.0));
  const PlaneVector shear(0.0, 0.0, 1.0);
  const PlaneVector n = shear / y.effective_stress(shear);
  EXPECT_GT(n.dot(eb.hessian.inverse() * n), 5.0);
  EXPECT_NEAR(eb.direction.dot(eb.hessian.inverse() * eb.direction), 1.0, 1e-9);
}

}  // namespace
}  // namespace vs
