#include "output/fld.h"

#include <gtest/gtest.h>

#include "output/profile_csv.h"
#include "test_data.h"

namespace vs {
namespace {

TEST(Fld, PrincipalStrainsAreLargerAndSmaller) {
  const PrincipalStrains a = in_plane_principal(0.1, -0.05);
  EXPECT_EQ(a.major, 0.1);
  EXPECT_EQ(a.minor, -0.05);
  const PrincipalStrains b = in_plane_principal(-0.02, 0.3);
  EXPECT_EQ(b.major, 0.3);
  EXPECT_EQ(b.minor, -0.02);
  EXPECT_TRUE(std::isnan(in_plane_principal(std::nan(""), 0.1).major));
}

TEST(Fld, FinalStateIsTheFurthestAlong) {
  RunResult r;
  EXPECT_EQ(final_state(r), nullptr);
  r.history = {test::profile(0.5)};
  EXPECT_EQ(final_state(r), &r.history[0]);
  r.profiles = {test::profile(0.5)};
  EXPECT_EQ(final_state(r), &r.profiles[0]);  // tie: profiles win
  r.history.push_back(test::profile(1.0));
  EXPECT_EQ(final_state(r), &r.history[1]);
}

TEST(Fld, PointsCsvHasEveryElement) {
  const Profile p = test::profile(2.0);
  const std::vector<std::string> lines = test::lines(fld_points_csv(fld_points(&p)));
  ASSERT_EQ(lines.size(), 5u);
  // One schema for both geometries (x0, y0: initial centre; an axisymmetric element sits on the
  // x axis at its initial radius).
  EXPECT_EQ(lines[0],
            "element,x0_mm,y0_mm,r0_mm,r_mm,eps_major,eps_minor,eps_thickness,thinning_percent,"
            "eps_effective,flc_eps_major,flc_margin,flc_zone");
  // Thinning 100 (1 - exp(-0.25)) = 22.1199217 %; no curve applied: empty margins (never
  // nan), zone none.
  EXPECT_EQ(lines[2].substr(0, 40), "1,15,0,15,15.3,0.2,0.05,-0.25,22.1199217");
  EXPECT_EQ(lines[2].substr(lines[2].size() - 7), ",,,none");
  EXPECT_EQ(test::lines(fld_points_csv(fld_points(nullptr))).size(), 1u);
}

TEST(Fld, PathElementsIncludeTheThinnest) {
  Profile p = test::profile(2.0);
  EXPECT_EQ(strain_path_elements(p, 1), std::vector<std::size_t>({1}));
  EXPECT_EQ(strain_path_elements(p, 3), std::vector<std::size_t>({0, 1, 3}));
  EXPECT_EQ(strain_path_elements(p, 20), std::vector<std::size_t>({0, 1, 2, 3}));
  EXPECT_TRUE(strain_path_elements(Profile{}, 6).empty());
}

TEST(Fld, PathsFollowHistoryWithStepNumbers) {
  const RunResult r = test::completed_result();
  const std::vector<StrainPath> paths = strain_paths(r, {1, 3});
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0].step, std::vector<int>({1, 2, 3, 4}));
  EXPECT_DOUBLE_EQ(paths[0].eps_major.back(), 0.2);
  EXPECT_DOUBLE_EQ(paths[1].r0_mm, 35.0);
  const std::vector<std::string> lines = test::lines(strain_paths_csv(paths));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[0], "step,punch_travel_mm,element,r0_mm,eps_major,eps_minor");
  EXPECT_EQ(lines[1], "1,0.5,1,15,0.05,0.0125");
}

TEST(Fld, PathsWithoutHistoryAreEmpty) {
  RunResult r = test::completed_result();
  r.history.clear();
  const std::vector<StrainPath> paths = strain_paths(r, {0});
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_TRUE(paths[0].step.empty());
}

TEST(ProfileCsv, StableNamesAndPaddedPartialFields) {
  EXPECT_EQ(strains_file_name(10.0), "strains_travel_010.00mm.csv");
  EXPECT_EQ(strains_file_name(2.5), "strains_travel_002.50mm.csv");
  EXPECT_EQ(strains_file_name(123.456), "strains_travel_123.46mm.csv");
  Profile p = test::profile(1.0);
  p.contact.resize(2);  // partial
  const std::vector<std::string> lines = test::lines(profile_csv(p));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "# punch_travel_mm=1");
  EXPECT_EQ(lines[1],
            "r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,"
            "thinning_percent,eps_effective,contact");
  EXPECT_EQ(lines[2].substr(0, 12), "5,5.2,1,0.90");
  EXPECT_EQ(lines[2].substr(lines[2].size() - 2), ",1");
  EXPECT_EQ(lines[5].substr(lines[5].size() - 4), ",nan");
}

TEST(ProfileCsv, StagesDropRepeatedTravels) {
  const RunResult r = test::completed_result();
  const std::vector<const Profile*> stages = profile_stages(r);
  ASSERT_EQ(stages.size(), 2u);
  RunResult early;
  early.history = {test::profile(0.5)};
  ASSERT_EQ(profile_stages(early).size(), 1u);
}

}  // namespace
}  // namespace vs
