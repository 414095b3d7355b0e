// The fixed travel grid of the step driver (stepping/travel_grid.h), with and without the graded
// start of numerics.start_refinement.
#include "stepping/travel_grid.h"

#include <gtest/gtest.h>

#include <vector>

namespace vs {
namespace {

void expect_grid(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << i;
}

TEST(TravelGrid, MultiplesOfTheIncrementAndTheOutputs) {
  expect_grid(travel_grid(2.0, 0.5, {0.75}), {0.5, 0.75, 1.0, 1.5, 2.0});
}

// Levels 3: the first increment in 8 parts, the second in 4, the third in 2, then the plain grid.
TEST(TravelGrid, StartRefinementGradesTheFirstIncrements) {
  expect_grid(travel_grid(2.0, 0.5, {}, 3), {0.0625, 0.125, 0.1875, 0.25, 0.3125, 0.375, 0.4375,
                                             0.5, 0.625, 0.75, 0.875, 1.0, 1.25, 1.5, 2.0});
  // A run shorter than the graded part keeps only the targets before its end.
  expect_grid(travel_grid(0.2, 0.5, {}, 2), {0.125, 0.2});
}

}  // namespace
}  // namespace vs
