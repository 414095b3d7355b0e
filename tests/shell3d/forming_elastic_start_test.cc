// The elastic start of [material.elastic] in the 3D forming model against the same law in the
// axisymmetric model: example 4a's quarter disc with Coulomb friction (the configuration of
// forming_normal_stress_test.cc) and its axisymmetric twin, with and without elasticity. Both
// models take the flow stress from the one Hardening (material/elastic_start.h), so the start must
// lower the punch force by about the same relative amount in both, most at small travel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/axisym_comparison.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

Scene quarter_disc(bool elastic) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 4;
  s.process.punch_travel_mm = 6.0;
  s.process.output_travels_mm = {2.0, 4.0, 6.0};
  s.tools.at(0).friction = 0.2;
  s.numerics.max_travel_increment_per_length = 1e9;  // the scene's 0.5 mm grid (forming_test.cc)
  // Measured with heun, the 3D default until 26 Nov 2026; the implicit default on this grid is
  // +2.7 % from the twin at 4 mm with the start (its step error, forming_test.cc).
  s.numerics.time_integration = TimeIntegration::kHeun;
  s.numerics.start_refinement = 0;
  if (elastic) {
    s.material.elastic.law = ElasticLaw::kIsotropic;
    s.material.elastic.E_MPa = 210000.0;
    s.material.elastic.nu = 0.3;
  }
  return s;
}

// Measured (Nov 2026; mean force over the last mm): the start lowers it by 29.0 / 3.5 / 2.4 % in
// 3D and by 36.0 / 5.4 / 2.6 % in the 30-element twin at 2 / 4 / 6 mm; with it the 3D model is
// +13.4 / +0.9 / -2.0 % from the twin (3D steps on the scene's 0.5 mm grid, the twin at 0.025
// element lengths; without elasticity +2.2 / -1.0 / -2.2 %). So this checks the sign in both
// models, the same size within half the axisymmetric effect, and forming_test.cc's tolerances
// against the twin from 4 mm.
TEST(Forming3d, ElasticStartChangesTheForceAsInTheAxisymmetricModel) {
  const Scene off = quarter_disc(false), on = quarter_disc(true);
  const RunResult s_off = simulate_shell3d(off), s_on = simulate_shell3d(on);
  const RunResult a_off = simulate(axisymmetric_twin(off, 30));
  const RunResult a_on = simulate(axisymmetric_twin(on, 30));
  ASSERT_TRUE(s_off.completed() && s_on.completed() && a_off.completed() && a_on.completed());
  const auto c_off = compare_with_axisymmetric(off, s_off, a_off);
  const auto c_on = compare_with_axisymmetric(on, s_on, a_on);
  ASSERT_EQ(c_off.size(), 3u);
  ASSERT_EQ(c_on.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const double d3 = c_on[k].mean_force_3d_N / c_off[k].mean_force_3d_N - 1.0;
    const double da = c_on[k].mean_force_axisym_N / c_off[k].mean_force_axisym_N - 1.0;
    std::printf(
        "%g mm: the elastic start changes the mean force by %+.3f %% (3D), %+.3f %% (axisym); "
        "3D vs twin with it %+.3f %% (without %+.3f %%), max |d eps_t| %.4f\n",
        c_on[k].punch_travel_mm, 100 * d3, 100 * da, 100 * c_on[k].mean_force_deviation,
        100 * c_off[k].mean_force_deviation, c_on[k].max_eps_thickness_deviation());
    EXPECT_LT(d3, 0.0);
    EXPECT_LT(da, 0.0);
    EXPECT_NEAR(d3, da, 0.5 * std::abs(da)) << c_on[k].punch_travel_mm;
    EXPECT_LT(c_on[k].max_eps_thickness_deviation(), 0.01);
    // From 4 mm, forming_test.cc's tolerance against the twin (2.5 % mean force); over 1-2 mm,
    // inside the elastic-plastic transition, the 3D run's 0.5 mm grid does not resolve it.
    if (c_on[k].punch_travel_mm >= 4.0) {
      EXPECT_LT(std::abs(c_on[k].mean_force_deviation), 0.025);
    }
  }
}

}  // namespace
}  // namespace vs::shell3d
