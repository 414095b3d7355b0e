#include "synthetic.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "inverse_test_support.h"
#include "scene/load_scene.h"

namespace vs {
namespace {

using namespace vs::testing;

TEST(Synthetic, GaussianNoiseIsDeterministicAndStandard) {
  GaussianNoise a(3), b(3);
  double sum = 0.0, sum_sq = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = a.next();
    EXPECT_EQ(x, b.next());
    sum += x;
    sum_sq += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.03);
  EXPECT_NEAR(sum_sq / n, 1.0, 0.03);
}

TEST(Synthetic, MeasurementsCarryProvenanceAndRoundTrip) {
  const fs::path dir = scratch_dir();
  Scene scene = load_scene(write_scene(dir).string());
  scene.process.output_travels_mm = {10.0};
  const RunResult run = StretchingFake{}(scene);
  const auto data = make_synthetic_measurements(
      scene, run,
      {{MeasurementKind::kLoadTravel, "load", 0.0, {}, 0.01, 0.0},
       {MeasurementKind::kThicknessStrain, "thick", 10.0, {}, 0.0, 0.001}},
      9);
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[0].x.size(), run.steps.size());  // default abscissae: the run's steps
  EXPECT_EQ(data[1].x, run.profiles[0].r0_mm);    // ... and element midpoints
  EXPECT_NE(data[0].provenance[0].second.find("SYNTHETIC"), std::string::npos);
  EXPECT_DOUBLE_EQ(data[1].point_sigma[0], 0.001);
  for (const auto& m : data) {
    write_measurement_csv(m, (dir / (m.name + ".csv")).string());
    const Measurement back = read_measurement_csv((dir / (m.name + ".csv")).string(), m.kind);
    EXPECT_EQ(back.y, m.y);
  }
  const auto again = make_synthetic_measurements(
      scene, run, {{MeasurementKind::kLoadTravel, "load", 0.0, {}, 0.01, 0.0}}, 9);
  EXPECT_EQ(again[0].y, data[0].y);
}

TEST(Synthetic, RunThatCannotProvideTheDataIsAnError) {
  const fs::path dir = scratch_dir();
  Scene scene = load_scene(write_scene(dir).string());
  const RunResult run = StretchingFake{}(scene);
  EXPECT_THROW(make_synthetic_measurements(
                   scene, run, {{MeasurementKind::kThicknessStrain, "t", 12.0, {}, 0.0, 0.0}}, 1),
               InputError);
}

}  // namespace
}  // namespace vs
