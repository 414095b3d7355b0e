// vshell as a user meets it, run as a subprocess on generated bad inputs of every class of issue
// 16: whatever the input, the process ends with an exit code (never a signal), bad input exits
// 2 with one line on stderr, a calibration that cannot fit exits 3 with its reason as one line.
// Each case is bounded in time (a few seconds); no case runs a simulation.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scene/fuzz_mutate.h"

#ifdef VS_VSHELL_PATH

namespace vs {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  bool signalled = false;
  int exit_code = -1;
  std::string err;  // stderr
  std::string out;  // stdout
};

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / (std::string("vs_cli_fuzz_") + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Runs `vshell ARGS` (ARGS already shell-quoted) with a 20 s CPU limit, in `dir`.
Outcome vshell(const fs::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && ulimit -t 20 && exec '" +
                              std::string(VS_VSHELL_PATH) + "' " + args + " > out.txt 2> err.txt";
  const int status = std::system(command.c_str());
  Outcome o;
  // The shell reports a child killed by signal N as exit status 128 + N.
  if (WIFSIGNALED(status)) {
    o.signalled = true;
  } else if (WIFEXITED(status)) {
    o.exit_code = WEXITSTATUS(status);
    o.signalled = o.exit_code > 128;
  }
  o.out = read_all(dir / "out.txt");
  o.err = read_all(dir / "err.txt");
  return o;
}

void expect_bad_input(const Outcome& o, const std::string& label) {
  EXPECT_FALSE(o.signalled) << label << ": " << o.err;
  EXPECT_EQ(o.exit_code, 2) << label << ": " << o.err.substr(0, 300);
  EXPECT_EQ(o.err.rfind("error: ", 0), 0u) << label << ": " << o.err.substr(0, 300);
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1)
      << label << ": " << o.err.substr(0, 300);
}

std::string repeat(const std::string& s, int n) { return testing::repeat(s, n); }

const std::string kScene =
    std::string(VS_SOURCE_DIR) + "/data/scenes/ex1_hemispherical_stretching.toml";

TEST(CliFuzz, DeeplyNestedScenesAreBadInputNotACrash) {
  const fs::path dir = scratch();
  std::string deep = "a";
  deep += repeat(".a", 50000);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"dotted key", deep + " = 1\n"},
      {"table header", "[" + deep + "]\n"},
      {"array-of-tables header", "[[" + deep + "]]\n"},
      {"arrays", "x = " + repeat("[", 50000) + repeat("]", 50000) + "\n"},
      {"inline tables", "x = " + repeat("{a=", 50000) + "1" + repeat("}", 50000) + "\n"},
  };
  for (const auto& [label, text] : cases) {
    write(dir / "deep.toml", text);
    const Outcome o = vshell(dir, "check deep.toml");
    expect_bad_input(o, label);
    EXPECT_NE(o.err.find("deep.toml:1: nested deeper than 64 levels"), std::string::npos)
        << label << ": " << o.err.substr(0, 300);
    write(dir / "deep_cal.toml", text);
    expect_bad_input(vshell(dir, "calibrate deep_cal.toml"), label + " (calibration config)");
  }
}

TEST(CliFuzz, AbsurdSizesAndHangsAreBadInputWithTheReason) {
  const fs::path dir = scratch();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"blank.elements=1000000000", "grow with the square of the element count"},
      {"numerics.step_fraction=1e-4", "steps per contact event"},
      {"numerics.max_travel_increment_mm=1e-9", "more than the 1e+06 a run may take"},
      {"numerics.max_strain_increment=1e-9", "millions of steps"},
      {"numerics.max_iterations=100000000", "1000 iterations"},
      {"process.punch_travel_mm=1e6", "shorten process.punch_travel_mm"},
  };
  for (const auto& [set, reason] : cases) {
    for (const char* command : {"check", "run"}) {
      const auto start = std::chrono::steady_clock::now();
      const std::string output = std::string(command) == "run" ? " -o out_run" : "";
      const Outcome o =
          vshell(dir, std::string(command) + " '" + kScene + "' --set " + set + output);
      expect_bad_input(o, set);
      EXPECT_NE(o.err.find(reason), std::string::npos) << set << ": " << o.err;
      EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << set;
    }
  }
}

TEST(CliFuzz, MutatedScenesNeverCrash) {
  const fs::path dir = scratch();
  const std::string scene = read_all(kScene);
  std::mt19937 rng(16);
  const auto start = std::chrono::steady_clock::now();
  int cases = 0;
  // At least 20 cases whatever the machine's load (a count bounded by time alone made the test
  // fail on a loaded machine: fewer than 10 cases in 3 s), up to 200 within 3 s.
  while (cases < 20 ||
         (cases < 200 && std::chrono::steady_clock::now() - start < std::chrono::seconds(3))) {
    const std::string text = testing::mutate_toml(scene, rng);
    write(dir / "mutated.toml", text);
    const Outcome o = vshell(dir, "check mutated.toml");
    ++cases;
    EXPECT_FALSE(o.signalled) << text;
    EXPECT_TRUE(o.exit_code == 0 || o.exit_code == 2) << o.exit_code << ": " << o.err;
    if (o.exit_code == 2) {
      EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    }
  }
}

// A calibration whose forward run cannot even start: exit 3, the reason on stderr as one line,
// no NaN and no null in the report.
// A calibration of ex1's punch friction from the bundled synthetic thickness strains at 10 mm,
// followed by `tail` (optimizer and forward settings).
std::string friction_calibration(const std::string& tail) {
  const std::string data = std::string(VS_SOURCE_DIR) + "/data/calibration/";
  return "scene = '" + kScene +
         "'\n[[parameter]]\naddress = \"tool.punch.friction\"\n"
         "initial = 0.07\nlower = 0.0\nupper = 0.5\n"
         "[[data]]\nkind = \"thickness_strain\"\nfile = '" +
         data + "synthetic_ex1_clean_thick_10mm.csv'\ntravel_mm = 10\n" + tail;
}

TEST(CliFuzz, CalibrationWhoseRunsAllFailExitsThree) {
  const fs::path dir = scratch();
  write(dir / "cal.toml",
        friction_calibration("[forward.set]\n\"blank.elements\" = 24\n"
                             "\"process.punch_travel_mm\" = 10\n"
                             "\"numerics.max_iterations\" = 1\n\"numerics.max_cutbacks\" = 0\n"));
  const Outcome o = vshell(dir, "calibrate cal.toml -o report --quiet");
  EXPECT_FALSE(o.signalled);
  EXPECT_EQ(o.exit_code, 3) << o.err;
  EXPECT_EQ(o.err.rfind("error: calibration failed: the forward run at the initial parameters "
                        "fails: ",
                        0),
            0u)
      << o.err;
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  EXPECT_EQ(o.err.find("WARNING"), std::string::npos) << o.err;  // no glog lines
  const std::string json = read_all(dir / "report" / "calibration.json");
  EXPECT_EQ(json.find(": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"termination\": \"failed\""), std::string::npos);
  const std::string log = read_all(dir / "report" / "evaluations.csv");
  EXPECT_EQ(log.find("nan"), std::string::npos) << log;
}

TEST(CliFuzz, CalibrationInputErrorsExitTwo) {
  const fs::path dir = scratch();
  const std::string head = "scene = '" + kScene + "'\n[[parameter]]\n";
  write(dir / "load.csv",
        "\xEF\xBB\xBF# source: t\n# units: mm, N\npunch_travel_mm,punch_force_N\n1,100\n2,300\n");
  write(dir / "bad_units.csv",
        "# source: t\n# units: inch, lbf\npunch_travel_mm,punch_force_N\n1,100\n");
  const std::string data = "[[data]]\nkind = \"load_travel\"\nfile = \"load.csv\"\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "address = \"blank.elements\"\n" + data, "integer keys cannot be calibrated"},
      {head + "address = \"tool.punch.friction\"\ninitial = nan\n" + data,
       "key 'parameter.initial': must be a number, got nan"},
      {head + "address = \"tool.punch.friction\"\n" + data + data + "name = \"again\"\n",
       "would count twice"},
      {head + "address = \"tool.punch.friction\"\n[[data]]\nkind = \"load_travel\"\nfile = "
              "\"bad_units.csv\"\n",
       "unknown unit 'inch'"},
      {head + "address = \"tool.punch.friction\"\n" + data + "[optimizer]\nthreads = 1000\n",
       "key 'optimizer.threads': 1000 is out of range [1, 256]"},
      {head + "adress = \"tool.punch.friction\"\n" + data, "did you mean 'address'?"},
  };
  for (const auto& [config, reason] : cases) {
    write(dir / "cal.toml", config);
    const Outcome o = vshell(dir, "calibrate cal.toml -o report --quiet");
    expect_bad_input(o, reason);
    EXPECT_NE(o.err.find(reason), std::string::npos) << o.err;
  }
}

TEST(CliFuzz, CalibrateHelpPointsToTheReference) {
  const fs::path dir = scratch();
  const Outcome o = vshell(dir, "calibrate --help");
  EXPECT_EQ(o.exit_code, 0);
  EXPECT_NE(o.out.find("docs/calibration-reference.md"), std::string::npos) << o.out;
}

// The exit codes of `vshell run` (README "Using it"): 0 completed, with every --set applied to
// the run; 3 stopped (the reason on stderr, everything up to the last converged step written);
// 2 bad input, one line naming the key or file, for each class of bad input.
TEST(CliRun, CompletedRunExitsZeroAndAppliesEverySet) {
  const fs::path dir = scratch();
  const Outcome o = vshell(dir, "run '" + kScene +
                                    "' --set process.punch_travel_mm=2 --set blank.elements=12 "
                                    "--set 'process.output_travels_mm=[2.0]' -o out");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const std::string csv = read_all(dir / "out" / "load_travel.csv");
  ASSERT_FALSE(csv.empty());
  // The last row is the 2 mm travel of the override (the scene says 30 mm).
  auto field = [](const std::string& line, int k) {
    std::stringstream s(line);
    std::string f;
    for (int i = 0; i <= k; ++i) std::getline(s, f, ',');
    return f;
  };
  const std::string header = csv.substr(0, csv.find('\n'));
  int column = -1;
  for (int k = 0; k < 40; ++k) {
    if (field(header, k) == "punch_travel_mm") column = k;
  }
  ASSERT_GE(column, 0) << header;
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  EXPECT_NEAR(std::stod(field(last, column)), 2.0, 1e-9) << last;
  // 12 elements: the 2 mm profile has 12 rows after its comment and header lines.
  const std::string profile = read_all(dir / "out" / "strains_travel_002.00mm.csv");
  EXPECT_EQ(std::count(profile.begin(), profile.end(), '\n'), 14) << profile.substr(0, 200);
}

// A calibration's identified_<scene>.toml runs as it is, into run_identified_<scene> beside the
// report (not over the base scene's folder, and not into the report's staging folder).
TEST(CliRun, TheIdentifiedSceneOfACalibrationRunsBesideTheReport) {
  const fs::path dir = scratch();
  write(dir / "cal.toml", friction_calibration("[optimizer]\nmax_iterations = 2\n"
                                               "[forward.set]\n\"blank.elements\" = 24\n"
                                               "\"process.punch_travel_mm\" = 10\n"));
  const Outcome cal = vshell(dir, "calibrate cal.toml -o report --quiet");
  ASSERT_EQ(cal.exit_code, 0) << cal.err;
  const std::string identified = read_all(dir / "report" / "identified_scene.toml");
  EXPECT_NE(identified.find("directory = \"report/run_identified_scene\""), std::string::npos)
      << identified;
  const Outcome run = vshell(dir, "run report/identified_scene.toml");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(read_all(dir / "report" / "run_identified_scene" / "load_travel.csv").empty());
}

TEST(CliRun, StoppedRunExitsThreeWithTheReasonAndKeepsItsSteps) {
  // One iteration per step and no cut-backs: the first step cannot converge, the run stops.
  const fs::path dir = scratch();
  const Outcome o =
      vshell(dir, "run '" + kScene +
                      "' --set numerics.max_iterations=1 --set numerics.max_cutbacks=0 "
                      "--set blank.elements=12 -o out");
  EXPECT_EQ(o.exit_code, 3) << o.err.substr(0, 300);
  EXPECT_FALSE(o.signalled);
  // The summary names the termination and its reason.
  EXPECT_NE(o.out.find("termination       failed"), std::string::npos) << o.out.substr(0, 300);
  EXPECT_NE(o.out.find("did not converge"), std::string::npos) << o.out.substr(0, 300);
  EXPECT_FALSE(read_all(dir / "out" / "load_travel.csv").empty());
}

// `check` on a 3D scene names the blank and its mesh, the ring when it differs from divisions.
TEST(CliRun, CheckSummarisesA3dBlankAndItsRing) {
  const fs::path dir = scratch();
  const std::string cup =
      "check '" + std::string(VS_SOURCE_DIR) + "/data/scenes/esaform_cup_3d_hill48_tuat.toml'";
  const Outcome plain = vshell(dir, cup);
  EXPECT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("3D shell, circular blank, radius 53.75 mm, thickness 1 mm, quarter "
                           "model, 6 divisions; tools: punch, die, holder"),
            std::string::npos)
      << plain.out;
  const Outcome ring = vshell(dir, cup + " --set blank.radial_divisions=10");
  EXPECT_EQ(ring.exit_code, 0) << ring.err;
  EXPECT_NE(ring.out.find("6 divisions (10 across the ring);"), std::string::npos) << ring.out;
}

TEST(CliRun, EachClassOfBadInputExitsTwoWithOneLineNamingIt) {
  const fs::path dir = scratch();
  const std::string run = "run '" + kScene + "' -o out ";
  struct Case {
    std::string args, named;
  };
  for (const Case& c : std::vector<Case>{
           {run + "--set blank.elemnts=12", "blank.elemnts"},      // unknown key
           {run + "--set blank.elements=many", "blank.elements"},  // wrong type
           {run + "--set blank.elements=-3", "blank.elements"},    // out of range
           {run + "--set blank.elements", "blank.elements"},       // --set without a value
           {"run '" + (dir / "no_such_scene.toml").string() + "'", "no_such_scene.toml"},
           {"check '" + (dir / "no_such_scene.toml").string() + "'", "no_such_scene.toml"}}) {
    const Outcome o = vshell(dir, c.args);
    expect_bad_input(o, c.args);
    EXPECT_NE(o.err.find(c.named), std::string::npos) << c.args << ": " << o.err;
  }
  // A scene with a syntax error: file and line named.
  write(dir / "broken.toml", "[blank]\nthickness_mm = = 1\n");
  const Outcome b = vshell(dir, "check broken.toml");
  expect_bad_input(b, "broken.toml");
  EXPECT_NE(b.err.find("broken.toml:2"), std::string::npos) << b.err;
}

}  // namespace
}  // namespace vs

#endif  // VS_VSHELL_PATH
