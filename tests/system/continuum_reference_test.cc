// The shell against an independent answer: the stored axisymmetric elastic-plastic continuum
// (CalculiX CAX8R, 60 x 4 elements) of example 1 with punch friction 0.1
// (experiments/08_continuum_reference/results/ci_reference_ex1_mu010.csv, README section 6).
// Not a twin: a different model of the same sheet (solid elements, penalty contact, elasticity),
// so a wrong material law, hardening, friction or thickness update in the shell moves the
// comparison. Only the reference itself is read here; CalculiX is not needed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
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
  auto next = [&in, &line] {
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the file has CRLF ends
    return true;
  };
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

}  // namespace
}  // namespace vs
