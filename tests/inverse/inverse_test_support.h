// Shared fixtures for the calibration tests: a small scene file, closed-form fake forward models
// (fast, smooth, thread-safe) and helpers to write configs and CSVs into a scratch folder.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "calibrate.h"
#include "calibration_config.h"
#include "forward_model.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs::testing {

namespace fs = std::filesystem;

// A fresh scratch folder per test, removed afterwards.
inline fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::temp_directory_path() /
                 (std::string("vs_inverse_") + info->test_suite_name() + "_" + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// Same layout as data/scenes/ex1_hemispherical_stretching.toml, smaller.
inline const char* kSceneToml = R"(title = "calibration test scene"
geometry = "axisymmetric"
[blank]
radius_mm = 50.0
thickness_mm = 1.0
elements = 20
edge = "pinned"
[material]
r_value = 1.2
[material.hardening]
law = "swift"
K_MPa = 500.0
eps0 = 0.01
n = 0.2
[material.rate]
law = "none"
[[tool]]
name = "punch"
kind = "hemispherical_punch"
radius_mm = 40.0
friction = 0.1
[[tool]]
name = "die"
kind = "die"
radius_mm = 45.0
profile_radius_mm = 5.0
friction = 0.1
[process]
punch_travel_mm = 30.0
output_travels_mm = [30.0]
)";

// A small load curve and thickness profile in the measurement CSV format (config tests).
inline constexpr const char* kLoadCsv =
    "# source: test\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,100\n2,200\n3,300\n";
inline constexpr const char* kThickCsv =
    "# source: test\n# units: mm, 1\nr0_mm,eps_thickness\n0,-0.1\n10,-0.2\n20,-0.1\n";

inline fs::path write_scene(const fs::path& dir) {
  const fs::path path = dir / "scene.toml";
  write_file(path, kSceneToml);
  return path;
}

inline double punch_friction(const Scene& scene) {
  for (const auto& tool : scene.tools) {
    if (tool.name == "punch") return tool.friction;
  }
  return 0.0;
}

// Closed-form stand-in for a stretching test. Smooth in (friction, K, n, R); each is visible:
// the load level and its curvature carry K and n (with R), the thinning peak moves outward with
// friction, its depth depends on R and n. The step grid does not depend on the parameters.
struct StretchingFake {
  std::atomic<int>* calls = nullptr;
  double fail_above_friction = INFINITY;  // runs with more friction fail (kFailed)
  bool throw_instead = false;             // ... or throw

  RunResult operator()(const Scene& scene) const {
    if (calls) ++*calls;
    const double mu = punch_friction(scene);
    const auto& h = scene.material.hardening;
    const double r = scene.material.r_value;
    const double total = scene.process.punch_travel_mm;
    RunResult run;
    if (mu > fail_above_friction) {
      if (throw_instead) throw std::runtime_error("fake solver exploded");
      run.termination = Termination::kFailed;
      run.message = "fake: no convergence at high friction";
      return run;
    }
    auto force = [&](double t) {
      return 20.0 * h.K_MPa * std::pow(h.eps0 + 0.02 * t, h.n) * t * std::sqrt(2.0 / (1.0 + r)) *
             (1.0 + 0.3 * mu * t / total);
    };
    const double dt = 0.37;  // not aligned with the data: interpolation is exercised
    for (int k = 1; k * dt <= total + 1e-12; ++k) {
      StepRecord s;
      s.step = k;
      s.punch_travel_mm = k * dt;
      s.punch_force_N = force(k * dt);
      run.steps.push_back(s);
    }
    StepRecord last;
    last.punch_travel_mm = total;
    last.punch_force_N = force(total);
    run.steps.push_back(last);

    std::vector<double> travels = scene.process.output_travels_mm;
    travels.push_back(total);
    const int n_el = scene.blank.elements;
    for (double t : travels) {
      Profile p;
      p.punch_travel_mm = t;
      const double amplitude = 0.25 * (t / total) * (1.5 / (0.5 + r)) * std::pow(0.2 / h.n, 0.3);
      const double centre = 10.0 + 40.0 * mu;
      const double width = 8.0 * (1.0 + h.n);
      for (int i = 0; i < n_el; ++i) {
        const double r0 = (i + 0.5) * scene.blank.radius_mm / n_el;
        const double z = (r0 - centre) / width;
        const double eps_t = -amplitude * std::exp(-z * z) - 0.02 * t / total;
        p.r0_mm.push_back(r0);
        p.eps_thickness.push_back(eps_t);
        p.eps_circumferential.push_back(-0.5 * eps_t * (1.0 - r0 / scene.blank.radius_mm));
      }
      run.profiles.push_back(p);
    }
    return run;
  }
};

// Linear in (K_MPa, punch friction): force(t) = K + 1000 friction t. For the exact-covariance
// check of the whole pipeline.
struct LinearFake {
  RunResult operator()(const Scene& scene) const {
    RunResult run;
    for (int k = 1; k <= 60; ++k) {
      StepRecord s;
      s.punch_travel_mm = 0.5 * k;
      s.punch_force_N =
          scene.material.hardening.K_MPa + 1000.0 * punch_friction(scene) * s.punch_travel_mm;
      run.steps.push_back(s);
    }
    return run;
  }
};

// Calibration options for tests: no report folder, no progress.
inline CalibrationOptions quiet() {
  CalibrationOptions options;
  options.write_report = false;
  return options;
}

inline ParameterSpec param(const std::string& address, double initial, double lower, double upper,
                           double scale, bool fixed = false) {
  ParameterSpec p;
  p.address = address;
  p.initial = initial;
  p.lower = lower;
  p.upper = upper;
  p.scale = scale;
  p.fixed = fixed;
  p.where = "test";
  return p;
}

inline DataSpec data_set(Measurement m, double sigma) {
  DataSpec d;
  d.measurement = std::move(m);
  d.sigma = sigma;
  d.where = "test";
  return d;
}

}  // namespace vs::testing
