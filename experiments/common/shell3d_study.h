// Work-precision study of the 3D forming solver (experiments/05_shell3d), shared with its quick
// CTest variant (tests/system/experiments_quick_test.cc): the quarter circular blank of paper
// example 4a at several mesh sizes and element rules against the axisymmetric solver on the same
// data (its "twin"), which is the reference; the reference's own mesh noise is measured by a
// second, finer axisymmetric run. Header-only.
#pragma once

#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/axisym_comparison.h"
#include "harness.h"
#include "model/forming_fields.h"
#include "run/simulate.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"
#include "table.h"

namespace vsx {

// One 3D discretisation: element rule ("mitc9" or "paper_selective") and mesh divisions (the
// quarter blank has 3 n^2 nine-node elements).
struct Shell3dCase {
  std::string rule = "mitc9";
  int divisions = 4;
};

struct Shell3dStudy {
  std::string scene_path;      // a circular shell3d blank (ex4a)
  std::string friction = "0";  // punch friction: a number or "sticking"
  double travel_mm = 6.0;
  std::vector<double> outputs_mm;  // compared travels; the last one is the travel
  int axisym_elements = 30;        // the reference
  int axisym_check_elements = 40;  // finer axisymmetric run: the reference's own mesh noise
  std::vector<Shell3dCase> cases;  // run in this order (increasing cost within a rule)
};

// The study of the report (full) and its reduced form (run_all.sh --quick). Example 4a with
// Coulomb friction 0.2 to 6 mm: past the bending-dominated start, with a contact front that has
// moved over several elements, at a cost of seconds to minutes per run.
inline Shell3dStudy shell3d_study(const std::string& source_dir, bool quick) {
  Shell3dStudy s;
  s.scene_path = source_dir + "/data/scenes/ex4a_quarter_disc_sticking.toml";
  s.friction = "0.2";
  if (quick) {
    s.travel_mm = 2.0;
    s.outputs_mm = {1.0, 2.0};
    s.cases = {{"mitc9", 2}, {"mitc9", 4}, {"paper_selective", 2}};
  } else {
    s.travel_mm = 6.0;
    s.outputs_mm = {4.0, 5.0, 6.0};
    s.cases = {
        {"mitc9", 2}, {"mitc9", 4}, {"mitc9", 8}, {"paper_selective", 2}, {"paper_selective", 4}};
  }
  return s;
}

// The scene of the study (travel, outputs, punch friction) before the discretisation choice.
inline vs::Scene shell3d_base_scene(const Shell3dStudy& study) {
  vs::Scene base = vs::load_scene(study.scene_path);
  base.process.punch_travel_mm = study.travel_mm;
  base.process.output_travels_mm = study.outputs_mm;
  for (auto& t : base.tools) {
    t.friction = study.friction == "sticking" ? std::numeric_limits<double>::infinity()
                                              : std::stod(study.friction);
  }
  return base;
}

inline vs::Scene shell3d_case_scene(const vs::Scene& base, const Shell3dCase& c) {
  vs::Scene scene = base;
  scene.blank.divisions = c.divisions;
  scene.numerics.element_rule = c.rule == "paper_selective" ? vs::ShellElementRule::kPaperSelective
                                                            : vs::ShellElementRule::kMitc9;
  return scene;
}

// Process CPU time (all threads: the 3D assembly is OpenMP-parallel).
inline double process_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Deviations from the reference, summarised over the compared travels.
struct Deviations {
  double force_at_travel = std::nan("");       // (F - F_ref) / F_ref at the last travel
  double mean_force_at_travel = std::nan("");  // the same for the mean over the last mm
  double max_abs_force = std::nan("");         // largest |force deviation| over the travels
  double max_abs_mean_force = std::nan("");    // largest |mean-force deviation| over the travels
  double max_eps_thickness = std::nan("");     // largest |d eps_t| over the travels and lines
  int travels = 0;                             // compared travels
};

inline Deviations summarise(const std::vector<vs::shell3d::TravelComparison>& cmp) {
  Deviations d;
  d.travels = static_cast<int>(cmp.size());
  if (cmp.empty()) return d;
  d.force_at_travel = cmp.back().force_deviation;
  d.mean_force_at_travel = cmp.back().mean_force_deviation;
  d.max_abs_force = d.max_abs_mean_force = d.max_eps_thickness = 0.0;
  for (const auto& c : cmp) {
    d.max_abs_force = std::max(d.max_abs_force, std::abs(c.force_deviation));
    d.max_abs_mean_force = std::max(d.max_abs_mean_force, std::abs(c.mean_force_deviation));
    d.max_eps_thickness = std::max(d.max_eps_thickness, c.max_eps_thickness_deviation());
  }
  return d;
}

struct Shell3dRow {
  Shell3dCase c;
  int elements = 0, dofs = 0;
  bool completed = false;
  std::string message;
  double wall_s = 0.0, cpu_s = 0.0;
  int steps = 0, iterations = 0, factorisations = 0;
  std::vector<vs::shell3d::TravelComparison> cmp;
  Deviations dev;
};

// Runs one 3D case and compares it with the axisymmetric reference at the output travels.
inline Shell3dRow run_shell3d_case(const vs::Scene& base, const Shell3dCase& c,
                                   const vs::RunResult& reference) {
  const vs::Scene scene = shell3d_case_scene(base, c);
  Shell3dRow row;
  row.c = c;
  const auto t0 = Clock::now();
  const double c0 = process_cpu_s();
  const vs::RunResult r = vs::shell3d::simulate_shell3d(scene);
  row.wall_s = seconds_since(t0);
  row.cpu_s = process_cpu_s() - c0;
  row.elements = r.shell->mesh.num_elements();
  row.dofs = r.dofs;
  row.completed = r.completed();
  row.message = r.message;
  row.steps = static_cast<int>(r.steps.size());
  row.iterations = r.total_iterations;
  row.factorisations = r.timings.factorisations;
  row.cmp = vs::shell3d::compare_with_axisymmetric(scene, r, reference);
  row.dev = summarise(row.cmp);
  return row;
}

struct AxisymRun {
  int elements = 0;
  vs::RunResult result;
  double wall_s = 0.0, cpu_s = 0.0;
};

inline AxisymRun run_axisym_twin(const vs::Scene& base, int elements) {
  AxisymRun a;
  a.elements = elements;
  const vs::Scene scene = vs::shell3d::axisymmetric_twin(base, elements);
  const auto t0 = Clock::now();
  const double c0 = process_cpu_s();
  a.result = vs::simulate(scene);
  a.wall_s = seconds_since(t0);
  a.cpu_s = process_cpu_s() - c0;
  return a;
}

// The finer axisymmetric run against the reference, in the same measures as a 3D run (force and
// mean force over the last `window_mm` at each travel; |d eps_t| at the check run's element
// midpoints, the reference interpolated at their initial radius): how far the reference itself
// is from a converged answer.
inline std::vector<vs::shell3d::TravelComparison> compare_axisym(const std::vector<double>& travels,
                                                                 const vs::RunResult& check,
                                                                 const vs::RunResult& reference,
                                                                 double window_mm = 1.0) {
  std::vector<vs::shell3d::TravelComparison> out;
  auto profile_at = [](const vs::RunResult& r, double travel) -> const vs::Profile* {
    for (const vs::Profile& p : r.profiles)
      if (std::abs(p.punch_travel_mm - travel) <= 1e-9 * (1.0 + travel)) return &p;
    return nullptr;
  };
  auto force_at_step = [](const vs::RunResult& r, double travel) {
    for (const vs::StepRecord& s : r.steps)
      if (std::abs(s.punch_travel_mm - travel) <= 1e-9 * (1.0 + travel)) return s.punch_force_N;
    return std::nan("");
  };
  for (double travel : travels) {
    const vs::Profile* pc = profile_at(check, travel);
    const vs::Profile* pr = profile_at(reference, travel);
    if (!pc || !pr) continue;
    vs::shell3d::TravelComparison c;
    c.punch_travel_mm = travel;
    c.force_3d_N = force_at_step(check, travel);
    c.force_axisym_N = force_at_step(reference, travel);
    c.force_deviation = (c.force_3d_N - c.force_axisym_N) / c.force_axisym_N;
    c.mean_force_3d_N = vs::shell3d::mean_force(check.steps, travel - window_mm, travel);
    c.mean_force_axisym_N = vs::shell3d::mean_force(reference.steps, travel - window_mm, travel);
    c.mean_force_deviation = (c.mean_force_3d_N - c.mean_force_axisym_N) / c.mean_force_axisym_N;
    double dev = 0.0;
    for (std::size_t i = 0; i < pc->r0_mm.size(); ++i) {
      const double ref = vs::shell3d::interpolate(pr->r0_mm, pr->eps_thickness, pc->r0_mm[i]);
      dev = std::max(dev, std::abs(pc->eps_thickness[i] - ref));
    }
    c.eps_thickness_deviation_y0 = c.eps_thickness_deviation_x0 =
        c.eps_thickness_deviation_diagonal = dev;
    out.push_back(c);
  }
  return out;
}

// The axisymmetric runs as rows of the study table: the reference ("axisymmetric_reference",
// compared with itself) and the finer check run ("axisymmetric", compared with the reference);
// `divisions` holds the element count, dofs are not recorded.
inline Shell3dRow axisym_row(const std::string& rule, const AxisymRun& run,
                             const std::vector<vs::shell3d::TravelComparison>& cmp) {
  Shell3dRow row;
  row.c = {rule, run.elements};
  row.elements = run.elements;
  row.completed = run.result.completed();
  row.message = run.result.message;
  row.wall_s = run.wall_s;
  row.cpu_s = run.cpu_s;
  row.steps = static_cast<int>(run.result.steps.size());
  row.iterations = run.result.total_iterations;
  row.cmp = cmp;
  row.dev = summarise(cmp);
  return row;
}

// What the summary needs besides the rows (also stored in every CSV row).
struct Shell3dMeta {
  std::string scene;  // file name
  std::string friction;
  std::string load_average;  // 1-minute load average when the study started
};

inline const char* kShell3dCsvHeader =
    "scene,friction,load_average,rule,divisions,elements,dofs,completed,wall_s,cpu_s,steps,"
    "iterations,factorisations,punch_travel_mm,force_N,force_reference_N,force_deviation,"
    "mean_force_N,mean_force_reference_N,mean_force_deviation,eps_thickness_dev_y0,"
    "eps_thickness_dev_x0,eps_thickness_dev_diagonal,message\n";

// One line per row and compared travel (one line with empty travel fields for a row without any).
inline std::string shell3d_csv_lines(const Shell3dMeta& meta, const Shell3dRow& r) {
  std::string message = r.message;
  for (char& ch : message)
    if (ch == ',' || ch == '"' || ch == '\n') ch = ';';
  const std::string head =
      fmt::format("{},{},{},{},{},{},{},{},{:.4g},{:.4g},{},{},{}", meta.scene, meta.friction,
                  meta.load_average, r.c.rule, r.c.divisions, r.elements, r.dofs,
                  r.completed ? 1 : 0, r.wall_s, r.cpu_s, r.steps, r.iterations, r.factorisations);
  if (r.cmp.empty()) return head + ",,,,,,,,,,," + message + "\n";
  std::string out;
  for (const auto& c : r.cmp) {
    out += head +
           fmt::format(",{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},",
                       c.punch_travel_mm, c.force_3d_N, c.force_axisym_N, c.force_deviation,
                       c.mean_force_3d_N, c.mean_force_axisym_N, c.mean_force_deviation,
                       c.eps_thickness_deviation_y0, c.eps_thickness_deviation_x0,
                       c.eps_thickness_deviation_diagonal) +
           message + "\n";
  }
  return out;
}

// Reads what shell3d_csv_lines wrote (rows in file order). Returns false if the file is missing
// or not in this format.
inline bool read_shell3d_csv(const std::string& path, Shell3dMeta* meta,
                             std::vector<Shell3dRow>* rows) {
  std::ifstream f(path);
  std::string line;
  if (!f || !std::getline(f, line) || line + "\n" != kShell3dCsvHeader) return false;
  rows->clear();
  while (std::getline(f, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cell;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cell.push_back(c);
    if (cell.size() < 23) return false;
    if (cell.size() == 23) cell.push_back("");
    auto num = [](const std::string& t) { return t.empty() ? std::nan("") : std::stod(t); };
    meta->scene = cell[0];
    meta->friction = cell[1];
    meta->load_average = cell[2];
    const std::string rule = cell[3];
    const int divisions = std::stoi(cell[4]);
    if (rows->empty() || rows->back().c.rule != rule || rows->back().c.divisions != divisions) {
      Shell3dRow r;
      r.c = {rule, divisions};
      r.elements = std::stoi(cell[5]);
      r.dofs = std::stoi(cell[6]);
      r.completed = cell[7] == "1";
      r.wall_s = num(cell[8]);
      r.cpu_s = num(cell[9]);
      r.steps = std::stoi(cell[10]);
      r.iterations = std::stoi(cell[11]);
      r.factorisations = std::stoi(cell[12]);
      r.message = cell[23];
      rows->push_back(r);
    }
    if (!cell[13].empty()) {
      vs::shell3d::TravelComparison c;
      c.punch_travel_mm = num(cell[13]);
      c.force_3d_N = num(cell[14]);
      c.force_axisym_N = num(cell[15]);
      c.force_deviation = num(cell[16]);
      c.mean_force_3d_N = num(cell[17]);
      c.mean_force_axisym_N = num(cell[18]);
      c.mean_force_deviation = num(cell[19]);
      c.eps_thickness_deviation_y0 = num(cell[20]);
      c.eps_thickness_deviation_x0 = num(cell[21]);
      c.eps_thickness_deviation_diagonal = num(cell[22]);
      rows->back().cmp.push_back(c);
    }
  }
  for (Shell3dRow& r : *rows) r.dev = summarise(r.cmp);
  return true;
}

inline std::string signed_pct(double v) {
  return v == v ? fmt::format("{:+.2f}", 100.0 * v) : std::string("-");
}
inline std::string abs_pct(double v) {
  return v == v ? fmt::format("{:.2f}", 100.0 * v) : std::string("-");
}
inline std::string seconds3(double v) { return v == v ? fmt::format("{:.3g}", v) : "-"; }

// The study's summary.md from its rows (as read back from the CSV: the report regenerates it
// from the committed CSV): the table and "what it shows", every sentence computed from the rows.
inline std::string shell3d_summary(const Shell3dMeta& meta, const std::vector<Shell3dRow>& rows) {
  const Shell3dRow* ref = nullptr;
  const Shell3dRow* check = nullptr;
  std::vector<const Shell3dRow*> shell;
  for (const Shell3dRow& r : rows) {
    if (r.c.rule == "axisymmetric_reference") {
      ref = &r;
    } else if (r.c.rule == "axisymmetric") {
      check = &r;
    } else {
      shell.push_back(&r);
    }
  }
  if (!ref || !check) return "_The 3D study's results lack the axisymmetric reference rows._\n";
  std::string travels;
  for (const auto& c : ref->cmp) travels += (travels.empty() ? "" : ", ") + g4(c.punch_travel_mm);
  const double travel = ref->cmp.empty() ? std::nan("") : ref->cmp.back().punch_travel_mm;
  std::string md = fmt::format(
      "Quarter circular blank of example 4a (`data/scenes/{}`), punch friction {}, to {} mm of "
      "punch travel, compared at {} mm. Reference: the axisymmetric solver on the same data with "
      "{} elements; its own mesh noise is the first row ({} elements against the reference). "
      "Deviations are (run - reference) / reference of the punch force at the last travel and of "
      "the mean force over the last millimetre before it (work / travel: filters the "
      "contact-event spikes both solvers have), the largest of each over all compared travels, "
      "and the largest |thickness-strain deviation| over the compared travels and the nodes of "
      "the lines y = 0, x = 0, x = y. Wall and process CPU time of one run, one thread, load "
      "average {} when the study started (the machine is shared: the sentences below use the "
      "CPU time, which the other load does not inflate).\n\n",
      meta.scene, meta.friction, g4(travel), travels, ref->elements, check->elements,
      meta.load_average);
  md +=
      "| rule | divisions | elements / dofs | wall s | CPU s | steps / iterations | dF at travel % "
      "| dF mean last mm % | max abs dF % | max abs dF mean % | max abs d eps_t |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  md += fmt::format(
      "| axisymmetric, reference noise | {} vs {} elements | - | {} | {} | {} / {} | {} | {} | "
      "{} | {} | {:.4f} |\n",
      check->elements, ref->elements, seconds3(check->wall_s), seconds3(check->cpu_s), check->steps,
      check->iterations, signed_pct(check->dev.force_at_travel),
      signed_pct(check->dev.mean_force_at_travel), abs_pct(check->dev.max_abs_force),
      abs_pct(check->dev.max_abs_mean_force), check->dev.max_eps_thickness);
  md += fmt::format(
      "| axisymmetric, reference | {} elements | - | {} | {} | {} / {} | 0 | 0 | 0 | "
      "0 | 0 |\n",
      ref->elements, seconds3(ref->wall_s), seconds3(ref->cpu_s), ref->steps, ref->iterations);
  for (const Shell3dRow* r : shell) {
    md += fmt::format("| {} | {} | {} / {} | {} | {} | {} / {} | {} | {} | {} | {} | {} |\n",
                      r->c.rule, r->c.divisions, r->elements, r->dofs, seconds3(r->wall_s),
                      seconds3(r->cpu_s), r->steps, r->iterations,
                      signed_pct(r->dev.force_at_travel), signed_pct(r->dev.mean_force_at_travel),
                      abs_pct(r->dev.max_abs_force), abs_pct(r->dev.max_abs_mean_force),
                      r->dev.travels ? fmt::format("{:.4f}", r->dev.max_eps_thickness)
                                     : "not completed: " + r->message);
  }

  md += "\n![3D work-precision](05_shell3d/results/shell3d_work_precision.svg)\n";
  // What it shows, from the numbers above.
  md += "\n**What it shows** (sentences generated from the table):\n\n";
  const double noise = check->dev.max_abs_mean_force;
  md += fmt::format(
      "- Reference noise: {} instead of {} axisymmetric elements moves the mean force over the "
      "last mm by up to {:.2f} % (at the compared travels) and the thickness strain by up to "
      "{:.4f}; 3D deviations of that size are not resolved by this reference.\n",
      check->elements, ref->elements, 100.0 * noise, check->dev.max_eps_thickness);
  std::vector<std::string> rules;
  for (const Shell3dRow* r : shell)
    if (std::find(rules.begin(), rules.end(), r->c.rule) == rules.end()) rules.push_back(r->c.rule);
  for (const std::string& rule : rules) {
    std::vector<const Shell3dRow*> rr;
    for (const Shell3dRow* r : shell)
      if (r->c.rule == rule && r->completed && r->dev.travels > 0) rr.push_back(r);
    if (rr.size() < 2) continue;
    std::sort(rr.begin(), rr.end(), [](const Shell3dRow* a, const Shell3dRow* b) {
      return a->c.divisions < b->c.divisions;
    });
    bool falls_force = true, falls_eps = true;
    for (std::size_t i = 1; i < rr.size(); ++i) {
      falls_force =
          falls_force && rr[i]->dev.max_abs_mean_force < rr[i - 1]->dev.max_abs_mean_force;
      falls_eps = falls_eps && rr[i]->dev.max_eps_thickness < rr[i - 1]->dev.max_eps_thickness;
    }
    std::string points;
    for (const Shell3dRow* r : rr) {
      points += fmt::format("{}n = {}: {:.2f} % / {:.4f} in {} s", points.empty() ? "" : "; ",
                            r->c.divisions, 100.0 * r->dev.max_abs_mean_force,
                            r->dev.max_eps_thickness, seconds3(r->cpu_s));
    }
    const Shell3dRow& first = *rr.front();
    const Shell3dRow& last = *rr.back();
    const char* every = rr.size() > 2 ? " with every refinement" : "";
    md += fmt::format(
        "- {}, max |mean-force deviation| / max |d eps_t| against CPU time: {}. From n = {} to "
        "n = {} the force deviation {}{} and the thickness-strain deviation {}{}; the CPU time "
        "grows {:.1f}x for {:.0f}x the elements.",
        rule, points, first.c.divisions, last.c.divisions, falls_force ? "falls" : "does not fall",
        every, falls_eps ? "falls" : "does not fall", every,
        last.cpu_s / std::max(first.cpu_s, 1e-9),
        static_cast<double>(last.elements) / std::max(first.elements, 1));
    md += fmt::format(
        " At n = {} the force deviation is {} the reference's own mesh noise and the "
        "thickness-strain deviation is {} it.\n",
        last.c.divisions, last.dev.max_abs_mean_force <= noise ? "within" : "larger than",
        last.dev.max_eps_thickness <= check->dev.max_eps_thickness ? "within" : "larger than");
  }
  // Integration rule at equal mesh.
  for (const Shell3dRow* a : shell) {
    if (a->c.rule != "paper_selective" || !a->completed || a->dev.travels == 0) continue;
    for (const Shell3dRow* b : shell) {
      if (b->c.rule != "mitc9" || b->c.divisions != a->c.divisions || !b->completed ||
          b->dev.travels == 0)
        continue;
      const double ratio = a->cmp.back().mean_force_3d_N / b->cmp.back().mean_force_3d_N - 1.0;
      md += fmt::format(
          "- Element rule at n = {}: at {} mm the paper's selective rule gives a mean force "
          "{:.2f} % {} the MITC9 one (deviation {} % against {} %); max |d eps_t| {:.4f} against "
          "{:.4f}; {:.2f}x the CPU time.\n",
          a->c.divisions, g4(a->cmp.back().punch_travel_mm), 100.0 * std::abs(ratio),
          ratio >= 0.0 ? "above" : "below", signed_pct(a->dev.mean_force_at_travel),
          signed_pct(b->dev.mean_force_at_travel), a->dev.max_eps_thickness,
          b->dev.max_eps_thickness, a->cpu_s / std::max(b->cpu_s, 1e-9));
    }
  }
  // Runs meeting the accuracy goal at every compared travel, cheapest first.
  std::vector<const Shell3dRow*> meeting;
  for (const Shell3dRow* r : shell) {
    if (r->completed && r->dev.travels > 0 && r->dev.max_abs_mean_force <= 0.02 &&
        r->dev.max_eps_thickness <= 0.01)
      meeting.push_back(r);
  }
  std::sort(meeting.begin(), meeting.end(),
            [](const Shell3dRow* a, const Shell3dRow* b) { return a->cpu_s < b->cpu_s; });
  if (!meeting.empty()) {
    std::string list;
    for (const Shell3dRow* r : meeting)
      list += fmt::format("{}{} n = {} ({} s CPU)", list.empty() ? "" : ", ", r->c.rule,
                          r->c.divisions, seconds3(r->cpu_s));
    md += fmt::format(
        "- Issue 3 accuracy goal (force within 2 %, here the mean over the last mm at every "
        "compared travel, and thickness strain within 0.01) is met by {} of {} 3D runs: {}. The "
        "cheapest takes {} s CPU ({} the 10 s goal; the axisymmetric reference takes {} s).\n",
        meeting.size(), shell.size(), list, seconds3(meeting.front()->cpu_s),
        meeting.front()->cpu_s <= 10.0 ? "within" : "above", seconds3(ref->cpu_s));
    // A coarse run that meets the goal while a finer run of the same rule does not.
    const Shell3dRow& best = *meeting.front();
    for (const Shell3dRow* r : shell) {
      if (r->c.rule == best.c.rule && r->c.divisions > best.c.divisions && r->completed &&
          r->dev.travels > 0 && r->dev.max_abs_mean_force > best.dev.max_abs_mean_force) {
        md += fmt::format(
            "  The finer {} n = {} deviates more ({:.2f} % against {:.2f} %), so n = {} meets the "
            "force goal by a cancellation of errors, not by resolution.\n",
            r->c.rule, r->c.divisions, 100.0 * r->dev.max_abs_mean_force,
            100.0 * best.dev.max_abs_mean_force, best.c.divisions);
        break;
      }
    }
  } else {
    md +=
        "- Issue 3 accuracy goal (mean force within 2 % at every compared travel and thickness "
        "strain within 0.01): no 3D run of the table meets it.\n";
  }
  int failed = 0;
  for (const Shell3dRow* r : shell) failed += r->completed ? 0 : 1;
  if (failed > 0) md += fmt::format("- {} 3D run(s) did not complete (see the table).\n", failed);
  return md;
}

// make_report's entry: the summary regenerated from the study's CSV ("" if it cannot be read).
inline std::string shell3d_summary_from_csv(const std::string& path) {
  Shell3dMeta meta;
  std::vector<Shell3dRow> rows;
  if (!read_shell3d_csv(path, &meta, &rows)) return "";
  return shell3d_summary(meta, rows);
}

}  // namespace vsx
