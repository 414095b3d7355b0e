// Twin experiments with closed-form forward models: recovery, noise coverage, exact linear
// covariance, undetermined parameters, failing forward runs, thread-count independence.
#include "calibrate.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <atomic>
#include <cmath>

#include "inverse_test_support.h"
#include "scene/load_scene.h"
#include "synthetic.h"

namespace vs {
namespace {

using namespace vs::testing;

struct Truth {
  double friction = 0.12;
  double K_MPa = 540.0;
  double n = 0.22;
  double r_value = 1.4;
};

Scene truth_scene(const fs::path& scene_file, const Truth& truth) {
  Scene scene = load_scene(scene_file.string());
  for (auto& tool : scene.tools) {
    if (tool.name == "punch") tool.friction = truth.friction;
  }
  scene.material.hardening.K_MPa = truth.K_MPa;
  scene.material.hardening.n = truth.n;
  scene.material.r_value = truth.r_value;
  scene.process.output_travels_mm = {15.0, 25.0};
  return scene;
}

// Load-travel curve plus thickness strain at two travels, as the stretching test.
CalibrationConfig stretching_config(const fs::path& dir, const Truth& truth, double noise_relative,
                                    unsigned long long seed, double start_factor) {
  const fs::path scene_file = write_scene(dir);
  const Scene scene = truth_scene(scene_file, truth);
  const RunResult run = StretchingFake{}(scene);
  std::vector<double> travels, radii;
  for (int i = 1; i <= 25; ++i) travels.push_back(1.0 * i);
  for (int i = 0; i <= 20; ++i) radii.push_back(2.0 * i);
  std::vector<SyntheticDataSpec> specs = {
      {MeasurementKind::kLoadTravel, "load", 0.0, travels, noise_relative, 0.0},
      {MeasurementKind::kThicknessStrain, "thick_15", 15.0, radii, noise_relative, 0.0},
      {MeasurementKind::kThicknessStrain, "thick_25", 25.0, radii, noise_relative, 0.0},
  };
  const auto measured = make_synthetic_measurements(scene, run, specs, seed);

  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {
      param("tool.punch.friction", truth.friction * start_factor, 0.0, 0.5, 0.1),
      param("material.hardening.K_MPa", truth.K_MPa * start_factor, 100.0, 2000.0, 500.0),
      param("material.hardening.n", truth.n * start_factor, 0.05, 0.6, 0.2),
      param("material.r_value", truth.r_value * start_factor, 0.3, 5.0, 1.0),
  };
  // Noise-free data still needs a scale per data set: about 1% of each curve's size.
  const double sigmas[] = {100.0, 0.002, 0.002};
  for (std::size_t k = 0; k < measured.size(); ++k) {
    config.data.push_back(data_set(measured[k], sigmas[k]));
  }
  config.optimizer.threads = 2;
  // The closed-form fake has no convergence noise: no noise-floor stop, so that these tests
  // check the optimiser to 1e-6 (the noise-floor stop is tested in honest_calibration_test.cc).
  config.optimizer.noise_floor_factor = 0.0;
  return config;
}

void expect_recovered(const CalibrationResult& result, const Truth& truth, double tolerance) {
  const Eigen::VectorXd x = result.free_values();
  const double expected[] = {truth.friction, truth.K_MPa, truth.n, truth.r_value};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(x[i] / expected[i], 1.0, tolerance) << result.parameters[i].spec.address;
  }
}

TEST(Calibrate, RecoversFourParametersFromTwoStarts) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  for (double start : {0.7, 1.3}) {
    const auto config = stretching_config(dir, truth, 0.0, 1, start);
    const auto result = calibrate(config, quiet(), StretchingFake{});
    EXPECT_EQ(result.termination, CalibrationTermination::kConverged) << result.message;
    expect_recovered(result, truth, 1e-6);
    EXPECT_LT(result.final_cost, 1e-12);
    EXPECT_EQ(result.failed_evaluations, 0);
    ASSERT_TRUE(result.uncertainty_available);
    EXPECT_EQ(result.uncertainty.rank, 4);
  }
}

TEST(Calibrate, RiddersDifferencesAlsoRecover) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  auto config = stretching_config(dir, truth, 0.0, 1, 0.7);
  config.optimizer.fd.method = FdMethod::kRidders;
  const auto result = calibrate(config, quiet(), StretchingFake{});
  expect_recovered(result, truth, 1e-6);
}

TEST(Calibrate, NoisyDataCoverageOfIntervalsIsPlausible) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  const double expected[] = {truth.friction, truth.K_MPa, truth.n, truth.r_value};
  const int repetitions = 20;
  int inside[4] = {0, 0, 0, 0};
  for (int seed = 1; seed <= repetitions; ++seed) {
    auto config = stretching_config(dir, truth, 0.01, static_cast<unsigned long long>(seed), 0.7);
    // Weights from the true noise level (the CSV sigma column), as a lab would state it.
    for (auto& d : config.data) d.sigma = 0.0;
    const auto result = calibrate(config, quiet(), StretchingFake{});
    ASSERT_TRUE(result.uncertainty_available) << result.uncertainty_message;
    for (int i = 0; i < 4; ++i) {
      const auto& u = result.uncertainty.parameters[i];
      if (u.interval_lower <= expected[i] && expected[i] <= u.interval_upper) ++inside[i];
      EXPECT_LT(std::abs(u.value / expected[i] - 1.0), 0.1) << "seed " << seed;
    }
  }
  RecordProperty("coverage", fmt::format("{} {} {} {} of {}", inside[0], inside[1], inside[2],
                                         inside[3], repetitions));
  for (int i = 0; i < 4; ++i) {
    EXPECT_GE(inside[i], 16) << "parameter " << i << ": truth inside the 95% interval in "
                             << inside[i] << " of " << repetitions << " repetitions";
  }
}

TEST(Calibrate, FrictionAloneFromThicknessProfiles) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  auto config = stretching_config(dir, truth, 0.0, 1, 1.0);
  config.data.erase(config.data.begin());  // profiles only
  for (std::size_t i = 1; i < config.parameters.size(); ++i) config.parameters[i].fixed = true;
  config.parameters[0].initial = 0.7 * truth.friction;
  const auto result = calibrate(config, quiet(), StretchingFake{});
  ASSERT_EQ(result.free_values().size(), 1);
  EXPECT_NEAR(result.free_values()[0] / truth.friction, 1.0, 1e-6);
  EXPECT_TRUE(result.uncertainty.well_determined());
}

TEST(Calibrate, HardeningAloneFromTheLoadCurve) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  auto config = stretching_config(dir, truth, 0.0, 1, 1.0);
  config.data.resize(1);  // load curve only
  config.parameters[0].fixed = true;
  config.parameters[3].fixed = true;
  config.parameters[1].initial = 1.3 * truth.K_MPa;
  config.parameters[2].initial = 0.7 * truth.n;
  const auto result = calibrate(config, quiet(), StretchingFake{});
  ASSERT_EQ(result.free_values().size(), 2);
  EXPECT_NEAR(result.free_values()[0] / truth.K_MPa, 1.0, 1e-6);
  EXPECT_NEAR(result.free_values()[1] / truth.n, 1.0, 1e-6);
}

TEST(Calibrate, LinearModelCovarianceIsExact) {
  const fs::path dir = scratch_dir();
  const fs::path scene_file = write_scene(dir);
  Measurement m;
  m.name = "load";
  m.kind = MeasurementKind::kLoadTravel;
  GaussianNoise noise(7);
  const double sigma = 20.0;
  for (int i = 1; i <= 30; ++i) {
    m.x.push_back(i);
    m.y.push_back(480.0 + 1000.0 * 0.15 * i + sigma * noise.next());
  }
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("material.hardening.K_MPa", 400.0, 1.0, 2000.0, 100.0),
                       param("tool.punch.friction", 0.3, 0.0, 1.0, 0.1)};
  config.data = {data_set(m, sigma)};
  const auto result = calibrate(config, quiet(), LinearFake{});
  ASSERT_TRUE(result.uncertainty_available);

  // Closed form: J = [1, 1000 t] / sigma, Cov = s^2 (J^T J)^-1, s^2 = |r|^2 / (m - p).
  Eigen::MatrixXd j(30, 2);
  for (int i = 0; i < 30; ++i) j.row(i) << 1.0 / sigma, 1000.0 * (i + 1) / sigma;
  const Eigen::VectorXd x = result.free_values();
  Eigen::VectorXd r(30);
  for (int i = 0; i < 30; ++i) r[i] = (x[0] + 1000.0 * x[1] * (i + 1) - m.y[i]) / sigma;
  // Least squares optimum: normal equations hold.
  const Eigen::VectorXd x_exact =
      (j.transpose() * j)
          .ldlt()
          .solve(j.transpose() * Eigen::Map<const Eigen::VectorXd>(m.y.data(), 30) / sigma);
  EXPECT_NEAR(x[0], x_exact[0], 1e-6 * std::abs(x_exact[0]));
  EXPECT_NEAR(x[1], x_exact[1], 1e-6 * std::abs(x_exact[1]));
  const Eigen::MatrixXd cov = (j.transpose() * j).inverse() * r.squaredNorm() / 28.0;
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      EXPECT_NEAR(result.uncertainty.covariance(a, b), cov(a, b),
                  1e-6 * std::sqrt(cov(a, a) * cov(b, b)));
    }
  }
  EXPECT_EQ(result.uncertainty.quantile_kind, "student_t(28)");
}

// A sigma per point (a measurement file's sigma column) makes the fit weighted least squares:
// residual (model - y_i) / sigma_i, so that with A = [1, 1000 t] the optimum is the closed form
// x = (A^T W A)^-1 A^T W y, W = diag(1 / sigma_i^2), and Cov = s^2 (A^T W A)^-1 with
// s^2 = r^T W r / (m - p). The first half of the points is 16 times more precise than the
// second; the weighted estimate then differs from the unweighted one and from one weighted by
// 1 / sigma^4 by many times the tolerance (checked), so a wrong power of sigma cannot pass.
TEST(Calibrate, LinearModelWithPointSigmasIsWeightedLeastSquares) {
  const fs::path dir = scratch_dir();
  const fs::path scene_file = write_scene(dir);
  Measurement m;
  m.name = "load";
  m.kind = MeasurementKind::kLoadTravel;
  GaussianNoise noise(11);
  constexpr int kPoints = 30;
  for (int i = 1; i <= kPoints; ++i) {
    const double sigma = i <= 15 ? 5.0 : 80.0;
    m.x.push_back(i);
    m.point_sigma.push_back(sigma);
    m.y.push_back(480.0 + 1000.0 * 0.15 * i + sigma * noise.next());
  }
  CalibrationConfig config;
  config.scenes = {{"scene", scene_file.string(), "test"}};
  config.parameters = {param("material.hardening.K_MPa", 400.0, 1.0, 2000.0, 100.0),
                       param("tool.punch.friction", 0.3, 0.0, 1.0, 0.1)};
  config.data = {data_set(m, 0.0)};
  const auto result = calibrate(config, quiet(), LinearFake{});
  ASSERT_TRUE(result.uncertainty_available);

  Eigen::MatrixXd a(kPoints, 2);
  Eigen::VectorXd y(kPoints), w(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    a.row(i) << 1.0, 1000.0 * (i + 1);
    y[i] = m.y[i];
    w[i] = 1.0 / (m.point_sigma[i] * m.point_sigma[i]);
  }
  auto weighted_fit = [&](const Eigen::VectorXd& weights) {
    const Eigen::MatrixXd atw = a.transpose() * weights.asDiagonal();
    return Eigen::VectorXd((atw * a).ldlt().solve(atw * y));
  };
  const Eigen::VectorXd x_exact = weighted_fit(w);
  const Eigen::VectorXd x_unweighted = weighted_fit(Eigen::VectorXd::Ones(kPoints));
  const Eigen::VectorXd x_fourth = weighted_fit(w.cwiseProduct(w));
  const Eigen::VectorXd x = result.free_values();
  for (int k = 0; k < 2; ++k) {
    const double tol = 1e-6 * std::abs(x_exact[k]);
    EXPECT_GT(std::abs(x_unweighted[k] - x_exact[k]), 100.0 * tol);
    EXPECT_GT(std::abs(x_fourth[k] - x_exact[k]), 100.0 * tol);
    EXPECT_NEAR(x[k], x_exact[k], tol) << config.parameters[k].address;
  }
  const Eigen::VectorXd r = a * x - y;
  const double s2 = r.dot(w.cwiseProduct(r)) / (kPoints - 2);
  const Eigen::MatrixXd cov = (a.transpose() * w.asDiagonal() * a).inverse() * s2;
  for (int p = 0; p < 2; ++p) {
    for (int q = 0; q < 2; ++q) {
      EXPECT_NEAR(result.uncertainty.covariance(p, q), cov(p, q),
                  1e-6 * std::sqrt(cov(p, p) * cov(q, q)));
    }
  }
}

TEST(Calibrate, ParameterTheDataCannotSeeIsReportedPoorlyDetermined) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  auto config = stretching_config(dir, truth, 0.0, 1, 0.8);
  // The fake ignores the die's friction entirely: a zero Jacobian column.
  config.parameters.push_back(param("tool.die.friction", 0.1, 0.0, 0.5, 0.1));
  const auto result = calibrate(config, quiet(), StretchingFake{});
  ASSERT_TRUE(result.uncertainty_available);
  EXPECT_EQ(result.uncertainty.rank, 4);
  const auto& die = result.uncertainty.parameters.at(4);
  EXPECT_FALSE(die.determined);
  EXPECT_TRUE(std::isinf(die.std_error));
  bool stated = false;
  for (const auto& s : result.uncertainty.statements) {
    stated = stated || s.find("tool.die.friction is not determined") != std::string::npos;
  }
  EXPECT_TRUE(stated);
  expect_recovered(result, truth, 1e-6);  // the others are unaffected
}

TEST(Calibrate, FrictionFromLoadCurveAloneIsPoorlyDetermined) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  auto config = stretching_config(dir, truth, 0.01, 3, 0.8);
  config.data.resize(1);  // load curve only: friction barely enters it
  config.data[0].sigma = 0.0;
  const auto result = calibrate(config, quiet(), StretchingFake{});
  ASSERT_TRUE(result.uncertainty_available);
  EXPECT_FALSE(result.uncertainty.parameters[0].determined);
  EXPECT_FALSE(result.uncertainty.well_determined());
}

TEST(Calibrate, FailingForwardRunsAreCountedNotFatal) {
  const fs::path dir = scratch_dir();
  const Truth truth;
  for (bool throws : {false, true}) {
    auto config = stretching_config(dir, truth, 0.0, 1, 1.0);
    // Start just below the failing region: the upward finite-difference run fails (and the
    // derivative is taken downward instead).
    config.parameters[0].initial = 0.1999;
    StretchingFake fake;
    fake.fail_above_friction = 0.2;
    fake.throw_instead = throws;
    const auto result = calibrate(config, quiet(), fake);
    EXPECT_GT(result.failed_evaluations, 0);
    EXPECT_NE(result.termination, CalibrationTermination::kFailed) << result.message;
    EXPECT_NEAR(result.free_values()[0], truth.friction, 1e-6);
    int failed_logged = 0;
    for (const auto& e : result.evaluations) failed_logged += e->ok ? 0 : 1;
    EXPECT_EQ(failed_logged, result.failed_evaluations);
  }
}

TEST(Calibrate, FailureAtTheStartIsReportedNotThrown) {
  const fs::path dir = scratch_dir();
  auto config = stretching_config(dir, Truth{}, 0.0, 1, 1.0);
  StretchingFake fake;
  fake.fail_above_friction = -1.0;  // always fails
  const auto result = calibrate(config, quiet(), fake);
  EXPECT_EQ(result.termination, CalibrationTermination::kFailed);
  EXPECT_FALSE(result.uncertainty_available);
  EXPECT_GT(result.failed_evaluations, 0);
}

TEST(Calibrate, ResultDoesNotDependOnThreadCount) {
  const fs::path dir = scratch_dir();
  auto config = stretching_config(dir, Truth{}, 0.01, 5, 0.75);
  config.optimizer.threads = 1;
  const auto one = calibrate(config, quiet(), StretchingFake{});
  config.optimizer.threads = 3;
  const auto three = calibrate(config, quiet(), StretchingFake{});
  ASSERT_EQ(one.evaluations.size(), three.evaluations.size());
  for (std::size_t i = 0; i < one.evaluations.size(); ++i) {
    EXPECT_EQ(one.evaluations[i]->x, three.evaluations[i]->x);
    EXPECT_EQ(one.evaluations[i]->cost, three.evaluations[i]->cost);
  }
  EXPECT_EQ(one.free_values(), three.free_values());
}

TEST(Calibrate, ProgressLinePerIteration) {
  const fs::path dir = scratch_dir();
  auto config = stretching_config(dir, Truth{}, 0.0, 1, 0.8);
  std::vector<std::string> lines;
  CalibrationOptions options = quiet();
  options.progress = [&](const std::string& line) { lines.push_back(line); };
  const auto result = calibrate(config, options, StretchingFake{});
  int iteration_lines = 0;
  for (const auto& l : lines) {
    if (l.rfind("iter", 0) == 0) {
      ++iteration_lines;
      EXPECT_NE(l.find("forward runs"), std::string::npos);
    }
  }
  EXPECT_EQ(iteration_lines, result.iterations + 1);  // iteration 0 is the start
  // The fake runs take microseconds: no line per evaluation at the default threshold.
  for (const auto& l : lines) EXPECT_EQ(l.find("  evaluation "), std::string::npos) << l;
}

// Slow forward runs (3D) get a line per evaluation: its values, its cost and its run time.
TEST(Calibrate, ProgressLinePerSlowEvaluation) {
  const fs::path dir = scratch_dir();
  auto config = stretching_config(dir, Truth{}, 0.0, 1, 0.8);
  std::vector<std::string> lines;
  CalibrationOptions options = quiet();
  options.progress = [&](const std::string& line) { lines.push_back(line); };
  options.progress_evaluation_s = 0.0;  // every evaluation counts as slow
  const auto result = calibrate(config, options, StretchingFake{});
  std::vector<std::string> evaluation_lines;
  for (const auto& l : lines) {
    if (l.rfind("  evaluation ", 0) == 0) evaluation_lines.push_back(l);
  }
  ASSERT_EQ(evaluation_lines.size(), result.evaluations.size());
  EXPECT_EQ(evaluation_lines.front().rfind("  evaluation 1: tool.punch.friction ", 0), 0u)
      << evaluation_lines.front();
  EXPECT_NE(evaluation_lines.front().find("cost "), std::string::npos);
  EXPECT_NE(evaluation_lines.front().find(" s of forward runs)"), std::string::npos);
}

}  // namespace
}  // namespace vs
