// The through-thickness normal stress (numerics.normal_stress = contact) in the 3D forming model
// against the same term in the axisymmetric model: example 4a's quarter disc with Coulomb
// friction (the CI configuration of forming_test.cc) and its axisymmetric twin, with the term off
// and on. The two implementations (FormingModel / shell9 and AxisymModel / axisym2, sharing
// material/normal_stress.h) must change the punch force by the same relative amount, and the
// 3D model must still match its twin with the term on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/axisym_comparison.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

Scene quarter_disc(NormalStress ns) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 4;
  s.process.punch_travel_mm = 6.0;
  s.process.output_travels_mm = {4.0, 5.0, 6.0};
  s.tools.at(0).friction = 0.2;
  s.numerics.max_travel_increment_per_length = 1e9;  // the scene's 0.5 mm grid (forming_test.cc)
  s.numerics.normal_stress = ns;
  return s;
}

// Measured (Nov 2026): the term lowers the mean force by 0.16 / 0.14 / 0.16 % in 3D and by
// 0.24 / 0.29 / 0.30 % in the twin at 4 / 5 / 6 mm (at the travel itself, 8 divisions: 0.13 %).
// The 3D effect is about half the axisymmetric one here (nodes 3.7 mm apart, about two node
// rings in contact, force jumps of 1-3 % at contact events); the nodal pressures are of the
// expected size (8.6-13.5 MPa near the pole at 6 mm, 2 h sigma / R ~ 10 MPa), and over 15-20 mm
// the work of the punch drops by as much as in the axisymmetric ex1 (0.6-0.8 %;
// experiments/08_continuum_reference, section 8). So this checks the sign in both models,
// agreement within 0.3 points of force (the size of the term), and that the 3D model still meets
// forming_test.cc's tolerances against its twin with the term (2.5 % mean force, 0.01 thickness
// strain; measured -0.9 / -1.7 / -2.0 % and 0.0045).
TEST(Forming3d, NormalStressChangesTheForceAsInTheAxisymmetricModel) {
  const Scene off = quarter_disc(NormalStress::kNone), on = quarter_disc(NormalStress::kContact);
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
        "%g mm: term changes the mean force by %+.3f %% (3D), %+.3f %% (axisym); "
        "3D vs twin with the term %+.3f %%, max |d eps_t| %.4f\n",
        c_on[k].punch_travel_mm, 100 * d3, 100 * da, 100 * c_on[k].mean_force_deviation,
        c_on[k].max_eps_thickness_deviation());
    EXPECT_LT(d3, 0.0);
    EXPECT_LT(da, 0.0);
    EXPECT_NEAR(d3, da, 0.003) << c_on[k].punch_travel_mm;
    EXPECT_LT(std::abs(c_on[k].mean_force_deviation), 0.025);
    EXPECT_LT(c_on[k].max_eps_thickness_deviation(), 0.01);
  }
}

}  // namespace
}  // namespace vs::shell3d
