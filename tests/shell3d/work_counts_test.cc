// The speed features of the 3D solver (chord steps on the last factorisation, also across solves;
// the full Newton step evaluated completely; the friction refresh) must not be lost when the
// forward core changes (issue 13: "assert the factorisation counts do not grow"). The counts are
// deterministic (the same scene gives the same bits with any number of threads), so they are
// exact figures of the code at the unification (25 Nov 2026), equal to those of the separate 3D
// stack before it: a change that loses a speed feature raises them.
#include <gtest/gtest.h>

#include <string>

#include "run/simulate.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

Scene scene(const std::string& name, double travel) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/" + name);
  s.blank.divisions = 4;
  s.process.punch_travel_mm = travel;
  s.process.output_travels_mm = {travel};
  return s;
}

TEST(WorkCounts, ShellFactorisationsDoNotGrow) {
  const RunResult sticking = simulate(scene("ex4a_quarter_disc_sticking.toml", 8.0));
  ASSERT_TRUE(sticking.completed()) << sticking.message;
  EXPECT_LE(sticking.timings.factorisations, 388);
  EXPECT_GT(sticking.timings.factorisations, 0);
  const RunResult clamped = simulate(scene("ex4b_square_clamped.toml", 6.0));
  ASSERT_TRUE(clamped.completed()) << clamped.message;
  EXPECT_LE(clamped.timings.factorisations, 165);
  EXPECT_GT(clamped.timings.factorisations, 0);
}

}  // namespace
}  // namespace vs
