// The shell against an independent answer: the stored axisymmetric elastic-plastic continuum
// (CalculiX CAX8R, 60 x 4 elements) of example 1 with punch friction 0.1
// (experiments/08_continuum_reference/results/ci_reference_ex1_mu010.csv, README section 6).
// Not a twin: a different model of the same sheet (solid elements, penalty contact, elasticity),
// so a wrong material law, hardening, friction or thickness update in the shell moves the
// comparison. Only the reference itself is read here; CalculiX is not needed.
// Two tests: the plane-stress shell (the default) within its model-form gap, and the shell with
// the through-thickness normal stress (numerics.normal_stress = contact, README section 8)
// within issue 15's goal where it meets it and within its measured gap where it does not.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "forming_util.h"

namespace vs {
namespace {

struct ReferenceRow {
  double travel_mm = 0.0, force_N = 0.0, eps_t = 0.0;  // eps_t at r0 = 2.959 mm
};

std::vector<ReferenceRow> read_reference() {
  std::ifstream in(std::string(VS_SOURCE_DIR) +
                   "/experiments/08_continuum_reference/results/ci_reference_ex1_mu010.csv");
  std::string line;
  auto next = [&in, &line] { return test::getline_crlf(in, line); };
  next();
  EXPECT_EQ(line,
            "punch_travel_mm,punch_force_N,eps_thickness_r0_1.7754mm,eps_thickness_r0_2.959mm");
  std::vector<ReferenceRow> rows;
  while (next()) {
    std::stringstream ss(line);
    std::string f[4];
    for (auto& x : f) std::getline(ss, x, ',');
    rows.push_back({std::stod(f[0]), std::stod(f[1]), std::stod(f[3])});
  }
  return rows;
}

// The reference row at `travel_mm`, or null.
const ReferenceRow* row_at(const std::vector<ReferenceRow>& ref, double travel_mm) {
  for (const ReferenceRow& q : ref) {
    if (q.travel_mm == travel_mm) return &q;
  }
  return nullptr;
}

// Tolerances: TODAY'S MODEL-FORM GAP, not the goal. The continuum is converged to 0.05 % in force
// and 0.0006 in thickness strain (README section 3). The shell differs from it by a model-form
// error (no through-thickness stress, no elasticity): +1.8 % in force at 10-15 mm and 0.0009 /
// 0.0025 in thickness strain at r0 = 2.959 mm at 10 / 15 mm (README section 6). The bounds are
// that gap plus the reference's uncertainty plus the shell's mesh noise in force (~0.5 %, the
// 50-element mesh against finer ones): force within [0, +2.5 %] (the shell is stiffer: a sign
// check too), thickness strain within 0.0035. Issue 15's goal (1 % / 0.005) is NOT met by the
// force today; experiments/08_continuum_reference prints the comparison against it.
constexpr double kForceGapMax = 0.025;
constexpr double kThicknessStrainGap = 0.0035;

TEST(ContinuumReference, Example1Friction01WithinTheModelFormGap) {
  const std::vector<ReferenceRow> ref = read_reference();
  ASSERT_GE(ref.size(), 3u);
  const RunResult r = simulate(test::load_with("ex1_hemispherical_stretching.toml",
                                               {{"tool.punch.friction", "0.1"},
                                                {"process.punch_travel_mm", "15"},
                                                {"process.output_travels_mm", "[10.0, 15.0]"},
                                                {"output.history", "false"}}));
  ASSERT_TRUE(r.completed()) << r.message;
  ASSERT_EQ(r.profiles.size(), 3u);  // 10, 15 mm and the final state
  int compared = 0;
  for (const ReferenceRow& row : ref) {
    if (row.travel_mm != 10.0 && row.travel_mm != 15.0) continue;
    double force = 0.0;
    for (const auto& s : r.steps) {
      if (std::abs(s.punch_travel_mm - row.travel_mm) < 1e-9) force = s.punch_force_N;
    }
    const Profile* p = nullptr;
    for (const Profile& q : r.profiles) {
      if (std::abs(q.punch_travel_mm - row.travel_mm) < 1e-9) p = &q;
    }
    ASSERT_NE(p, nullptr);
    // The shell's third point is the reference's r0 = 2.959 mm (50 elements, the scene's mesh).
    ASSERT_GE(p->r0_mm.size(), 3u);
    ASSERT_NEAR(p->r0_mm[2], 2.959, 1e-3);
    const double dF = force / row.force_N - 1.0;
    const double de = p->eps_thickness[2] - row.eps_t;
    fmt::print("{} mm: force {:.1f} N vs continuum {:.1f} N ({:+.2f} %), eps_t {:.5f} vs {:.5f}\n",
               row.travel_mm, force, row.force_N, 100 * dF, p->eps_thickness[2], row.eps_t);
    EXPECT_GT(dF, 0.0) << row.travel_mm << " mm";
    EXPECT_LT(dF, kForceGapMax) << row.travel_mm << " mm";
    EXPECT_LT(std::abs(de), kThicknessStrainGap) << row.travel_mm << " mm";
    ++compared;
  }
  EXPECT_EQ(compared, 2);
}

// A run of ex1 (friction 0.1) to `travel_mm` with outputs at `at`, and its punch force and
// thickness strain at r0 = 2.959 mm (the shell's third point at the scene's 50 elements) there.
struct ShellPoint {
  double force_N = 0.0, eps_t = 0.0;
};
std::vector<ShellPoint> run_ex1(const std::string& normal_stress, double travel_mm,
                                const std::vector<double>& at,
                                const std::vector<std::pair<std::string, std::string>>& more = {}) {
  std::string outs = "[";
  for (double t : at) outs += fmt::format("{}{:.1f}", outs.size() > 1 ? ", " : "", t);
  outs += "]";
  std::vector<std::pair<std::string, std::string>> set = {
      {"tool.punch.friction", "0.1"},
      {"numerics.normal_stress", normal_stress},
      {"process.punch_travel_mm", fmt::format("{}", travel_mm)},
      {"process.output_travels_mm", outs},
      {"output.history", "false"}};
  set.insert(set.end(), more.begin(), more.end());
  const RunResult r = simulate(test::load_with("ex1_hemispherical_stretching.toml", set));
  EXPECT_TRUE(r.completed()) << r.message;
  std::vector<ShellPoint> out;
  for (double t : at) {
    ShellPoint sp;
    for (const auto& s : r.steps) {
      if (std::abs(s.punch_travel_mm - t) < 1e-9) sp.force_N = s.punch_force_N;
    }
    for (const Profile& q : r.profiles) {
      if (std::abs(q.punch_travel_mm - t) < 1e-9) {
        EXPECT_GE(q.r0_mm.size(), 3u);
        if (q.r0_mm.size() < 3) continue;
        EXPECT_NEAR(q.r0_mm[2], 2.959, 1e-3);
        sp.eps_t = q.eps_thickness[2];
      }
    }
    out.push_back(sp);
  }
  return out;
}

// With the through-thickness normal stress (README section 8; measured there for friction 0, 0.1
// and 0.3): the force gap falls from +1.8 / +1.8 / +1.4 / +1.4 % to +1.30 / +1.12 / +0.64 /
// +0.54 % at 10 / 15 / 20 / 25 mm, and the thickness-strain gap at r0 = 2.959 mm from +0.0009 /
// +0.0025 / +0.0050 / +0.0077 to -0.0010 / -0.0004 / +0.0002 / +0.0011. Issue 15's goal (force
// within 1 %, thickness strain within 0.005, from 10 mm) holds from 20 mm; at 10-15 mm the force
// misses it by the elastic start that a rigid-plastic shell cannot have (+0.5 % at 10 mm in
// closed form, README section 5.1), so there the bound is the measured gap plus 0.3 points:
// [0, +1.6 %]. Also checked: the term brings force and thickness strain closer at every travel.
constexpr double kGoalForceGap = 0.01;
constexpr double kGoalThicknessStrainGap = 0.005;
constexpr double kElasticStartForceGap = 0.016;  // 10 and 15 mm (measured +1.30 / +1.12 %)

TEST(ContinuumReference, Example1Friction01WithNormalStressMeetsTheGoalFrom20mm) {
  const std::vector<ReferenceRow> ref = read_reference();
  const std::vector<double> at = {10.0, 15.0, 20.0, 25.0};
  const std::vector<ShellPoint> on = run_ex1("contact", 25.0, at);
  const std::vector<ShellPoint> off = run_ex1("none", 25.0, at);
  ASSERT_EQ(on.size(), at.size());
  int compared = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const ReferenceRow* row = row_at(ref, at[k]);
    ASSERT_NE(row, nullptr) << at[k];
    const double dF = on[k].force_N / row->force_N - 1.0;
    const double dF_off = off[k].force_N / row->force_N - 1.0;
    const double de = on[k].eps_t - row->eps_t, de_off = off[k].eps_t - row->eps_t;
    fmt::print(
        "{} mm, normal stress on / off: force {:+.2f} / {:+.2f} %, eps_t {:+.4f} / {:+.4f}\n",
        at[k], 100 * dF, 100 * dF_off, de, de_off);
    EXPECT_GT(dF, 0.0) << at[k] << " mm";
    EXPECT_LT(dF, at[k] >= 20.0 ? kGoalForceGap : kElasticStartForceGap) << at[k] << " mm";
    EXPECT_LT(std::abs(de), kGoalThicknessStrainGap) << at[k] << " mm";
    EXPECT_LT(dF, dF_off) << at[k] << " mm";
    if (at[k] >= 20.0) {
      EXPECT_LT(std::abs(de), std::abs(de_off)) << at[k] << " mm";
    }
    ++compared;
  }
  EXPECT_EQ(compared, 4);
}

// With the elastic correction as well ([material.elastic], E 210 GPa and nu 0.3 of the
// continuum; README section 10): the elastic start removes the rigid-plastic start, and the
// force meets issue 15's goal from 5 mm (measured +0.67 / +0.12 / +0.52 / +0.30 / +0.33 % at 5 /
// 10 / 15 / 20 / 25 mm, against +3.62 / +1.29 / +1.12 / +0.64 / +0.54 % without). The thickness
// strain at r0 = 2.959 mm (with its elastic part, (4b) of material/elastic_start.h) is within the
// goal to 20 mm (+0.0028 / +0.0034 / +0.0047) and misses it at 25 mm (+0.0061): bound there the
// measured gap plus 0.001.
TEST(ContinuumReference, Example1Friction01WithElasticStartMeetsTheForceGoalFrom5mm) {
  const std::vector<ReferenceRow> ref = read_reference();
  const std::vector<double> at = {5.0, 10.0, 15.0, 20.0, 25.0};
  const std::vector<ShellPoint> on = run_ex1("contact", 25.0, at,
                                             {{"material.elastic.law", "isotropic"},
                                              {"material.elastic.E_MPa", "210000.0"},
                                              {"material.elastic.nu", "0.3"}});
  ASSERT_EQ(on.size(), at.size());
  int compared = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const ReferenceRow* row = row_at(ref, at[k]);
    ASSERT_NE(row, nullptr) << at[k];
    const double dF = on[k].force_N / row->force_N - 1.0;
    const double de = on[k].eps_t - row->eps_t;
    fmt::print("{} mm, elastic start and strains: force {:+.2f} %, eps_t {:+.4f}\n", at[k],
               100 * dF, de);
    EXPECT_LT(std::abs(dF), kGoalForceGap) << at[k] << " mm";
    if (at[k] >= 10.0) {
      EXPECT_LT(std::abs(de), at[k] <= 20.0 ? kGoalThicknessStrainGap : 0.0071) << at[k] << " mm";
    }
    ++compared;
  }
  EXPECT_EQ(compared, 5);
}

}  // namespace
}  // namespace vs
