// The elastic start and the elastic part of the strains (material/elastic_start.h) against closed
// forms: the uniaxial elastic-plastic curve (total strain e = e_p + sigma_y(e_p) / E), its tangent
// E H / (E + H), Hooke's law in uniaxial and equibiaxial tension, and a point of the viscous law
// stepped along a uniaxial path with the backward-Euler hardening of the models.
#include "material/elastic_start.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "material/hardening.h"
#include "material/viscous_law.h"
#include "run/elastic_strains.h"

namespace vs {
namespace {

HardeningSpec swift() {
  HardeningSpec h;
  h.law = HardeningLaw::kSwift;
  h.K_MPa = 589.0;
  h.eps0 = 0.0032;
  h.n = 0.216;
  return h;
}

std::vector<HardeningSpec> laws() {
  std::vector<HardeningSpec> out{swift()};
  HardeningSpec ho;
  ho.law = HardeningLaw::kHollomon;
  ho.K_MPa = 500.0;
  ho.n = 0.25;
  ho.sigma0_MPa = 150.0;
  out.push_back(ho);
  HardeningSpec vo;
  vo.law = HardeningLaw::kVoce;
  vo.sigma0_MPa = 160.0;
  vo.Q_MPa = 120.0;
  vo.b = 12.0;
  out.push_back(vo);
  HardeningSpec ta;
  ta.law = HardeningLaw::kTable;
  ta.table_strain = {0.0, 0.01, 0.05, 0.3};
  ta.table_stress_MPa = {200.0, 260.0, 330.0, 450.0};
  out.push_back(ta);
  return out;
}

ElasticSpec steel() {
  ElasticSpec e;
  e.law = ElasticLaw::kIsotropic;
  e.E_MPa = 210000.0;
  e.nu = 0.3;
  return e;
}

// The uniaxial elastic-plastic curve, parametrised by the plastic strain: sigma = sigma_y(e_p) at
// total strain e_p + sigma / E; below the yield strain sigma = E e.
TEST(ElasticStart, IsTheUniaxialElasticPlasticCurve) {
  for (const HardeningSpec& spec : laws()) {
    const Hardening curve(spec);
    const Hardening flow(spec, steel());
    const double E = 210000.0, s0 = curve.curve_stress(0.0);
    EXPECT_EQ(flow.start_modulus_MPa(), E);
    // Elastic branch.
    for (double f : {0.0, 0.1, 0.5, 0.99}) {
      const double e = f * s0 / E;
      EXPECT_NEAR(flow.flow_stress(e), E * e, 1e-12 * s0);
      EXPECT_EQ(flow.slope(e), E);
    }
    // Plastic branch.
    for (double ep : {0.0, 1e-5, 1e-3, 0.004, 0.02, 0.1, 0.25, 0.6}) {
      const double sigma = curve.curve_stress(ep);
      const double e = ep + sigma / E;
      EXPECT_NEAR(flow.flow_stress(e), sigma, 1e-11 * sigma)
          << static_cast<int>(spec.law) << " " << ep;
      const double H = curve.curve_slope(ep);
      if (ep > 0.0 && !(spec.law == HardeningLaw::kTable && std::abs(ep - 0.05) < 1e-12)) {
        EXPECT_NEAR(flow.slope(e), E * H / (E + H), 1e-9 * E * H / (E + H) + 1e-9);
      }
    }
    // Below the curve, continuous at the yield strain, and approaching it at large strain.
    const double ey = s0 / E;
    EXPECT_NEAR(flow.flow_stress(ey * (1 + 1e-12)), s0, 1e-9 * s0);
    for (double e : {0.002, 0.01, 0.1, 0.5}) {
      EXPECT_LE(flow.flow_stress(e), curve.curve_stress(e));
      EXPECT_GE(flow.flow_stress(e), curve.curve_stress(e - curve.curve_stress(e) / E) - 1e-9);
    }
  }
}

// The slope is the derivative of the curve (central differences, Swift); flow_stress_and_slope
// (what the models call) gives both, bit for bit.
TEST(ElasticStart, SlopeIsTheDerivative) {
  const Hardening flow(swift(), steel());
  for (double e : {2e-4, 0.002, 0.01, 0.05, 0.3}) {
    double slope = 0.0;
    EXPECT_EQ(flow.flow_stress_and_slope(e, &slope), flow.flow_stress(e));
    EXPECT_EQ(slope, flow.slope(e));
    const double h = 1e-7 * std::max(e, 1e-3);
    const double fd = (flow.flow_stress(e + h) - flow.flow_stress(e - h)) / (2 * h);
    EXPECT_NEAR(flow.slope(e), fd, 1e-5 * std::abs(fd)) << e;
  }
}

// Without the elastic start (law none, or start = false) the flow stress is the curve, bit for
// bit.
TEST(ElasticStart, OffIsTheHardeningCurve) {
  ElasticSpec off = steel();
  off.start = false;
  for (const ElasticSpec& el : {ElasticSpec{}, off}) {
    const Hardening flow(swift(), el);
    const Hardening curve(swift());
    EXPECT_EQ(flow.start_modulus_MPa(), 0.0);
    for (double e : {0.0, 1e-4, 0.01, 0.2}) {
      EXPECT_EQ(flow.flow_stress(e), curve.flow_stress(e));
      EXPECT_EQ(flow.slope(e), curve.slope(e));
      double slope = 0.0;
      EXPECT_EQ(flow.flow_stress_and_slope(e, &slope), curve.curve_stress(e));
      EXPECT_EQ(slope, curve.curve_slope(e));
    }
  }
}

// A uniaxial point of the viscous law (R = 1, rate (1, -1/2): e = 1, stress (sigma, 0)) stepped
// as the models step it: sigma_y = f(e_n), hardening viscosity f'(e_n) dt (backward Euler). The
// stress of each step is f at the end of the step to first order in dt, from zero strain (where f
// = 0 and the step is elastic with modulus E) through yield.
TEST(ElasticStart, ViscousPointFollowsTheCurveFromZeroStrain) {
  const Hardening flow(swift(), steel());
  const ViscousLaw law(RateSpec{}, 1e-9, 1.0);
  const Eigen::Vector2d d(1.0, -0.5);
  const double dt = 2e-5;
  const double ey = flow.curve_stress(0.0) / 210000.0;
  double e = 0.0, worst = 0.0, worst_kink = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const ViscousLaw::Point p = law.evaluate(flow.flow_stress(e), flow.slope(e) * dt, d);
    EXPECT_NEAR(p.rate, 1.0, 1e-12);
    EXPECT_NEAR(p.stress(1), 0.0, 1e-9);
    const bool kink = e < ey && e + dt > ey;
    e += dt * p.rate;
    double& w = kink ? worst_kink : worst;
    w = std::max(w, std::abs(p.stress(0) - flow.flow_stress(e)));
  }
  EXPECT_GT(e, 10 * ey);
  // O(dt^2 f'') on each branch (f'' ~ 2e6 MPa just past yield), at most one elastic increment
  // E dt in the step that crosses the yield strain.
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(worst_kink, 0.0);
  EXPECT_LT(worst_kink, 210000.0 * dt);
  // At e = 0 the step is the elastic increment: stress E dt e_dot.
  const ViscousLaw::Point first = law.evaluate(flow.flow_stress(0.0), flow.slope(0.0) * dt, d);
  EXPECT_NEAR(first.stress(0), 210000.0 * dt, 1e-9);
}

// Hooke's law, plane stress (3): uniaxial -nu sigma / E, equibiaxial -2 nu sigma / E, and the 3D
// compliance with sigma_33.
TEST(ElasticStrains, HookesLawThicknessStrain) {
  const double E = 210000.0, nu = 0.3, s = 440.0;
  EXPECT_NEAR(elastic_thickness_strain(E, nu, s, 0.0), -nu * s / E, 1e-15);
  EXPECT_NEAR(elastic_thickness_strain(E, nu, s, s), -2.0 * nu * s / E, 1e-15);
  EXPECT_NEAR(elastic_thickness_strain(E, nu, s, s), -0.0012571428571428571, 1e-15);
  Eigen::Matrix3d C;  // compliance
  C << 1, -nu, -nu, -nu, 1, -nu, -nu, -nu, 1;
  const Eigen::Vector3d sig(300.0, 120.0, -11.0);
  const Eigen::Vector3d eps = C * sig / E;
  EXPECT_NEAR(elastic_thickness_strain(E, nu, sig(0), sig(1), sig(2)), eps(2), 1e-15);
}

// What the reported thickness strain gains: the elastic thickness strain (4a) for rigid-plastic
// strains, the elastic volume change (4b) with the elastic start; nothing when off.
TEST(ElasticStrains, CorrectionDependsOnWhatTheShellStrainIs) {
  const double E = 210000.0, nu = 0.3;
  Eigen::Matrix3d C;
  C << 1, -nu, -nu, -nu, 1, -nu, -nu, -nu, 1;
  const Eigen::Vector3d sig(410.0, 380.0, -9.0);
  const Eigen::Vector3d eps = C * sig / E;
  ElasticSpec el = steel();
  el.start = false;
  EXPECT_NEAR(thickness_strain_correction(el, sig(0), sig(1), sig(2)), eps(2), 1e-15);
  el.start = true;
  EXPECT_NEAR(thickness_strain_correction(el, sig(0), sig(1), sig(2)), eps.sum(), 1e-15);
  // Equibiaxial, plane stress: (1 - 2 nu) 2 sigma / E.
  EXPECT_NEAR(thickness_strain_correction(el, 440.0, 440.0), 0.4 * 880.0 / E, 1e-15);
  el.strains = false;
  EXPECT_EQ(thickness_strain_correction(el, 440.0, 440.0), 0.0);
  EXPECT_EQ(thickness_strain_correction(ElasticSpec{}, 440.0, 440.0), 0.0);
}

// The stress of a profile point (run/elastic_strains.h): the section's mean stresses N / h where
// the profile has forces; else the deformation-theory stress of a proportional path, here
// equibiaxial (R = 1: s = f(e_bar) (1, 1)) and uniaxial (s = (f(e_bar), 0)). The profile gains the
// correction in eps_thickness and thickness_mm.
TEST(ElasticStrains, ProfileStressAndCorrection) {
  Scene scene;
  scene.material.hardening = swift();
  scene.material.elastic = steel();
  Profile p;
  p.eps_meridional = {0.1, 0.2};
  p.eps_circumferential = {0.1, -0.1};
  p.eps_effective = {0.2, 0.2};
  p.eps_thickness = {-0.2, -0.1};
  p.thickness_mm = {0.85 * std::exp(-0.2), 0.85 * std::exp(-0.1)};
  const double f = Hardening(swift(), steel()).flow_stress(0.2);
  const Eigen::Vector2d eb = profile_point_stress(scene, p, 0);
  EXPECT_NEAR(eb(0), f, 1e-9 * f);
  EXPECT_NEAR(eb(1), f, 1e-9 * f);
  const Eigen::Vector2d un = profile_point_stress(scene, p, 1);
  EXPECT_NEAR(un(0), f, 1e-9 * f);
  EXPECT_NEAR(un(1), 0.0, 1e-9 * f);
  Profile q = p;
  q.meridional_force_N_per_mm = {0.7 * 440.0, 0.0};
  q.circumferential_force_N_per_mm = {0.7 * 400.0, 0.0};
  q.thickness_mm = {0.7, 0.8};
  const Eigen::Vector2d fs = profile_point_stress(scene, q, 0);
  EXPECT_NEAR(fs(0), 440.0, 1e-12);
  EXPECT_NEAR(fs(1), 400.0, 1e-12);
  RunResult r;
  r.profiles = {p};
  add_elastic_strains(scene, &r);
  const double d = 0.4 * 2.0 * f / 210000.0;  // (4b), equibiaxial
  EXPECT_NEAR(r.profiles[0].eps_thickness[0], -0.2 + d, 1e-15);
  EXPECT_NEAR(r.profiles[0].thickness_mm[0], 0.85 * std::exp(-0.2 + d), 1e-14);
  EXPECT_NEAR(r.profiles[0].eps_thickness[1], -0.1 + 0.4 * f / 210000.0, 1e-15);
  scene.material.elastic.strains = false;
  RunResult unchanged;
  unchanged.profiles = {p};
  add_elastic_strains(scene, &unchanged);
  EXPECT_EQ(unchanged.profiles[0].eps_thickness, p.eps_thickness);
}

}  // namespace
}  // namespace vs
