// linalg/dynamic_teams.h: inside the scope a region that asks for a fixed team of 4 (as CHOLMOD's
// do) gets no more threads than this thread's team size; the scope restores the setting.
#include "linalg/dynamic_teams.h"

#include <gtest/gtest.h>
#include <omp.h>

namespace vs {
namespace {

int team_of_four() {
  int size = 0;
#pragma omp parallel num_threads(4)
  {
#pragma omp single
    size = omp_get_num_threads();
  }
  return size;
}

TEST(DynamicTeams, CapsAFixedTeamAtThisThreadsTeamSize) {
  const int threads = omp_get_max_threads();
  omp_set_dynamic(0);
  omp_set_num_threads(1);
  EXPECT_EQ(team_of_four(), 4);  // the num_threads clause overrides the team size
  {
    const DynamicTeams teams;
    EXPECT_TRUE(omp_get_dynamic());
    EXPECT_EQ(team_of_four(), 1);
  }
  EXPECT_FALSE(omp_get_dynamic());
  omp_set_dynamic(1);
  { const DynamicTeams teams; }
  EXPECT_TRUE(omp_get_dynamic());  // restored, not reset
  omp_set_dynamic(0);
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace vs
