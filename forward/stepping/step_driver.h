// The one step driver of both geometries (paper section 3 steps 1-7, section 4.6): solve the
// velocity field in the current configuration, choose the time step from the next contact event
// and the increment caps, update geometry, thickness and hardening, and repeat to the total punch
// travel. Steps end on a fixed travel grid (multiples of the travel cap) and at the output
// travels, and contact events split grid intervals: the step sequence then moves continuously
// with the material and friction parameters, which keeps outputs smooth for calibration. The
// geometry update is implicit (the default; take_implicit_step), Heun (explicit trapezoidal) or
// Euler. A failed step is cut back (redone
// with half the step) and retried; a run that cannot go on, or whose step keeps collapsing, or
// that stalls at one instant, stops with the reason and everything so far.
//
// The geometry is a Stepper behind this template (stepping/axisym_driver.cc,
// stepping/shell3d_driver.cc): it owns its model, state and contact search and provides
//   using State (with double time_s), using Solved (with State state, double punch_force,
//     max_rate, std::vector<std::vector<double>> point_rates, NewtonSummary summary);
//   int num_nodes(); int num_unknowns(); bool contact_eligible(int node);
//   bool in_contact(const State&, int node);
//   double shortest_element_mm();
//   void set_grid_increment(double mm);                       (once, before the run)
//   State initial_state(); void place_tools(State&);
//   void maintain_contacts(State&, const ContactHolds&);     (attach, re-attach, hole filling)
//   bool solve(Solved*, double dt_predicted, const std::vector<double>* hardening_from,
//              ContactHolds&, std::string* why);             (contact rounds with releases)
//   double contact_time(const State&, int node, double horizon);   (earliest tool, eq. 53)
//   void move(const Solved& from, double dt, State* to);     (x, directors, tools, eps_bar, t)
//   bool update_thickness(State&, std::string* why);
//   Solved blend(const Solved& a, const Solved& b, double w);  (a's state, rates (1-w) a + w b)
//   void couple_geometry(const Solved* ref, double scale_s);  (implicit: coupling, null = off)
//   void set_tolerance(double tolerance);                     (Newton tolerance of solve())
//   void attach_touching(const State& predicted, State* corrected, const ContactHolds&);
//   void start_from(const Solved& predicted, Solved* corrected);   (start velocity, duals)
//   const std::vector<double>& eps_bar(const State&);         (the predictor hardens from it)
//   StepRecord record(const Solved&);                         (geometry fields of a step)
//   void output(const Solved&, double travel, RunResult*);    (a profile / stage)
//   void history(const Solved&, double travel, RunResult*);   (every step, if asked)
//   void observe(const Solved&);                              (after every accepted state)
//   void start(RunResult*); void finish(RunResult*);          (built, warnings, timings)
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "contact/contact_holds.h"
#include "run/run_options.h"
#include "run/run_result.h"
#include "scene/scene.h"
#include "stepping/step_driver_options.h"
#include "stepping/travel_grid.h"

namespace vs {

// (1 - w) a + w b of two sets of point rates (per element and point), for the steppers'
// blend(): w = 1/2 is Heun's mean, w = 1 the implicit update's end-of-step rates.
inline std::vector<std::vector<double>> blend_point_rates(const std::vector<std::vector<double>>& a,
                                                          const std::vector<std::vector<double>>& b,
                                                          double w) {
  std::vector<std::vector<double>> mid = a;
  for (std::size_t e = 0; e < mid.size(); ++e) {
    for (std::size_t k = 0; k < mid[e].size(); ++k) mid[e][k] = (1.0 - w) * a[e][k] + w * b[e][k];
  }
  return mid;
}

template <class Stepper>
class StepDriver {
 public:
  using State = typename Stepper::State;
  using Solved = typename Stepper::Solved;

  StepDriver(const Scene& scene, const RunOptions& run_options, const StepDriverOptions& options,
             Stepper& stepper)
      : scene_(scene), run_options_(run_options), options_(options), g_(stepper) {
    grid_increment_mm_ =
        std::min(scene.numerics.max_travel_increment_mm,
                 scene.numerics.max_travel_increment_per_length * g_.shortest_element_mm());
    targets_ = travel_grid(scene.process.punch_travel_mm, grid_increment_mm_,
                           scene.process.output_travels_mm, scene.numerics.start_refinement);
    g_.set_grid_increment(grid_increment_mm_);
  }

  RunResult run();

  // Grid spacing of the step ends: the smaller of the absolute cap and the cap relative to the
  // shortest initial element (the stability limit of the explicit geometry update).
  double grid_increment_mm() const { return grid_increment_mm_; }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }
  double travel(const State& s) const { return s.time_s * scene_.process.punch_speed_mm_per_s; }
  double choose_dt(const Solved& from, double cap_factor);
  bool advance(const Solved& from, double dt, State* to, std::string* why);
  bool take_step(const Solved& from, double dt, Solved* to, std::string* why);
  bool take_implicit_step(const Solved& from, double dt, Solved* to, std::string* why);
  void finish(double total_s, RunResult* result);

  const Scene& scene_;
  RunOptions run_options_;
  StepDriverOptions options_;
  Stepper& g_;
  std::vector<double> targets_;
  double grid_increment_mm_ = 0.0;
  ContactHolds holds_;
  double contact_s_ = 0.0;
  std::vector<int> implicit_iterations_;  // RunResult::implicit_solve_iterations
};

template <class Stepper>
double StepDriver<Stepper>::choose_dt(const Solved& from, double cap_factor) {
  const auto t0 = Clock::now();
  // To the next grid point in equal strain-capped sub-steps; a cut-back divides further.
  const double cap =
      cap_factor * step_to_next_target(targets_, travel(from.state),
                                       scene_.process.punch_speed_mm_per_s,
                                       scene_.numerics.max_strain_increment, from.max_rate);
  // Next contact event (paper eq. 53, any tool, any free node), looked for a little beyond the
  // cap so that the step fraction can approach it gradually.
  if (scene_.numerics.time_integration == TimeIntegration::kImplicit &&
      !scene_.numerics.contact_events)
    return cap;
  const double frac = scene_.numerics.step_fraction;
  const double horizon = cap / frac;
  double dt_event = std::numeric_limits<double>::infinity();
  const State& s = from.state;
  const double T = travel(s);
  for (int i = 0; i < g_.num_nodes(); ++i) {
    if (!g_.contact_eligible(i) || g_.in_contact(s, i) || !holds_.may_touch(i, T)) continue;
    dt_event = std::min(dt_event, g_.contact_time(s, i, horizon));
  }
  contact_s_ += seconds_since(t0);
  if (dt_event <= cap) return std::max(dt_event, options_.min_event_fraction * cap);
  if (std::isfinite(dt_event)) return std::min(cap, frac * dt_event);
  return cap;
}

template <class Stepper>
bool StepDriver<Stepper>::advance(const Solved& from, double dt, State* to, std::string* why) {
  *to = from.state;
  g_.move(from, dt, to);
  g_.place_tools(*to);
  g_.maintain_contacts(*to, holds_);
  return g_.update_thickness(*to, why);
}

template <class Stepper>
bool StepDriver<Stepper>::take_step(const Solved& from, double dt, Solved* to, std::string* why) {
  g_.start_from(from, to);
  if (scene_.numerics.time_integration == TimeIntegration::kImplicit) {
    return take_implicit_step(from, dt, to, why);
  }
  if (scene_.numerics.time_integration == TimeIntegration::kEuler) {
    return advance(from, dt, &to->state, why) && g_.solve(to, dt, nullptr, holds_, why);
  }
  // Heun (explicit trapezoidal rule): predict with the start velocity, solve there, then redo the
  // update with the mean of both velocities and strain rates. The plain forward update lags the
  // moving contact front by a whole step, which costs O(dt) in the strain distribution with a
  // large constant; the corrected update is second order.
  // The predictor's solve hardens from the start of the step, like the start state's own solve:
  // both rates then see sigma_y(eps_bar_n + dt eps_dot), and their mean moves a yield-stress
  // difference between two flowing elements to zero in one step (the models' freeze_material).
  // Hardening from the predicted eps_bar_n + dt eps_dot_n instead counts the start rate's
  // hardening twice and halves that damping (measured, ex1, 24 elements, 0.05 element lengths
  // per step, rms step-to-step alternation of the element strain increments over their mean, at
  // the pole / mid-radius / near the rim: theta 1/2 as before 0.19 / 0.19 / 0.73, theta 1 with
  // this start 0.07 / 0.05 / 0.19; at 0.025 element lengths 0.04 / 0.03 / 0.10 -> 0.03 / 0.02 /
  // 0.06). What is left is the explicit geometry update's own limit.
  Solved pred;
  g_.start_from(from, &pred);
  if (!advance(from, dt, &pred.state, why) ||
      !g_.solve(&pred, dt, &g_.eps_bar(from.state), holds_, why)) {
    return false;
  }
  const Solved mid = g_.blend(from, pred, 0.5);
  if (!advance(mid, dt, &to->state, why)) return false;
  // Nodes the predictor found touching at the end of the step touch in the corrected state too.
  g_.attach_touching(pred.state, &to->state, holds_);
  if (!g_.update_thickness(to->state, why)) return false;
  g_.start_from(pred, to);  // the best start for the corrected solve
  return g_.solve(to, dt, nullptr, holds_, why);
}

// Backward Euler in the geometry: x_{n+1} = x_n + dt v_{n+1}, with v_{n+1} the velocity solved in
// the configuration x_{n+1} (and the hardening from the step start, as the predictor's). Why: a
// nearly rigid free region (the unsupported wall between punch and die) has its shape slaved to
// equilibrium; a shape error w of wavelength l is undone by the membrane tension N against only
// the bending viscosity, at the rate lambda ~ 12 N / (mu h^3 l^-2) = 36 eps_dot (l / h)^2. The
// explicit update is stable only for lambda dt < 2 (that is the 0.025 element lengths per step
// cap); backward Euler damps the mode by 1 / (1 + lambda dt) at any step.
// How: Newton on the geometry. Solve k moves the start state with the previous solve's velocity
// v_k (the first: with the start velocity, Euler's predictor) and solves there with the
// configuration's dependence on the velocity linearised: the membrane initial-stress stiffness
// K_g of the previous solve's stresses, dt K_g (v - v_k) (the models' GeometryCoupling). K_g holds
// the stiff mode (the tension against a change of shape), so the iteration converges where the
// plain fixed point (Heun's corrector) diverges. A fixed number of solves per step
// (numerics.implicit_solves, 2 by default) keeps the step a smooth map of the parameters.
// Measured on ex1 (50 elements, 0.25 element lengths per step): a third solve moves the force by
// <= 0.005 % and the smallest thickness by 4e-5 mm, for 47 % more factorisations.
// One solve: the configuration is moved with the start velocity v_n and the solve's velocity is
// carried into the next step. On a stiff mode of rate lambda (a = lambda dt) the step is then
// w_{n+1} = w_n + dt u_n, u_{n+1} = -lambda (w_n + (1 - theta) dt u_n) / (1 + theta a): damped,
// |z|^2 = theta a / (1 + theta a), but weakly at large a; first order in the geometry
// (experiments/05_shell3d, "One solve per step").
// Each solve starts from the previous solve's velocity (and duals), set after the configuration
// is moved (moving it copies the blended velocity; until Nov 2026 the later solves started from
// that blend, 4-45x farther from their answer). Every solve but the last stops at a looser
// tolerance (StepDriverOptions::implicit_first_tolerance_factor): its velocity only places the
// next configuration.
// Releases wait for the last solve: a node whose reaction pulls leaves a (not sticking) tool only
// in the last solve's contact rounds. The configuration moved with the start velocity puts nodes
// at the front of a patch onto a tool whose reaction then pulls, and the later solves' contact
// sets start from the step start's (plus what the previous solve found touching), so each later
// solve repeated the first solve's release rounds (ex4a, 32 divisions, friction 0.2: 4-10 nodes in
// 1-3 extra rounds in most steps, each round a factorisation). Measured (experiments/05_shell3d,
// "Releases in the last solve"): ex4a 32 divisions to 5 mm, 139 -> 121 solves, 130.5 -> 109.2 s;
// the Hill 1948 TUAT cup 43.0 -> 30.8 s. Carrying the first solve's releases into the later
// solves instead saved as much but decided them in the predictor's configuration: the quarter 3D
// cup chattered (39 cut-backs).
// Where new contacts enter (numerics.contact_entry). first_solve (the default): a node that
// reaches a tool in the first solve's configuration (moved with the start velocity) touches from
// the first solve on. last_solve: every configuration but the last is searched for the contact
// set of the step start only (ContactHolds::defer_new), so a node that reaches a tool
// during the step is free in the velocities that place the step's end configuration, is put onto
// the tool there, and touches in the last solve (whose velocity the next step carries). A node
// touching at the fraction phi of the step is then free for the whole step in the geometry, an
// error (1 - phi) of its contact increment; attached in the first solve's configuration, it was
// in contact for theta of the step, an error |theta - (1 - phi)|. Stretching nodes wrap onto a
// punch tangentially and touch late in a step (phi mostly 0.8-1 on ex4a at 0.25 element lengths),
// and with contact events the event node touches at the step's end (phi = 1; but the last
// configuration can leave it just short of the tool, and tiny follow-up steps take it there: 5-7 %
// more steps on the axisymmetric examples). Measured against the same mesh at a quarter of the
// step with events (experiments/05_shell3d, "New contacts in the last solve"): ex4a n = 16,
// friction 0.2, max |d eps_t| 0.0010 / 0.0020 / 0.0036 at 10 / 20 / 30 mm against 0.0035 / 0.0042 /
// 0.0108, at the same cost; ex1 (24 elements, events) 0.0003 against 0.0016 at 0.2 element lengths.
// Not the default: where nodes touch early in their steps (a coarse 3D mesh at the first
// millimetres: ex4a n = 4, 0.5 mm steps, mean force at 4 mm 2.44 % above the axisymmetric twin
// instead of 1.87 %) the whole-step error (1 - phi) is larger, and choosing per node (attach in the
// first solve below phi = 1/2) made the outputs jump under 1e-5 changes of friction (4.6e-6 of the
// force). New contacts with a sticking tool never wait (ContactHolds::defers): a node that touches
// it stops, and a free step more deepened the neck at the stuck patch's edge (ex1 sticking, 48
// elements, 0.444 mm against 0.489 step-converged).
template <class Stepper>
bool StepDriver<Stepper>::take_implicit_step(const Solved& from, double dt, Solved* to,
                                             std::string* why) {
  struct Restore {
    Stepper& g;
    double tolerance;
    ContactHolds& holds;
    ~Restore() {
      g.couple_geometry(nullptr, 0.0);
      g.set_tolerance(tolerance);
      holds.defer_new = false;
      holds.keep_touching = false;
    }
  } restore{g_, scene_.numerics.tolerance, holds_};
  const double theta = scene_.numerics.implicit_theta;
  const int solves = scene_.numerics.implicit_solves;
  const double loose_tolerance =
      std::max(scene_.numerics.tolerance,
               std::min(StepDriverOptions::kMaxLooseTolerance,
                        options_.implicit_first_tolerance_factor * scene_.numerics.tolerance));
  if (static_cast<int>(implicit_iterations_.size()) < solves) implicit_iterations_.resize(solves);
  const bool defer = scene_.numerics.contact_entry == ContactEntry::kLastSolve;
  Solved previous = from;  // the iterate whose velocity moves the geometry
  for (int k = 0; k < solves; ++k) {
    const bool last = k + 1 == solves;
    const Solved moving = g_.blend(from, previous, theta);
    holds_.defer_new = defer && !last;  // numerics.contact_entry (above; restore clears it)
    holds_.keep_touching = !last;       // releases wait for the last solve (above)
    if (!advance(moving, dt, &to->state, why)) return false;  // (thickness included)
    if (k > 0) {
      // Nodes the previous solve found touching touch here too; attaching moves them, so the
      // thickness is recomputed.
      g_.attach_touching(previous.state, &to->state, holds_);
      if (!g_.update_thickness(to->state, why)) return false;
    }
    g_.start_from(previous, to);
    g_.couple_geometry(&previous, theta * dt);
    g_.set_tolerance(last ? scene_.numerics.tolerance : loose_tolerance);
    const bool solved = g_.solve(to, dt, &g_.eps_bar(from.state), holds_, why);
    implicit_iterations_[static_cast<std::size_t>(k)] += to->summary.iterations;
    if (!solved) return false;
    if (!last) previous = *to;
  }
  return true;
}

template <class Stepper>
void StepDriver<Stepper>::finish(double total_s, RunResult* result) {
  result->timings.total_s = total_s;
  result->timings.contact_s += contact_s_;
  result->implicit_solve_iterations = implicit_iterations_;
  g_.finish(result);
}

template <class Stepper>
RunResult StepDriver<Stepper>::run() {
  const auto t_start = Clock::now();
  RunResult result;
  g_.start(&result);
  Solved current;
  current.state = g_.initial_state();
  holds_.reset(g_.num_nodes());
  holds_.released.clear();  // the first search releases nothing
  g_.place_tools(current.state);
  g_.maintain_contacts(current.state, holds_);
  std::string why;
  const double V = scene_.process.punch_speed_mm_per_s;
  if (!g_.solve(&current, grid_increment_mm_ / V, nullptr, holds_, &why)) {
    result.termination = Termination::kFailed;
    result.message = "the first step did not converge: " + why;
    g_.output(current, 0.0, &result);
    finish(seconds_since(t_start), &result);
    return result;
  }
  const double total = scene_.process.punch_travel_mm;
  std::size_t next_output = 0;
  const auto& outputs = scene_.process.output_travels_mm;
  double cap_factor = 1.0;
  int cutbacks_since_success = 0;
  int steps_with_cutbacks = 0;  // consecutive steps that needed a cut-back
  int stalled_steps = 0;        // consecutive steps that did not advance the punch
  for (int step = 0;; ++step) {
    // Record the converged configuration.
    const double T = travel(current.state);
    StepRecord rec = g_.record(current);
    rec.step = step;
    rec.time_s = current.state.time_s;
    rec.punch_travel_mm = T;
    rec.punch_force_N = current.punch_force;
    rec.iterations = current.summary.iterations;
    rec.residual_norm = current.summary.residual_norm;
    rec.update_norm = current.summary.update_norm;
    rec.cutbacks = cutbacks_since_success;
    result.steps.push_back(rec);
    g_.observe(current);
    result.total_iterations += rec.iterations;
    result.max_condition_estimate =
        std::max(result.max_condition_estimate, current.summary.condition_estimate);
    if (run_options_.on_step) run_options_.on_step(rec);
    while (next_output < outputs.size() && std::abs(outputs[next_output] - T) <= 1e-9 * total) {
      g_.output(current, T, &result);
      ++next_output;
    }
    if (scene_.output.history) g_.history(current, T, &result);
    if (T >= total * (1.0 - 1e-12)) break;

    // Next configuration, with cut-back on failure.
    Solved next;
    bool ok = false;
    cutbacks_since_success = 0;
    const std::vector<double> holds_before = holds_.hold_until_mm;
    while (!ok) {
      const double dt = choose_dt(current, cap_factor);
      ok = take_step(current, dt, &next, &why);
      if (ok) break;
      if (cutbacks_since_success >= scene_.numerics.max_cutbacks) {
        result.termination = Termination::kFailed;
        result.message = fmt::format("stopped at punch travel {:.4f} mm after {} cut-backs: {}", T,
                                     cutbacks_since_success, why);
        g_.output(current, T, &result);
        finish(seconds_since(t_start), &result);
        return result;
      }
      if (run_options_.verbose) {
        std::fprintf(stderr, "  cut-back at travel %.5f mm: %s\n", T, why.c_str());
      }
      ++cutbacks_since_success;
      ++result.total_cutbacks;
      cap_factor *= 0.5;
      // The released set belongs to `current`; a retry must not inherit the failed attempt's.
      holds_.new_solve(g_.num_nodes());
      holds_.hold_until_mm = holds_before;
    }
    cap_factor = std::min(1.0, 2.0 * cap_factor);
    // Steps that do not advance the punch (contact events piling up at one instant) must not go
    // on for ever: a run that cannot leave an instant stops with the reason.
    stalled_steps = travel(next.state) - T < options_.stall_fraction * grid_increment_mm_
                        ? stalled_steps + 1
                        : 0;
    if (stalled_steps >= options_.max_stalled_steps) {
      result.termination = Termination::kFailed;
      result.message = fmt::format(
          "stopped at punch travel {:.4f} mm: {} consecutive steps advanced the punch by less than "
          "{} of the travel increment (contact events pile up at one instant)",
          T, stalled_steps, options_.stall_fraction);
      current = std::move(next);
      break;
    }
    steps_with_cutbacks = cutbacks_since_success > 0 ? steps_with_cutbacks + 1 : 0;
    if (steps_with_cutbacks >= options_.max_steps_with_cutbacks) {
      // Every step fails at first and creeps on with tiny increments: the run would take for
      // ever without a trustworthy answer. Stop and say so.
      result.termination = Termination::kFailed;
      result.message = fmt::format(
          "stopped at punch travel {:.4f} mm: {} consecutive steps needed cut-backs (last: {}); "
          "the step size keeps collapsing",
          travel(next.state), steps_with_cutbacks, why);
      current = std::move(next);
      break;
    }
    current = std::move(next);
  }
  g_.output(current, travel(current.state), &result);
  if (result.completed()) {
    result.message = fmt::format("completed: punch travel {:.4f} mm in {} steps",
                                 travel(current.state), result.steps.size());
  }
  finish(seconds_since(t_start), &result);
  return result;
}

// The implicit update's velocity solves per step when a scene leaves them to the model's size
// (NumericsSpec::implicit_solves = kImplicitSolvesBySize, the default of a shell3d scene file):
// two (second order in the geometry) below kOneSolveMinUnknowns unknowns, one from there. Two
// solves cost about 1.5x one; one solve is first order, with an error proportional to the step,
// which the default cap sets at a quarter of the element length: largest on the coarse meshes,
// where a run takes seconds, smallest on the fine ones, where it takes minutes. Measured on ex4a
// (friction 0.2, to 30 mm, 2 threads; against the 120-element axisymmetric twin with
// numerics.transverse_shear_scale = 0.1 on both sides, where the twin is mesh-converged), largest
// |d eps_t| at 30 mm, one solve against two: 8 divisions (4 085 unknowns) 0.0068 / 0.0034,
// 16 (15 845) 0.0052 / 0.0021, 32 (62 405) 0.0030 / 0.0015; and at the default penalty, 32
// divisions 136-139 s against 215-217 s (experiments/05_shell3d, "One solve per step from
// 30 000 unknowns").
inline constexpr int kOneSolveMinUnknowns = 30000;
inline int implicit_solves_for(const NumericsSpec& numerics, int unknowns) {
  if (numerics.implicit_solves != kImplicitSolvesBySize) return numerics.implicit_solves;
  return unknowns >= kOneSolveMinUnknowns ? 1 : 2;
}

// RunResult::built's line for the geometry update of `numerics` (its implicit_solves resolved;
// `by_size`: chosen by implicit_solves_for).
inline std::string time_integration_line(const NumericsSpec& numerics, bool by_size) {
  switch (numerics.time_integration) {
    case TimeIntegration::kHeun:
      return "time integration: Heun (explicit trapezoidal, two velocity solves per step)";
    case TimeIntegration::kEuler:
      return "time integration: Euler (the start-of-step velocity, one velocity solve per step)";
    case TimeIntegration::kImplicit:
      break;
  }
  return fmt::format(
      "time integration: implicit (theta {:g}), {} velocity solve{} per step{}",
      numerics.implicit_theta, numerics.implicit_solves, numerics.implicit_solves == 1 ? "" : "s",
      by_size ? fmt::format(" (by the model's size: 2 below {} unknowns, 1 from there)",
                            kOneSolveMinUnknowns)
              : "");
}

// A run of one geometry: checks the step driver's options (RunOptions::driver; invalid ones fail
// the run at once with the reason), builds the stepper, resolves the velocity solves per step
// that the scene leaves to the model's size, and drives it.
template <class Stepper>
RunResult run_stepper(const Scene& scene, const RunOptions& options) {
  if (std::string why; !options.driver.IsValid(&why)) {
    RunResult failed;
    failed.termination = Termination::kFailed;
    failed.message = "invalid step driver options: " + why;
    return failed;
  }
  // A scene file's range check does not reach a scene built in code.
  const bool by_size = scene.numerics.implicit_solves == kImplicitSolvesBySize;
  if (!by_size && (scene.numerics.implicit_solves < 1 || scene.numerics.implicit_solves > 3)) {
    RunResult failed;
    failed.termination = Termination::kFailed;
    failed.message = fmt::format(
        "numerics.implicit_solves = {} is out of range [1, 3] (or {}: by the model's size)",
        scene.numerics.implicit_solves, kImplicitSolvesBySize);
    return failed;
  }
  Stepper stepper(scene, options, options.driver);
  // The count needs the built model; the stepper itself never reads it, the driver does.
  Scene resolved = scene;
  resolved.numerics.implicit_solves = implicit_solves_for(scene.numerics, stepper.num_unknowns());
  StepDriver<Stepper> driver(resolved, options, options.driver, stepper);
  RunResult result = driver.run();
  result.implicit_solves = resolved.numerics.implicit_solves;
  // After the model's own line (the stepper's first).
  const auto at = result.built.begin() + std::min<std::ptrdiff_t>(1, std::ssize(result.built));
  result.built.insert(at, time_integration_line(resolved.numerics, by_size));
  return result;
}

}  // namespace vs
