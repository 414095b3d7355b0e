#include "residual_pipeline.h"

#include <gtest/gtest.h>

namespace vs {
namespace {

RunResult ramp_run(double last_travel) {
  RunResult run;
  for (double t = 1.0; t <= last_travel + 1e-12; t += 1.0) {
    StepRecord s;
    s.punch_travel_mm = t;
    s.punch_force_N = 100.0 * t * t;
    run.steps.push_back(s);
  }
  Profile p;
  p.punch_travel_mm = 5.0;
  p.r0_mm = {1.0, 3.0, 5.0};
  p.eps_thickness = {-0.1, -0.3, -0.2};
  p.eps_circumferential = {0.0, 0.1, 0.2};
  run.profiles.push_back(p);
  return run;
}

TEST(ResidualPipeline, InterpolatesLoadFromTheOriginAndWeights) {
  Measurement m;
  m.kind = MeasurementKind::kLoadTravel;
  m.x = {0.5, 2.5, 4.0};
  m.y = {0.0, 600.0, 1600.0};
  ResidualPipeline pipeline({{m, 0, {0.1, 0.1, 1.0}, nullptr, false, {}}});
  const auto r = pipeline.residuals({ramp_run(4.0)});
  ASSERT_TRUE(r.ok);
  EXPECT_DOUBLE_EQ(r.values[0], 0.1 * 50.0);  // between (0,0) and (1,100)
  EXPECT_DOUBLE_EQ(r.values[1], 0.1 * 50.0);  // (400 + 900) / 2 - 600
  EXPECT_DOUBLE_EQ(r.values[2], 0.0);
}

TEST(ResidualPipeline, RunStoppingBeforeTheDataFails) {
  Measurement m;
  m.name = "load";
  m.kind = MeasurementKind::kLoadTravel;
  m.x = {1.0, 6.0};
  m.y = {1.0, 2.0};
  ResidualPipeline pipeline({{m, 0, {1.0, 1.0}, nullptr, false, {}}});
  const auto r = pipeline.residuals({ramp_run(5.0)});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("stopped at 5 mm"), std::string::npos) << r.message;
}

TEST(ResidualPipeline, ProfilesAtTheirTravelWithEndValuesOutside) {
  Measurement m;
  m.kind = MeasurementKind::kThicknessStrain;
  m.travel_mm = 5.0;
  m.x = {0.0, 2.0, 6.0};
  m.y = {0.0, 0.0, 0.0};
  ResidualPipeline pipeline({{m, 0, {1.0, 1.0, 1.0}, nullptr, false, {}}});
  const auto r = pipeline.residuals({ramp_run(5.0)});
  ASSERT_TRUE(r.ok);
  EXPECT_DOUBLE_EQ(r.values[0], -0.1);
  EXPECT_DOUBLE_EQ(r.values[1], -0.2);
  EXPECT_DOUBLE_EQ(r.values[2], -0.2);

  m.travel_mm = 4.0;  // no profile there
  ResidualPipeline missing({{m, 0, {1.0, 1.0, 1.0}, nullptr, false, {}}});
  EXPECT_FALSE(missing.residuals({ramp_run(5.0)}).ok);
}

}  // namespace
}  // namespace vs
