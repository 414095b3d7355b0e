// numerics.transverse_shear_scale (issue 15; experiments/08_continuum_reference, section 14): the
// factor on the transverse-shear penalty of both shells, against the closed form of the shear
// potential. A flat, undeformed blank turned at a uniform angular velocity theta about a line in
// its plane (no translation) has no membrane rate and no meridional (axisymmetric) or any (3D)
// curvature rate, and a uniform transverse shear rate |gamma| = theta. Its transverse-shear
// potential is 1/2 (5/6) s mu_nom gamma^2 over the volume, with mu_nom = sigma_y(0) / (3 e_nom)
// the penalty viscosity of the undeformed sheet at the nominal rate e_nom = punch speed / blank
// radius (rate-independent Swift law: sigma_y(0) = K eps0^n, with the cut-off's factor
// 1 / sqrt(1 + c^2)), so the potential grows by
// (s - 1) 1/2 (5/6) mu_nom theta^2 h A from scale 1 to scale s. The other terms (the hoop
// curvature of the axisymmetric rotation, the drilling stiffness in 3D) do not depend on s.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "model/axisym_model.h"
#include "model/forming_model.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

Scene scene(const std::string& name) {
  return load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/" + name + ".toml");
}

// 1/2 (5/6) mu_nom theta^2 per unit volume.
double shear_energy_density(const Scene& sc, double theta) {
  const auto& hd = sc.material.hardening;
  const double sigma0 = hd.K_MPa * std::pow(hd.eps0, hd.n);
  const double e_nom = sc.process.punch_speed_mm_per_s / sc.blank.radius_mm;
  // The regularised law's stress at e_nom with the cut-off rate c e_nom (viscous_law.h).
  const double c = sc.numerics.strain_rate_cutoff;
  const double mu_nom = sigma0 / std::sqrt(1.0 + c * c) / (3.0 * e_nom);
  return 0.5 * (5.0 / 6.0) * mu_nom * theta * theta;
}

double axisym_potential(Scene sc, double scale, double theta) {
  sc.numerics.transverse_shear_scale = scale;
  AxisymModel m(sc);
  AxisymState s = m.initial_state();
  m.freeze_material(s, 0.01);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(m.num_dofs());
  for (int i = 0; i < m.num_nodes(); ++i) v(3 * i + 2) = theta;
  AxisymSystem sys;
  m.evaluate_elements(s, v, StiffnessKind::kNone, &sys);
  return sys.element_potential;
}

TEST(TransverseShearScale, AxisymmetricShearPotentialIsTheClosedForm) {
  const Scene sc = scene("ex1_hemispherical_stretching");
  ASSERT_EQ(sc.material.rate.law, RateLaw::kNone);
  const double theta = 0.01, R = sc.blank.radius_mm, h = sc.blank.thickness_mm;
  const double expected = shear_energy_density(sc, theta) * h * std::numbers::pi * R * R;
  const double p1 = axisym_potential(sc, 1.0, theta);
  for (double scale : {0.1, 0.3, 4.0}) {
    const double ps = axisym_potential(sc, scale, theta);
    EXPECT_NEAR((ps - p1) / ((scale - 1.0) * expected), 1.0, 1e-12) << scale;
  }
  // The rest (the hoop curvature rate theta / r of the axisymmetric rotation) is not scaled.
  EXPECT_GT(p1 - expected, 0.0);
}

double shell3d_potential(Scene sc, double scale, double theta) {
  using shell3d::FormingModel;
  using shell3d::FormingState;
  using shell3d::FormingSystem;
  using shell3d::Vec3;
  sc.numerics.transverse_shear_scale = scale;
  FormingModel m(sc);
  FormingState s = m.initial_state();
  m.freeze_material(s, 0.01);
  m.prepare(s);
  const std::size_t nn = s.x.size();
  const std::vector<Vec3> velocity(nn, Vec3::Zero());
  const std::vector<Vec3> omega(nn, theta * Vec3::UnitX());
  const Eigen::VectorXd x = m.to_local(velocity, omega);
  FormingSystem sys;
  m.evaluate(s, x, shell3d::Shell9Stiffness::kNone, 0.0, &sys);
  return sys.potential;
}

TEST(TransverseShearScale, ShellShearPotentialIsTheClosedForm) {
  Scene sc = scene("ex4a_full_disc");
  sc.blank.divisions = 4;
  ASSERT_EQ(sc.material.rate.law, RateLaw::kNone);
  const double theta = 0.01, R = sc.blank.radius_mm, h = sc.blank.thickness_mm;
  const double expected = shear_energy_density(sc, theta) * h * std::numbers::pi * R * R;
  const double p1 = shell3d_potential(sc, 1.0, theta);
  // The whole potential is the shear term (no membrane or bending rate, 5-dof nodes without a
  // drilling term): the closed form to the mesh's area (quadratic edges on the circle).
  EXPECT_NEAR(p1 / expected, 1.0, 2e-4);
  for (double scale : {0.1, 4.0}) {
    const double ps = shell3d_potential(sc, scale, theta);
    EXPECT_NEAR(ps / (scale * p1), 1.0, 1e-12) << scale;
  }
}

}  // namespace
}  // namespace vs
