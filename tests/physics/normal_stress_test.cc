// The through-thickness normal stress term (material/normal_stress.h) against closed forms: the
// point law against the 3D Hill 1948 yield function and its flow rule, the section resultants of
// the axisymmetric element, and a spherical membrane pressed from inside by a uniform pressure
// (equilibrium p = 2 h sigma_eb / (rho + h) with the term, 2 h sigma_eb / rho without).
#include "material/normal_stress.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <vector>

#include "element/axisym2.h"
#include "element/simpson.h"
#include "material/viscous_law.h"

namespace vs {
namespace {

// Hill 1948 with planar isotropy in 3D principal stresses (normalised to the in-plane uniaxial
// flow stress) and its gradient, written out independently of the solver's plane-stress form.
double hill3d(double s1, double s2, double s3, double R) {
  return std::sqrt(((s2 - s3) * (s2 - s3) + (s3 - s1) * (s3 - s1) + R * (s1 - s2) * (s1 - s2)) /
                   (1.0 + R));
}
Eigen::Vector3d hill3d_gradient(double s1, double s2, double s3, double R) {
  const double f = hill3d(s1, s2, s3, R), c = 1.0 / ((1.0 + R) * f);
  return c * Eigen::Vector3d((s1 - s3) + R * (s1 - s2), (s2 - s3) + R * (s2 - s1),
                             (s3 - s2) + (s3 - s1));
}

// A point with sigma_33 = -p: the shifted plane-stress stress is on the 3D yield surface and the
// rate is normal to it there, with d_33 = -(d_11 + d_22) (the derivation of normal_stress.h).
TEST(NormalStress, PointLawIsTheHill3dFlowRuleWithPrescribedSigma33) {
  const double sy = 320.0, p = 11.0;
  for (double R : {1.0, 0.41, 1.8}) {
    const ViscousLaw law(RateSpec{}, 1e-12, R);
    for (const Eigen::Vector2d& d : {Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(0.7, -0.2),
                                     Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(-0.3, 0.9)}) {
      const ViscousLaw::Point pt = law.evaluate(sy, 0.0, d);
      Eigen::Vector2d s = pt.stress;
      const NormalStressTerm t = normal_stress_term(p, d(0), d(1));
      s.array() += t.stress_shift_MPa;
      // On the yield surface with sigma_33 = -p.
      EXPECT_NEAR(hill3d(s(0), s(1), -p, R), sy, 1e-9 * sy) << R;
      // Normality: the 3D rate (d1, d2, -(d1 + d2)) is parallel to the gradient.
      const Eigen::Vector3d g = hill3d_gradient(s(0), s(1), -p, R);
      const Eigen::Vector3d d3(d(0), d(1), -(d(0) + d(1)));
      EXPECT_LT(g.normalized().cross(d3.normalized()).norm(), 1e-9) << R;
      // Work: the in-plane power with the term is the 3D power sigma : d less sigma_33 d_33.
      const double power3d = s.dot(d) + (-p) * d3(2);
      EXPECT_NEAR(power3d, sy * pt.rate, 1e-9 * sy);
      EXPECT_NEAR(s.dot(d), pt.stress.dot(d) + t.potential, 1e-9 * sy);
    }
  }
  // Closed form (a), equibiaxial: sigma = (sigma_bar sqrt((1 + R) / 2) - p) (1, 1).
  const double R = 1.5;
  const ViscousLaw law(RateSpec{}, 1e-12, R);
  const ViscousLaw::Point pt = law.evaluate(sy, 0.0, Eigen::Vector2d(0.4, 0.4));
  EXPECT_NEAR(pt.stress(0) + normal_stress_term(p, 0.4, 0.4).stress_shift_MPa,
              sy * std::sqrt((1.0 + R) / 2.0) - p, 1e-9 * sy);
}

TEST(NormalStress, LinearProfileBetweenTheFaces) {
  const FacePressure f{12.0, 3.0};
  EXPECT_DOUBLE_EQ(f.at(-0.5), 12.0);
  EXPECT_DOUBLE_EQ(f.at(0.5), 3.0);
  EXPECT_DOUBLE_EQ(f.at(0.0), 7.5);
  EXPECT_FALSE(FacePressure{}.active());
  FacePressure g;
  add_face_pressure(0.9, 5.0, &g);   // tool normal along the shell normal: the lower face
  add_face_pressure(-0.9, 2.0, &g);  // against it: the upper face
  EXPECT_DOUBLE_EQ(g.lower_MPa, 5.0);
  EXPECT_DOUBLE_EQ(g.upper_MPa, 2.0);
}

// Section resultants (E) of the axisymmetric element at an equibiaxial membrane rate:
// N_s = N_t = h (sigma_eb - (p_l + p_u) / 2), M_s = M_t = (p_l - p_u) h^2 / 12; the potential
// drops by W h (p_l + p_u) / 2 (d_s + d_t); the stiffness is unchanged; force = d potential / d v.
TEST(NormalStress, Axisym2SectionResultants) {
  const double sy = 250.0, h = 0.8, R = 1.5, pl = 14.0, pu = 4.0, rate = 0.3;
  const ViscousLaw law(RateSpec{}, 1e-12, R);
  for (int np : {3, 5, 9}) {
    const ThicknessRule rule = simpson_rule(np);
    const std::vector<double> sigma(static_cast<std::size_t>(np), sy);
    Axisym2Section plain;
    plain.thickness_mm = h;
    plain.sigma_y = &sigma;
    Axisym2Section pressed = plain;
    pressed.face_pressure = FacePressure{pl, pu};
    const Axisym2Geometry g{40.0, 1.0, 41.5, 1.0};  // flat ring, normal +z
    Vec6 d = Vec6::Zero();
    d(0) = rate * g.ra;  // u = rate r: eps_s = eps_t = rate
    d(3) = rate * g.rb;
    Axisym2Output a, b;
    axisym2_evaluate(g, plain, rule, law, d, StiffnessKind::kTangent, &a);
    axisym2_evaluate(g, pressed, rule, law, d, StiffnessKind::kTangent, &b);
    const double seb = sy * std::sqrt((1.0 + R) / 2.0);
    EXPECT_NEAR(a.stress_resultant(0), h * seb, 1e-9 * h * seb);
    EXPECT_NEAR(b.stress_resultant(0), h * (seb - 0.5 * (pl + pu)), 1e-9 * h * seb) << np;
    EXPECT_NEAR(b.stress_resultant(1), h * (seb - 0.5 * (pl + pu)), 1e-9 * h * seb) << np;
    EXPECT_NEAR(b.stress_resultant(2), (pl - pu) * h * h / 12.0, 1e-9 * h * seb) << np;
    EXPECT_NEAR(b.stress_resultant(3), (pl - pu) * h * h / 12.0, 1e-9 * h * seb) << np;
    const double W = 2.0 * std::numbers::pi * g.mid_radius() * g.length();
    EXPECT_NEAR(b.potential - a.potential, -W * h * 0.5 * (pl + pu) * 2.0 * rate,
                1e-9 * std::abs(a.potential));
    EXPECT_LT((b.stiffness - a.stiffness).norm(), 1e-12 * a.stiffness.norm());
  }
  // The force is the gradient of the potential with the term (a general rate, bending too).
  const ThicknessRule rule = simpson_rule(5);
  const std::vector<double> sigma(5, sy);
  Axisym2Section sec;
  sec.thickness_mm = h;
  sec.sigma_y = &sigma;
  sec.shear_viscosity = 50.0;
  sec.face_pressure = FacePressure{pl, pu};
  const Axisym2Geometry g{10.0, 3.0, 12.0, 2.0};
  Vec6 d;
  d << 0.1, 0.7, -0.02, 0.3, 0.1, 0.05;
  Axisym2Output out, op, om;
  axisym2_evaluate(g, sec, rule, law, d, StiffnessKind::kTangent, &out);
  for (int j = 0; j < 6; ++j) {
    const double eps = 1e-6;
    Vec6 dp = d, dm = d;
    dp(j) += eps;
    dm(j) -= eps;
    axisym2_evaluate(g, sec, rule, law, dp, StiffnessKind::kNone, &op);
    axisym2_evaluate(g, sec, rule, law, dm, StiffnessKind::kNone, &om);
    EXPECT_NEAR((op.potential - om.potential) / (2.0 * eps), out.force(j), 1e-5 * out.force.norm())
        << j;
  }
}

// Closed form (b): a hemispherical membrane of mid-surface radius rho, rigid-plastic, expanding
// uniformly (v = (V / rho) x: every element at the equibiaxial rate V / rho, no bending, no
// shear), pressed from inside (the lower face) by a uniform contact pressure p. Equilibrium in
// that mode, f_int(p) . v = f_ext(p) . v with the consistent nodal loads of p on the mid-surface
// elements, gives the pressure the membrane carries:
//   plane stress: p = 2 h sigma_eb / rho;   with sigma_33: p = 2 h sigma_eb / (rho + h),
// up to the chord factor cos(alpha / 2) of the mesh (alpha = element angle; 1 - 8e-7 here).
TEST(NormalStress, PressedSphericalMembrane) {
  const double sy = 300.0, R = 1.3, rho = 20.0, h = 1.0, V = 0.5;  // h / rho = 5 %
  const double seb = sy * std::sqrt((1.0 + R) / 2.0);
  const ViscousLaw law(RateSpec{}, 1e-12, R);
  const ThicknessRule rule = simpson_rule(5);
  const std::vector<double> sigma(5, sy);
  const int n = 800;
  std::vector<Eigen::Vector2d> x(n + 1), v(n + 1);
  for (int j = 0; j <= n; ++j) {
    const double phi = 0.5 * std::numbers::pi * j / n;  // from the pole to the equator
    x[j] = rho * Eigen::Vector2d(std::sin(phi), std::cos(phi));
    v[j] = (V / rho) * x[j];
  }
  // f_int(p) . v = P0 - p Q (linear in p); f_ext(p) . v = p E.
  auto internal_power = [&](double p) {
    double P = 0.0;
    for (int e = 0; e < n; ++e) {
      const Axisym2Geometry g{x[e].x(), x[e].y(), x[e + 1].x(), x[e + 1].y()};
      Axisym2Section sec;
      sec.thickness_mm = h;
      sec.sigma_y = &sigma;
      if (p > 0.0) sec.face_pressure = FacePressure{p, 0.0};
      Vec6 d;
      d << v[e].x(), v[e].y(), 0.0, v[e + 1].x(), v[e + 1].y(), 0.0;
      Axisym2Output out;
      axisym2_evaluate(g, sec, rule, law, d, StiffnessKind::kNone, &out);
      EXPECT_NEAR(out.strain_rate(0), V / rho, 1e-12);
      EXPECT_NEAR(out.strain_rate(1), V / rho, 1e-12);
      P += out.force.dot(d);
    }
    return P;
  };
  double E = 0.0;  // external power per unit pressure: p W_e n_e / 2 at each node
  for (int e = 0; e < n; ++e) {
    const Axisym2Geometry g{x[e].x(), x[e].y(), x[e + 1].x(), x[e + 1].y()};
    const double l = g.length();
    const Eigen::Vector2d nrm(-(g.zb - g.za) / l, (g.rb - g.ra) / l);  // outward: lower face in
    const double W = 2.0 * std::numbers::pi * g.mid_radius() * l;
    E += 0.5 * W * nrm.dot(v[e] + v[e + 1]);
  }
  const double P0 = internal_power(0.0), Q = P0 - internal_power(1.0);
  const double p_plane = P0 / E, p_term = P0 / (E + Q);
  EXPECT_NEAR(p_plane / (2.0 * h * seb / rho) - 1.0, 0.0, 1e-5);
  EXPECT_NEAR(p_term / (2.0 * h * seb / (rho + h)) - 1.0, 0.0, 1e-5);
  // The two differ by h / rho (5 %): the test tells them apart by four orders of magnitude.
  EXPECT_NEAR(p_plane / p_term - 1.0, h / rho, 1e-5);
}

}  // namespace
}  // namespace vs
