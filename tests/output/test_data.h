// Small hand-made scenes and results for the output tests, and a scratch folder per test.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs::test {

inline Scene small_scene() {
  Scene s;
  s.source = "small.toml";
  s.title = "Hemispherical <punch> & die";
  s.blank.radius_mm = 50.0;
  s.blank.elements = 4;
  ToolSpec punch;
  punch.name = "punch";
  punch.friction = std::numeric_limits<double>::infinity();
  ToolSpec die;
  die.name = "die";
  die.kind = ToolKind::kDie;
  die.friction = 0.1;
  s.tools = {punch, die};
  s.process.punch_travel_mm = 2.0;
  s.process.output_travels_mm = {1.0};
  return s;
}

inline StepRecord step_record(int step, double travel_mm, double force_N, double thickness_mm) {
  StepRecord r;
  r.step = step;
  r.time_s = travel_mm;
  r.punch_travel_mm = travel_mm;
  r.punch_force_N = force_N;
  r.iterations = 3;
  r.residual_norm = 1e-8;
  r.update_norm = 2e-7;
  r.contact_nodes = step;
  r.min_thickness_mm = thickness_mm;
  r.thinnest_r0_mm = 5.0;
  r.thinnest_r_mm = 5.5;
  r.volume_mm3 = 7853.98;
  r.rim_draw_in_mm = 0.01 * step;
  return r;
}

// Four elements of a 40 mm blank; strains grow with travel and peak at element 1.
inline Profile profile(double travel_mm) {
  Profile p;
  p.punch_travel_mm = travel_mm;
  const double a = 0.05 * travel_mm;
  p.r0_mm = {5.0, 15.0, 25.0, 35.0};
  p.r_mm = {5.2, 15.3, 25.2, 35.0};
  p.z_mm = {travel_mm, 0.8 * travel_mm, 0.3 * travel_mm, 0.0};
  p.eps_meridional = {a, 2.0 * a, a, 0.2 * a};
  p.eps_circumferential = {a, 0.5 * a, -0.2 * a, -0.5 * a};
  for (std::size_t i = 0; i < 4; ++i) {
    p.eps_thickness.push_back(-(p.eps_meridional[i] + p.eps_circumferential[i]));
    p.thickness_mm.push_back(std::exp(p.eps_thickness[i]));
    p.eps_effective.push_back(p.eps_meridional[i]);
  }
  p.contact = {1, 1, 0, 0};
  p.node_r_mm = {0.0, 10.0, 20.0, 30.0, 40.0};
  p.node_z_mm = {travel_mm, 0.9 * travel_mm, 0.5 * travel_mm, 0.1 * travel_mm, 0.0};
  return p;
}

inline RunResult completed_result() {
  RunResult r;
  r.steps = {step_record(1, 0.5, 1000.0, 0.98), step_record(2, 1.0, 2500.0, 0.95),
             step_record(3, 1.5, 3000.0, 0.91), step_record(4, 2.0, 2900.0, 0.88)};
  r.profiles = {profile(1.0), profile(2.0), profile(2.0)};  // end repeats the last travel
  for (const StepRecord& s : r.steps) r.history.push_back(profile(s.punch_travel_mm));
  r.total_iterations = 12;
  r.timings.total_s = 0.25;
  return r;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream buffer;
  buffer << file.rdbuf();
  return buffer.str();
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A fresh, empty folder named after the running test, under the system temp folder.
inline std::filesystem::path scratch_folder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vs_output_tests" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace vs::test
