#include "output/run_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "output/step_csv.h"
#include "test_data.h"

namespace vs {
namespace {

namespace fs = std::filesystem;

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(RunWriter, WritesEveryFileOfACompletedRun) {
  const fs::path dir = test::scratch_folder();
  const Scene scene = test::small_scene();
  const RunResult result = test::completed_result();
  const std::vector<std::string> files = write_run_folder(scene, result, dir.string());

  const std::vector<std::string> expected = {"scene.toml",
                                             "load_travel.csv",
                                             "thinnest_point.csv",
                                             "strains_travel_001.00mm.csv",
                                             "strains_travel_002.00mm.csv",
                                             "fld_points.csv",
                                             "strain_paths.csv",
                                             "load_travel.svg",
                                             "thickness_strain.svg",
                                             "strains.svg",
                                             "deformed_stages.svg",
                                             "fld.svg",
                                             "run.json"};
  EXPECT_EQ(files, expected);
  for (const std::string& f : files) EXPECT_TRUE(fs::exists(dir / f)) << f;

  EXPECT_EQ(test::read_file(dir / "load_travel.csv"), load_travel_csv(result.steps));
  EXPECT_EQ(test::lines(test::read_file(dir / "strain_paths.csv")).size(), 1u + 4u * 4u);
  EXPECT_EQ(test::lines(test::read_file(dir / "fld_points.csv")).size(), 5u);
  const std::string svg = test::read_file(dir / "load_travel.svg");
  EXPECT_NE(svg.find("Hemispherical &lt;punch&gt; &amp; die"), std::string::npos);
}

TEST(RunWriter, ManifestHasSceneProgramAndResults) {
  const fs::path dir = test::scratch_folder();
  write_run_folder(test::small_scene(), test::completed_result(), dir.string());
  const nlohmann::json j = nlohmann::json::parse(test::read_file(dir / "run.json"));

  for (const char* key : {"program", "termination", "message", "steps", "total_iterations",
                          "total_cutbacks", "timings", "peak_punch_force_N",
                          "punch_travel_at_peak_mm", "final_min_thickness_mm", "scene", "files"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"version", "git_describe", "compiler", "instruction_set", "eigen_version",
                          "blas_library"}) {
    EXPECT_TRUE(j["program"][key].is_string()) << key;
  }
  EXPECT_EQ(j["termination"], "completed");
  EXPECT_EQ(j["steps"], 4);
  EXPECT_EQ(j["total_iterations"], 12);
  EXPECT_DOUBLE_EQ(j["peak_punch_force_N"].get<double>(), 3000.0);
  EXPECT_DOUBLE_EQ(j["punch_travel_at_peak_mm"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["final_min_thickness_mm"].get<double>(), 0.88);
  EXPECT_DOUBLE_EQ(j["timings"]["total_s"].get<double>(), 0.25);

  const nlohmann::json& scene = j["scene"];
  EXPECT_EQ(scene["title"], "Hemispherical <punch> & die");
  EXPECT_EQ(scene["blank"]["elements"], 4);
  EXPECT_EQ(scene["blank"]["edge"], "pinned");
  EXPECT_DOUBLE_EQ(scene["material"]["hardening"]["K_MPa"].get<double>(), 500.0);
  EXPECT_EQ(scene["material"]["rate"]["law"], "none");
  EXPECT_EQ(scene["tools"][0]["friction"], "sticking");
  EXPECT_DOUBLE_EQ(scene["tools"][1]["friction"].get<double>(), 0.1);
  EXPECT_EQ(scene["tools"][1]["kind"], "die");
  EXPECT_DOUBLE_EQ(scene["numerics"]["max_travel_increment_mm"].get<double>(),
                   NumericsSpec{}.max_travel_increment_mm);
  EXPECT_EQ(scene["output"]["history"], true);
  EXPECT_TRUE(contains(j["files"].get<std::vector<std::string>>(), "run.json"));
}

TEST(RunWriter, SameResultGivesSameBytes) {
  const fs::path a = test::scratch_folder() / "a";
  const fs::path b = a.parent_path() / "b";
  fs::create_directories(a);
  fs::create_directories(b);
  const std::vector<std::string> files =
      write_run_folder(test::small_scene(), test::completed_result(), a.string());
  write_run_folder(test::small_scene(), test::completed_result(), b.string());
  for (const std::string& f : files) {
    EXPECT_EQ(test::read_file(a / f), test::read_file(b / f)) << f;
  }
}

TEST(RunWriter, FailedRunWithoutProfilesOrHistoryStillWritesWhatItHas) {
  const fs::path dir = test::scratch_folder();
  RunResult result;
  result.termination = Termination::kFailed;
  result.message = "no convergence at step 3 after 8 cut-backs";
  result.steps = {test::step_record(1, 0.5, 100.0, 0.99), test::step_record(2, 1.0, 150.0, 0.97)};
  std::vector<std::string> files;
  ASSERT_NO_THROW(files = write_run_folder(test::small_scene(), result, dir.string()));
  EXPECT_FALSE(contains(files, "strains_travel_001.00mm.csv"));
  EXPECT_TRUE(contains(files, "fld.svg"));
  EXPECT_EQ(test::lines(test::read_file(dir / "load_travel.csv")).size(), 3u);
  EXPECT_EQ(test::lines(test::read_file(dir / "fld_points.csv")).size(), 1u);
  EXPECT_EQ(test::lines(test::read_file(dir / "strain_paths.csv")).size(), 1u);
  const nlohmann::json j = nlohmann::json::parse(test::read_file(dir / "run.json"));
  EXPECT_EQ(j["termination"], "failed");
  EXPECT_EQ(j["message"], result.message);
  EXPECT_NE(test::read_file(dir / "load_travel.svg").find("(run failed)"), std::string::npos);
}

TEST(RunWriter, RunFailedBeforeTheFirstStep) {
  const fs::path dir = test::scratch_folder();
  RunResult result;
  result.termination = Termination::kFailed;
  std::vector<std::string> files;
  ASSERT_NO_THROW(files = write_run_folder(test::small_scene(), result, dir.string()));
  const nlohmann::json j = nlohmann::json::parse(test::read_file(dir / "run.json"));
  EXPECT_TRUE(j["peak_punch_force_N"].is_null());
  EXPECT_EQ(j["steps"], 0);
  EXPECT_NE(test::read_file(dir / "strains.svg").find("no data"), std::string::npos);
}

TEST(RunWriter, FailedRunWithHistoryOnlyUsesTheLastState) {
  const fs::path dir = test::scratch_folder();
  RunResult result = test::completed_result();
  result.termination = Termination::kFailed;
  result.profiles.clear();
  const std::vector<std::string> files =
      write_run_folder(test::small_scene(), result, dir.string());
  EXPECT_TRUE(contains(files, "strains_travel_002.00mm.csv"));
  EXPECT_EQ(test::lines(test::read_file(dir / "fld_points.csv")).size(), 5u);
}

TEST(RunWriter, NoPlotsWhenSwitchedOff) {
  const fs::path dir = test::scratch_folder();
  Scene scene = test::small_scene();
  scene.output.plots = false;
  const std::vector<std::string> files =
      write_run_folder(scene, test::completed_result(), dir.string());
  for (const std::string& f : files) EXPECT_EQ(f.find(".svg"), std::string::npos) << f;
}

TEST(RunWriter, TravelsThatRoundAlikeDoNotOverwrite) {
  const fs::path dir = test::scratch_folder();
  RunResult result = test::completed_result();
  result.profiles = {test::profile(1.0), test::profile(1.001)};
  const std::vector<std::string> files =
      write_run_folder(test::small_scene(), result, dir.string());
  EXPECT_TRUE(contains(files, "strains_travel_001.00mm.csv"));
  EXPECT_TRUE(contains(files, "strains_travel_001.00mm_2.csv"));
}

TEST(RunWriter, MissingFolderIsAnInputError) {
  const fs::path dir = test::scratch_folder() / "does_not_exist";
  EXPECT_THROW(write_run_folder(test::small_scene(), test::completed_result(), dir.string()),
               InputError);
}

}  // namespace
}  // namespace vs
