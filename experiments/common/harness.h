// Experiment harness: build a bundled scene with overrides in memory and run it in-process with a
// wall-clock measurement and an optional time budget. Header-only so that the quick CTest variant
// (tests/system/experiments_quick_test.cc) shares it with the experiment drivers.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "run/simulate.h"
#include "scene/load_scene.h"
#include "scene/scene_table.h"

namespace vsx {

// One override as typed on the command line: `vshell run SCENE --set address=value`.
struct Override {
  std::string address;
  std::string value;
};
using Overrides = std::vector<Override>;

// "a=1 b=2" for tables and messages; "(bundled)" when empty.
inline std::string describe(const Overrides& ov) {
  if (ov.empty()) return "(bundled)";
  std::string s;
  for (const Override& o : ov) s += (s.empty() ? "" : " ") + o.address + "=" + o.value;
  return s;
}

// The same overrides as `vshell run` arguments.
inline std::string cli_args(const Overrides& ov) {
  std::string s;
  for (const Override& o : ov) s += " --set " + o.address + "=" + o.value;
  return s;
}

inline std::string scenes_dir(const std::string& source_dir) { return source_dir + "/data/scenes"; }

inline std::string scene_path(const std::string& source_dir, const std::string& name) {
  return scenes_dir(source_dir) + "/" + name + ".toml";
}

// Loads `path`, switches off the per-step history (outputs only need the requested profiles) and
// applies the overrides in order. Throws vs::InputError on a bad override.
inline vs::Scene make_scene(const std::string& path, const Overrides& ov) {
  toml::table table = vs::read_scene_table(path);
  vs::set_scene_value_from_text(table, "output.history", "false");
  vs::set_scene_value_from_text(table, "output.plots", "false");
  for (const Override& o : ov) vs::set_scene_value_from_text(table, o.address, o.value);
  const std::string dir = path.substr(0, path.find_last_of('/'));
  return vs::scene_from_table(table, path, dir);
}

struct TimedRun {
  vs::RunResult result;
  double wall_s = 0.0;   // median over the repeats
  double cpu_s = 0.0;    // thread CPU time, median over the repeats (not inflated by other load)
  bool aborted = false;  // stopped by the experiment's time budget (not a solver verdict)
};

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

inline double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Runs once, stopping the run from the step callback when `budget_s` is exceeded (the steps done
// so far are kept). An infinite budget runs without any callback.
inline TimedRun run_once(const vs::Scene& scene, double budget_s) {
  struct BudgetExceeded {};
  TimedRun out;
  std::vector<vs::StepRecord> seen;
  vs::RunOptions options;
  const auto t0 = Clock::now();
  const double c0 = thread_cpu_s();
  if (std::isfinite(budget_s)) {
    options.on_step = [&](const vs::StepRecord& rec) {
      seen.push_back(rec);
      if (seconds_since(t0) > budget_s) throw BudgetExceeded{};
    };
  }
  try {
    out.result = vs::simulate(scene, options);
  } catch (const BudgetExceeded&) {
    out.aborted = true;
    out.result.steps = std::move(seen);
    out.result.termination = vs::Termination::kFailed;
    out.result.message = "aborted by the experiment's time budget (not a solver verdict)";
  }
  out.wall_s = seconds_since(t0);
  out.cpu_s = thread_cpu_s() - c0;
  return out;
}

// Runs `repeats` times (single thread, sequential) and keeps the last result with the median
// wall time; repeats stop early once `min_total_s` of measurement has been spent.
inline TimedRun run_timed(const vs::Scene& scene, int repeats, double budget_s,
                          double min_total_s = 0.0) {
  std::vector<double> times, cpu;
  TimedRun last;
  double spent = 0.0;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    last = run_once(scene, budget_s);
    times.push_back(last.wall_s);
    cpu.push_back(last.cpu_s);
    spent += last.wall_s;
    if (last.aborted || (min_total_s > 0.0 && spent >= min_total_s)) break;
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu.begin(), cpu.end());
  last.wall_s = times[times.size() / 2];
  last.cpu_s = cpu[cpu.size() / 2];
  return last;
}

}  // namespace vsx
