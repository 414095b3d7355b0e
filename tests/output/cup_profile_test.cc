// The cup-height (earing) profile: the periodic summary (mean, amplitude, ears) on profiles with
// known answers, the rim extraction and quarter unfolding on synthetic 3D stages, the measured
// ESAFORM 2021 profile, the strict reader of profile files and the run-folder files.
#include "output/cup_profile.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "mesh/forming_mesh.h"
#include "output/cup_profile_output.h"
#include "output/cup_profile_summary.h"
#include "output/run_summary.h"
#include "output/run_writer.h"
#include "scene/cup_profile_file.h"
#include "scene/load_scene.h"
#include "test_data.h"

namespace vs {
namespace {

constexpr double kPi = 3.14159265358979323846;

double rad(double deg) { return deg * kPi / 180.0; }

// ---------------------------------------------------------------------------------------------
// The summary of a periodic profile.

TEST(CupProfileSummary, RecoversMeanAmplitudeAndEarsOfFourEars) {
  // H = 34 + cos(4 theta), sampled every 5 deg from 3.7 deg: no sample at an ear (the nearest is
  // 1.3 deg away), so only the parabola puts the ears at 0, 90, 180, 270.
  std::vector<double> a, h;
  for (int k = 0; k < 72; ++k) {
    a.push_back(3.7 + 5.0 * k);
    h.push_back(34.0 + std::cos(4.0 * rad(a.back())));
  }
  const CupProfileSummary s = summarize_cup_profile(a, h);
  EXPECT_EQ(s.points, 72);
  // Trapezoids of equally spaced samples of cos over whole turns sum to zero.
  EXPECT_NEAR(s.mean_height_mm, 34.0, 1e-12);
  // Samples miss the extremes by at most cos(4 x 2.5 deg): amplitude within 2 (1 - 0.985).
  EXPECT_NEAR(s.amplitude_mm, 2.0, 0.03);
  EXPECT_GT(s.amplitude_mm, 1.9);
  // The parabola puts them within 0.01 deg (the ear near 0 deg at 359.99: last by angle).
  ASSERT_EQ(s.ears.size(), 4u);
  ASSERT_EQ(s.valleys.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const auto i = static_cast<std::size_t>(k);
    EXPECT_LT(angle_distance_deg(s.ears[i].angle_deg, 90.0 * (k + 1)), 0.02) << s.ears[i].angle_deg;
    EXPECT_LT(angle_distance_deg(s.valleys[i].angle_deg, 45.0 + 90.0 * k), 0.02);
    EXPECT_NEAR(s.ears[i].height_mm, 35.0, 2e-3);
    EXPECT_NEAR(s.valleys[i].height_mm, 33.0, 2e-3);
  }
}

TEST(CupProfileSummary, OrderAndTurnsOfTheAnglesDoNotMatter) {
  std::vector<double> a, h;
  for (int k = 0; k < 36; ++k) {
    a.push_back(10.0 * k + 2.0);
    h.push_back(34.0 + std::cos(4.0 * rad(a.back())));
  }
  const CupProfileSummary ref = summarize_cup_profile(a, h);
  std::vector<double> a2, h2;
  for (int k = 35; k >= 0; --k) {  // reversed, and every other angle a turn off
    const auto i = static_cast<std::size_t>(k);
    a2.push_back(a[i] + (k % 2 == 0 ? 360.0 : -360.0));
    h2.push_back(h[i]);
  }
  const CupProfileSummary s = summarize_cup_profile(a2, h2);
  EXPECT_NEAR(s.mean_height_mm, ref.mean_height_mm, 1e-12);
  ASSERT_EQ(s.ears.size(), ref.ears.size());
  for (std::size_t i = 0; i < s.ears.size(); ++i) {
    EXPECT_NEAR(s.ears[i].angle_deg, ref.ears[i].angle_deg, 1e-9);
  }
}

TEST(CupProfileSummary, MeanIsWeightedByAngleNotByPointCount) {
  // H = 34 + |theta - 180| / 180 (35 at 0 deg, 34 at 180 deg), linear between the samples, which
  // crowd near 0 deg: the mean of the function is 34.5, the mean of the samples near 34.9.
  std::vector<double> a = {180.0}, h = {34.0};
  for (int k = 0; k <= 20; ++k) {
    const double t = 1.0 * k;
    a.push_back(t);
    h.push_back(34.0 + std::abs(t - 180.0) / 180.0);
    if (k > 0) {
      a.push_back(360.0 - t);
      h.push_back(34.0 + std::abs(180.0 - t) / 180.0);
    }
  }
  const CupProfileSummary s = summarize_cup_profile(a, h);
  EXPECT_NEAR(s.mean_height_mm, 34.5, 1e-12);
  EXPECT_DOUBLE_EQ(s.max_height_mm, 35.0);
  EXPECT_DOUBLE_EQ(s.min_height_mm, 34.0);
  ASSERT_EQ(s.ears.size(), 1u);
  EXPECT_LT(angle_distance_deg(s.ears[0].angle_deg, 0.0), 1e-9);
  ASSERT_EQ(s.valleys.size(), 1u);
  EXPECT_NEAR(s.valleys[0].angle_deg, 180.0, 1e-9);
}

TEST(CupProfileSummary, ParabolaVertexIsExactForAQuadraticPeak) {
  // h = 10 - (a - 47)^2 / 100 at unevenly spaced 40, 45, 56 deg, and lower points elsewhere.
  auto q = [](double x) { return 10.0 - (x - 47.0) * (x - 47.0) / 100.0; };
  const std::vector<double> a = {40.0, 45.0, 56.0, 200.0};
  const std::vector<double> h = {q(40.0), q(45.0), q(56.0), 0.0};
  const CupProfileSummary s = summarize_cup_profile(a, h);
  ASSERT_EQ(s.ears.size(), 1u);
  EXPECT_NEAR(s.ears[0].angle_deg, 47.0, 1e-9);
  EXPECT_NEAR(s.ears[0].height_mm, 10.0, 1e-12);
}

TEST(CupProfileSummary, ARunOfEqualHeightsIsOneEarAtItsMiddle) {
  const std::vector<double> a = {0.0, 90.0, 100.0, 110.0, 120.0, 200.0, 300.0};
  const std::vector<double> h = {1.0, 2.0, 3.0, 3.0, 3.0, 2.5, 2.0};
  const CupProfileSummary s = summarize_cup_profile(a, h);
  ASSERT_EQ(s.ears.size(), 1u);
  EXPECT_DOUBLE_EQ(s.ears[0].angle_deg, 110.0);
  EXPECT_DOUBLE_EQ(s.ears[0].height_mm, 3.0);
  ASSERT_EQ(s.valleys.size(), 1u);  // 1 at 0 deg, between 2 at 300 and 2 at 90
  // A rising step (3, 3 then 4) is not an ear.
  const CupProfileSummary t =
      summarize_cup_profile({0.0, 90.0, 180.0, 270.0}, {1.0, 3.0, 3.0, 4.0});
  ASSERT_EQ(t.ears.size(), 1u);
  EXPECT_GT(t.ears[0].angle_deg, 180.0);
}

TEST(CupProfileSummary, BumpsBelowTheProminenceAreNotEars) {
  // Four ears of 1 mm and, at the bottom of the valley at 45 deg, a bump of 0.02 mm (an ear by
  // the default 0.01 mm, splitting the valley in two) or 0.005 mm (noise: one valley stays); a
  // flat profile with 0.004 mm noise has no ears at all.
  auto profile = [](double bump_mm) {
    std::vector<double> a, h;
    for (int k = 0; k < 360; ++k) {
      a.push_back(k);
      h.push_back(34.0 + std::cos(4.0 * rad(k)) + (k == 45 ? bump_mm : 0.0));
    }
    return std::make_pair(a, h);
  };
  const auto [a1, h1] = profile(0.02);
  EXPECT_EQ(summarize_cup_profile(a1, h1).ears.size(), 5u);
  EXPECT_EQ(summarize_cup_profile(a1, h1).valleys.size(), 5u);
  const auto [a2, h2] = profile(0.005);
  EXPECT_EQ(summarize_cup_profile(a2, h2).ears.size(), 4u);
  EXPECT_EQ(summarize_cup_profile(a2, h2).valleys.size(), 4u);
  std::vector<double> a, h;
  for (int k = 0; k < 64; ++k) {
    a.push_back(5.625 * k);
    h.push_back(40.0 + 0.004 * std::sin(7.0 * k));
  }
  EXPECT_TRUE(summarize_cup_profile(a, h).ears.empty());
  EXPECT_TRUE(summarize_cup_profile(a, h).valleys.empty());
  CupProfileSummaryOptions every;
  every.min_prominence_mm = 0.0;
  EXPECT_GT(summarize_cup_profile(a, h, every).ears.size(), 4u);
  // The highest ear's prominence is the whole amplitude: a lone ear of 0.02 mm counts.
  EXPECT_EQ(summarize_cup_profile({0.0, 120.0, 240.0}, {1.02, 1.0, 1.0}).ears.size(), 1u);
  EXPECT_EQ(summarize_cup_profile({0.0, 120.0, 240.0}, {1.005, 1.0, 1.0}).ears.size(), 0u);
}

TEST(CupProfileSummary, FlatProfileHasNoEarsAndZeroAmplitude) {
  const CupProfileSummary s = summarize_cup_profile({0.0, 120.0, 240.0}, {5.0, 5.0, 5.0});
  EXPECT_DOUBLE_EQ(s.mean_height_mm, 5.0);
  EXPECT_DOUBLE_EQ(s.amplitude_mm, 0.0);
  EXPECT_TRUE(s.ears.empty());
  EXPECT_TRUE(s.valleys.empty());
  EXPECT_TRUE(std::isnan(summarize_cup_profile({}, {}).mean_height_mm));
}

TEST(CupProfileSummary, EarOffsetIsTheWorstNearestCircularDistance) {
  EXPECT_DOUBLE_EQ(angle_distance_deg(359.0, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(angle_distance_deg(10.0, 190.0), 180.0);
  const std::vector<ProfileExtremum> found = {{1.0, 0.0}, {95.0, 0.0}, {178.0, 0.0}};
  const std::vector<ProfileExtremum> ref = {{359.0, 0.0}, {90.0, 0.0}, {180.0, 0.0}, {270.0, 0.0}};
  EXPECT_DOUBLE_EQ(max_extremum_offset_deg(found, ref), 91.0);  // 270 -> 1
  EXPECT_TRUE(std::isnan(max_extremum_offset_deg({}, ref)));
}

// ---------------------------------------------------------------------------------------------
// The rim profile of a 3D stage.

Scene disc_scene(BlankSymmetry symmetry) {
  Scene s;
  s.geometry = Geometry::kShell3d;
  s.title = "synthetic cup";
  s.blank.radius_mm = 50.0;
  s.blank.edge = EdgeCondition::kFree;
  s.blank.symmetry = symmetry;
  s.blank.divisions = 3;
  return s;
}

// A synthetic drawn cup: every node moved radially to 0.6 of its radius and down so that the
// rim hangs `height(theta)` below the outer bottom surface at the axis (thickness 1 mm
// everywhere, centre at z = 0): H(theta) = height(theta) exactly at the rim nodes.
template <class Height>
ShellFields synthetic_cup(const Scene& scene, Height height) {
  ShellFields f;
  f.mesh = shell3d::forming_mesh(scene);
  ShellStage st;
  st.punch_travel_mm = 40.0;
  for (const Eigen::Vector3d& x0 : f.mesh.nodes) {
    const double r0 = x0.head<2>().norm();
    const double theta_deg = std::atan2(x0.y(), x0.x()) * 180.0 / kPi;
    const double z = -(r0 / scene.blank.radius_mm) * (height(theta_deg) - 0.5);
    st.x.emplace_back(0.6 * x0.x(), 0.6 * x0.y(), z);
    st.thickness_mm.push_back(1.0);
    st.contact_tool.push_back(-1);
  }
  // The per-element fields the ParaView stage needs.
  st.eps_effective.assign(f.mesh.elements.size(), 0.1);
  st.effective_stress_MPa.assign(f.mesh.elements.size(), 200.0);
  f.stages.push_back(st);
  return f;
}

double four_ears(double theta_deg) { return 34.0 + std::cos(4.0 * rad(theta_deg)); }

TEST(RimCupProfile, QuarterUnfoldedEqualsTheFullBlank) {
  const Scene quarter = disc_scene(BlankSymmetry::kQuarter);
  const Scene full = disc_scene(BlankSymmetry::kFull);
  const ShellFields q = synthetic_cup(quarter, four_ears);
  const ShellFields f = synthetic_cup(full, four_ears);
  const CupProfileResult pq = rim_cup_profile(quarter, q, q.stages.back(), 0.0);
  const CupProfileResult pf = rim_cup_profile(full, f, f.stages.back(), 0.0);
  ASSERT_TRUE(pq.available) << pq.reason;
  ASSERT_TRUE(pf.available) << pf.reason;
  EXPECT_TRUE(pq.profile.unfolded);
  EXPECT_FALSE(pf.profile.unfolded);
  // 3 divisions: 4 x 3 + 1 rim nodes on the quarter arc, 16 x 3 on the whole circle.
  ASSERT_EQ(pf.profile.angle_from_rd_deg.size(), 48u);
  ASSERT_EQ(pq.profile.angle_from_rd_deg.size(), 48u);
  for (std::size_t i = 0; i < 48; ++i) {
    EXPECT_NEAR(pq.profile.angle_from_rd_deg[i], pf.profile.angle_from_rd_deg[i], 1e-9) << i;
    EXPECT_NEAR(pq.profile.height_mm[i], pf.profile.height_mm[i], 1e-9) << i;
    EXPECT_NEAR(pq.profile.x_mm[i].x(), pf.profile.x_mm[i].x(), 1e-9) << i;
    EXPECT_NEAR(pq.profile.x_mm[i].y(), pf.profile.x_mm[i].y(), 1e-9) << i;
    EXPECT_NEAR(pq.profile.height_mm[i], four_ears(pq.profile.angle_from_rd_deg[i]), 1e-9) << i;
    EXPECT_NEAR(pq.profile.x_mm[i].head<2>().norm(), 30.0, 1e-9);
  }
  const CupProfileSummary s =
      summarize_cup_profile(pq.profile.angle_from_rd_deg, pq.profile.height_mm);
  EXPECT_NEAR(s.mean_height_mm, 34.0, 1e-9);
  EXPECT_NEAR(s.amplitude_mm, 2.0, 1e-9);  // nodes at the ears and the valleys (7.5 deg grid)
  ASSERT_EQ(s.ears.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT(angle_distance_deg(s.ears[k].angle_deg, 90.0 * static_cast<double>(k)), 1e-6);
  }
}

TEST(RimCupProfile, AnglesAreMeasuredFromTheRollingDirection) {
  const Scene full = disc_scene(BlankSymmetry::kFull);
  // Ears at 30 + k 90 deg from x: at 0, 90, 180, 270 from a rolling direction at 30 deg.
  const ShellFields f = synthetic_cup(full, [](double t) { return four_ears(t - 30.0); });
  const CupProfileResult p = rim_cup_profile(full, f, f.stages.back(), 30.0);
  ASSERT_TRUE(p.available);
  EXPECT_EQ(p.profile.rolling_direction_deg, 30.0);
  const CupProfileSummary s =
      summarize_cup_profile(p.profile.angle_from_rd_deg, p.profile.height_mm);
  ASSERT_EQ(s.ears.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT(angle_distance_deg(s.ears[k].angle_deg, 90.0 * static_cast<double>(k)), 1e-6)
        << s.ears[k].angle_deg;
  }
  // The angle column starts at RD: its first node is the one at 30 deg from x.
  EXPECT_NEAR(p.profile.angle_from_rd_deg.front(), 0.0, 1e-9);
  EXPECT_NEAR(std::atan2(p.profile.x_mm.front().y(), p.profile.x_mm.front().x()), rad(30.0), 1e-9);
}

TEST(RimCupProfile, RefusesWhatItCannotMeasure) {
  const Scene quarter = disc_scene(BlankSymmetry::kQuarter);
  const ShellFields q = synthetic_cup(quarter, four_ears);
  // RD at 30 deg: the quarter is not a symmetric part of the cup.
  const CupProfileResult oblique = rim_cup_profile(quarter, q, q.stages.back(), 30.0);
  EXPECT_FALSE(oblique.available);
  EXPECT_NE(oblique.reason.find("rolling direction at 30 deg"), std::string::npos)
      << oblique.reason;
  // RD along y is fine: the same cup seen from y.
  const CupProfileResult along_y = rim_cup_profile(quarter, q, q.stages.back(), 90.0);
  ASSERT_TRUE(along_y.available);
  EXPECT_NEAR(along_y.profile.height_mm.front(), four_ears(90.0), 1e-9);
  Scene pinned = quarter;
  pinned.blank.edge = EdgeCondition::kPinned;
  EXPECT_EQ(rim_cup_profile(pinned, q, q.stages.back(), 0.0).reason, "the blank edge is not free");
  ShellStage empty;
  EXPECT_FALSE(rim_cup_profile(quarter, q, empty, 0.0).available);
}

TEST(RimCupProfile, SquareBlankRimIsItsOutline) {
  Scene square = disc_scene(BlankSymmetry::kQuarter);
  square.blank.shape = BlankShape::kSquare;
  const ShellFields q = synthetic_cup(square, [](double) { return 20.0; });
  const CupProfileResult p = rim_cup_profile(square, q, q.stages.back(), 0.0);
  ASSERT_TRUE(p.available) << p.reason;
  // 2 x 3 + 1 nodes on each outer edge of the quarter (the corner shared): 13, unfolded 48.
  EXPECT_EQ(p.profile.angle_from_rd_deg.size(), 48u);
  // The synthetic drop scales with the initial radius: the corner hangs lowest.
  const CupProfileSummary s =
      summarize_cup_profile(p.profile.angle_from_rd_deg, p.profile.height_mm);
  ASSERT_EQ(s.ears.size(), 4u);
  EXPECT_LT(angle_distance_deg(s.ears[0].angle_deg, 45.0), 1e-6);
}

// ---------------------------------------------------------------------------------------------
// The measured ESAFORM 2021 profile and the file reader.

const std::string kMeasured = std::string(VS_SOURCE_DIR) +
                              "/data/measured/esaform2021-aa6016t4-cup/"
                              "AA6016_Experiment_Fig91_CupProfile_angle.txt";

TEST(MeasuredCupProfile, Esaform2021SummaryIsThePublishedOne) {
  const CupProfilePoints m = read_cup_profile_file(kMeasured);
  ASSERT_EQ(m.angle_deg.size(), 25u);
  EXPECT_DOUBLE_EQ(m.angle_deg.front(), 0.480331);
  EXPECT_DOUBLE_EQ(m.height_mm.back(), 34.515);
  const CupProfileSummary s = summarize_cup_profile(m.angle_deg, m.height_mm);
  // The published mean 34.15 mm is the plain mean of the 25 samples, which counts the ear at
  // 0 deg twice (at 0.48 and 359.954 deg); the mean over the angle is 0.02 mm lower.
  double plain = 0.0;
  for (double h : m.height_mm) plain += h / 25.0;
  EXPECT_NEAR(plain, 34.15, 0.005);
  EXPECT_NEAR(s.mean_height_mm, 34.130, 0.001);
  EXPECT_DOUBLE_EQ(s.min_height_mm, 33.131);
  EXPECT_DOUBLE_EQ(s.max_height_mm, 35.256);
  EXPECT_NEAR(s.amplitude_mm, 2.125, 1e-9);
  ASSERT_EQ(s.ears.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT(angle_distance_deg(s.ears[k].angle_deg, 90.0 * static_cast<double>(k)), 8.0)
        << s.ears[k].angle_deg;
  }
  // The valleys near 45 + k 90 deg, the one at 225 deg measured at 238 deg.
  ASSERT_EQ(s.valleys.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT(angle_distance_deg(s.valleys[k].angle_deg, 45.0 + 90.0 * static_cast<double>(k)),
              15.0)
        << s.valleys[k].angle_deg;
  }
}

// The InputError message of reading `text` as a profile file, the scratch folder removed.
std::string profile_error(const std::string& text) {
  const std::filesystem::path path = test::scratch_folder() / "profile.txt";
  std::ofstream(path) << text;
  try {
    read_cup_profile_file(path.string());
  } catch (const InputError& e) {
    std::string message = e.what();
    const std::string folder = path.parent_path().string() + "/";
    if (const auto at = message.find(folder); at != std::string::npos)
      message.erase(at, folder.size());
    return message;
  }
  return "read";
}

TEST(MeasuredCupProfile, MalformedFilesGiveOneLineNamingFileAndLine) {
  EXPECT_EQ(profile_error("0, 34\n90, 35\n180, 34\n"), "read");
  EXPECT_EQ(profile_error("# c\n0 34\n\n90\t35\n180 ,34\n"), "read");
  EXPECT_EQ(profile_error("0, 34\n90, abc\n180, 34\n"),
            "profile.txt:2: '90, abc' does not start with two numbers");
  EXPECT_EQ(profile_error("0, 34\n90, 35, 1\n180, 34\n"),
            "profile.txt:2: expected 2 values (angle_deg, height_mm), got '90, 35, 1'");
  EXPECT_EQ(profile_error("0, 34\n# gap\n400, 35\n180, 34\n"),
            "profile.txt:3: angle 400 deg is outside [0, 360]");
  EXPECT_EQ(profile_error("0, 34\n90, 35\n360.5, 34\n"),
            "profile.txt:3: angle 360.5 deg is outside [0, 360]");
  EXPECT_EQ(profile_error("10, 34\n90, 35\n370, 34\n"),
            "profile.txt:3: angle 370 deg is outside [0, 360]");
  EXPECT_EQ(profile_error("0, 34\n90, 35\n180, 33\n360, 35\n"),
            "profile.txt:4: angle 360 deg repeats the angle of line 1 (modulo 360) with another "
            "height (35 vs 34 mm)");
  EXPECT_EQ(profile_error("0, 34\n90, 35\n90, 34\n"),
            "profile.txt:3: angle 90 deg repeats the angle of line 2 (modulo 360) with another "
            "height (34 vs 35 mm)");
  // A closed curve (0 and 360 deg with one height) and quarters joined at 90 deg (the benchmark
  // participants' files) are read once: the repeated points do not count towards three points.
  EXPECT_EQ(profile_error("0, 34\n90, 35\n90, 35\n180, 33\n360, 34\n"), "read");
  EXPECT_EQ(profile_error("0, 34\n90, 35\n360, 34\n"),
            "profile.txt:3: a cup profile needs at least 3 points, got 2");
  EXPECT_EQ(profile_error("0, 34\n90, nan\n180, 34\n"),
            "profile.txt:2: height nan mm is not finite");
  EXPECT_EQ(profile_error("0, 34\n90, 35\n"),
            "profile.txt:2: a cup profile needs at least 3 points, got 2");
  EXPECT_EQ(profile_error("angle,height\n0, 34\n"),
            "profile.txt:1: expected a header starting 'angle_from_rd_deg,cup_height_mm', got "
            "'angle,height'");
  // A run's own cup_profile.csv reads back (its first two columns).
  EXPECT_EQ(profile_error("# punch_travel_mm=40\nangle_from_rd_deg,cup_height_mm,x_mm,y_mm,z_mm\n"
                          "0,34,1,2,3\n90,35,1,2,3\n180,34,1,2,3\n"),
            "read");
  EXPECT_EQ(profile_error("angle_from_rd_deg,cup_height_mm,x_mm\n0,34\n"),
            "profile.txt:2: expected 3 values (angle_deg, height_mm, ...), got '0,34'");
}

TEST(MeasuredCupProfile, SceneKeyIsResolvedBesideTheSceneAndCheckedAtLoad) {
  const std::filesystem::path dir = test::scratch_folder();
  std::ofstream(dir / "cup.txt") << "0, 34\n90, 35\n180, 34\n270, 35\n";
  // The bundled 3D deep drawing (it ends with its [output] table) with the key appended.
  const std::string base = test::read_file(std::string(VS_SOURCE_DIR) +
                                           "/data/scenes/ex2_quarter_disc_deep_drawing_3d.toml");
  ASSERT_NE(base.rfind("[output]"), std::string::npos);
  const auto key_line = static_cast<int>(std::count(base.begin(), base.end(), '\n')) + 1;
  std::ofstream(dir / "scene.toml") << base << "measured_cup_profile = \"cup.txt\"\n";
  const Scene scene = load_scene((dir / "scene.toml").string());
  EXPECT_EQ(scene.output.measured_cup_profile, (dir / "cup.txt").string());
  EXPECT_EQ(scene.output.measured_cup_height_mm, (std::vector<double>{34.0, 35.0, 34.0, 35.0}));
  std::ofstream(dir / "scene.toml") << base << "measured_cup_profile = \"no.txt\"\n";
  try {
    load_scene((dir / "scene.toml").string());
    ADD_FAILURE() << "a missing profile file loaded";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(fmt::format("scene.toml:{}:", key_line)), std::string::npos) << message;
    EXPECT_NE(message.find("output.measured_cup_profile: cannot open"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  // A malformed file is refused at load, naming the file and its line.
  std::ofstream(dir / "cup.txt") << "0, 34\n90, 35\n180, x\n";
  std::ofstream(dir / "scene.toml") << base << "measured_cup_profile = \"cup.txt\"\n";
  try {
    load_scene((dir / "scene.toml").string());
    ADD_FAILURE() << "a malformed profile file loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cup.txt:3: '180, x' does not start with two numbers"),
              std::string::npos)
        << e.what();
  }
}

// ---------------------------------------------------------------------------------------------
// The run folder.

RunResult synthetic_3d_run(const Scene& scene) {
  RunResult r;
  r.geometry = Geometry::kShell3d;
  r.steps = {test::step_record(1, 20.0, 1000.0, 0.9), test::step_record(2, 40.0, 1500.0, 0.8)};
  r.shell = std::make_shared<ShellFields>(synthetic_cup(scene, four_ears));
  return r;
}

TEST(CupProfileFiles, RunFolderHasTheCsvTheSvgAndTheSummary) {
  Scene scene = disc_scene(BlankSymmetry::kQuarter);
  scene.output.measured_cup_profile = kMeasured;
  const CupProfilePoints m = read_cup_profile_file(kMeasured);
  scene.output.measured_cup_angle_deg = m.angle_deg;
  scene.output.measured_cup_height_mm = m.height_mm;
  const std::filesystem::path dir = test::scratch_folder();
  const std::vector<std::string> files =
      write_run_folder(scene, synthetic_3d_run(scene), dir.string());
  EXPECT_NE(std::find(files.begin(), files.end(), "cup_profile.csv"), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), "cup_profile.svg"), files.end());
  const std::vector<std::string> csv = test::lines(test::read_file(dir / "cup_profile.csv"));
  ASSERT_EQ(csv.size(), 2u + 48u);
  EXPECT_EQ(csv[0], "# punch_travel_mm=40, rolling_direction_deg=0, unfolded=1");
  EXPECT_EQ(csv[1], "angle_from_rd_deg,cup_height_mm,x_mm,y_mm,z_mm");
  EXPECT_EQ(csv[2].rfind("0,35,30,0,", 0), 0u) << csv[2];
  // The CSV reads back as a profile file.
  const CupProfilePoints back = read_cup_profile_file((dir / "cup_profile.csv").string());
  EXPECT_EQ(back.angle_deg.size(), 48u);
  const std::string svg = test::read_file(dir / "cup_profile.svg");
  EXPECT_NE(svg.find("angle from the rolling direction [deg]"), std::string::npos);
  EXPECT_NE(svg.find("measured"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(test::read_file(dir / "run.json"));
  ASSERT_TRUE(j.contains("cup_profile"));
  EXPECT_TRUE(j["cup_profile"]["available"].get<bool>());
  EXPECT_NEAR(j["cup_profile"]["computed"]["mean_height_mm"].get<double>(), 34.0, 1e-9);
  EXPECT_NEAR(j["cup_profile"]["computed"]["amplitude_mm"].get<double>(), 2.0, 1e-9);
  EXPECT_EQ(j["cup_profile"]["computed"]["ears"].size(), 4u);
  EXPECT_NEAR(j["cup_profile"]["measured"]["mean_height_mm"].get<double>(), 34.13, 0.001);
  EXPECT_LT(j["cup_profile"]["ear_offset_deg"].get<double>(), 8.0);
  const std::string text = summary_report(summarize_run(scene, synthetic_3d_run(scene)));
  EXPECT_NE(text.find("cup height        mean 34.000 mm, 33.000-35.000 mm, amplitude 2.000 mm"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("ears              0.0, 90.0, 180.0, 270.0 deg from RD"), std::string::npos)
      << text;
}

TEST(CupProfileFiles, NoProfileWithoutAFreeEdgeOr3D) {
  Scene scene = disc_scene(BlankSymmetry::kQuarter);
  scene.blank.edge = EdgeCondition::kClamped;
  const std::filesystem::path dir = test::scratch_folder();
  const std::vector<std::string> files =
      write_run_folder(scene, synthetic_3d_run(scene), dir.string());
  EXPECT_EQ(std::find(files.begin(), files.end(), "cup_profile.csv"), files.end());
  const nlohmann::json j = nlohmann::json::parse(test::read_file(dir / "run.json"));
  EXPECT_FALSE(j["cup_profile"]["available"].get<bool>());
  EXPECT_EQ(j["cup_profile"]["reason"], "the blank edge is not free");
  EXPECT_EQ(summary_report(summarize_run(scene, synthetic_3d_run(scene))).find("cup height"),
            std::string::npos);
  // An axisymmetric run has the entry too (both geometries write the same keys), not available.
  const std::filesystem::path axi = test::scratch_folder() / "axisymmetric";
  std::filesystem::create_directories(axi);
  write_run_folder(test::small_scene(), test::completed_result(), axi.string());
  const nlohmann::json a = nlohmann::json::parse(test::read_file(axi / "run.json"));
  EXPECT_FALSE(a["cup_profile"]["available"].get<bool>());
  EXPECT_FALSE(std::filesystem::exists(axi / "cup_profile.csv"));
}

}  // namespace
}  // namespace vs
