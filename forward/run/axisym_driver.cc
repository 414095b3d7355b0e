// Step driver (paper section 3 steps 1-7 and section 4.6): solve the velocity field in the current
// configuration, choose the time step from the next contact event and the increment caps, update
// geometry, thickness and hardening, and repeat to the total punch travel. A failed solve is cut
// back (the previous update is redone with half the step); a run that cannot go on returns what
// it has with Termination::kFailed.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "model/axisym_model.h"
#include "run/axisym_problem.h"
#include "run/built_components.h"
#include "run/observe.h"
#include "run/simulate.h"
#include "run/travel_grid.h"

namespace vs {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Iterations allowed to a solve with consistent friction before it is redone with lagged friction.
constexpr int kConsistentIterations = 30;
// Thickness limits relative to the initial thickness (see update_thickness).
constexpr double kMinThicknessRatio = 0.05;
constexpr double kMaxThicknessRatio = 3.0;

// A converged configuration: state plus what the step control needs.
struct Solved {
  AxisymState state;
  double punch_force = 0.0;
  double max_rate = 0.0;
  std::vector<std::vector<double>> point_rates;
  std::vector<Vec5> resultants;
  NewtonSummary summary;
  int active_set_rounds = 0;
  // Flow directions of the converged solve (primal-dual unknowns), the next solve's start.
  std::vector<double> directions;
  std::vector<double> punch_node_force;  // axial punch force on each node [N]
};

class Driver {
 public:
  Driver(const Scene& scene, const RunOptions& options)
      : scene_(scene), options_(options), model_(scene) {
    model_.set_consistent_friction(options.consistent_friction);
    contact_tol_ = 1e-8 * scene.blank.thickness_mm;
    attach_tol_ = 1e-2 * scene.blank.thickness_mm;
    nl_.kind = scene.numerics.solver;
    nl_.tolerance = scene.numerics.tolerance;
    nl_.max_iterations = scene.numerics.max_iterations;
    nl_.verbose = options.verbose;
    // Steps end on a fixed travel grid (multiples of the travel cap) and at the output travels;
    // contact events split grid intervals. The step sequence then moves continuously with the
    // material and friction parameters, which keeps outputs smooth for calibration.
    double shortest = std::numeric_limits<double>::infinity();
    for (int e = 0; e < model_.num_elements(); ++e)
      shortest = std::min(shortest, model_.initial_length(e));
    grid_increment_mm_ = std::min(scene.numerics.max_travel_increment_mm,
                                  scene.numerics.max_travel_increment_per_length * shortest);
    targets_ = travel_grid(scene.process.punch_travel_mm, grid_increment_mm_,
                           scene.process.output_travels_mm);
    model_.set_squeeze_correction_time(grid_increment_mm_ / scene.process.punch_speed_mm_per_s);
  }

  RunResult run();

 private:
  // Grid spacing of the step ends: the smaller of the absolute cap and the cap relative to the
  // shortest initial element (the stability limit of the explicit geometry update).
  double travel_increment() const { return grid_increment_mm_; }
  // Squeeze check of a converged state: a node in contact with one tool whose other surface
  // lies inside another tool by more than 2 % of the thickness, i.e. more than the ironing
  // constraint (AxisymModel::update_squeezed) lets through: the run says so.
  void note_squeeze(const AxisymState& s);
  // Timings, counters and the squeeze warning into the result, on every way out of run().
  void finish_result(double total_s, RunResult* result);
  bool eligible(int node) const {
    return !(node == model_.num_nodes() - 1 && scene_.blank.edge != EdgeCondition::kFree);
  }
  void attach(AxisymState& s, int node, int tool);
  void maintain_contacts(AxisymState& s, const std::vector<char>& released);
  // dt_predicted: step size expected after this solve (for the hardening seen by the solve);
  // hardening_from: the effective strains the solve's hardening starts from (default: the
  // state's own).
  bool solve(Solved* out, double dt_predicted, std::string* why,
             const std::vector<double>* hardening_from = nullptr);
  bool advance(const Solved& from, double dt, AxisymState* to, std::string* why);
  // Element thickness from its constant volume and current geometry; false if degenerate.
  bool update_thickness(AxisymState& s, std::string* why) const;
  // One step of size dt from a converged configuration to the next converged one.
  bool take_step(const Solved& from, double dt, Solved* to, std::string* why);
  double choose_dt(const Solved& from, double cap_factor, std::vector<char>* released) const;
  double travel(const AxisymState& s) const {
    return s.time_s * scene_.process.punch_speed_mm_per_s;
  }

  const Scene& scene_;
  RunOptions options_;
  AxisymModel model_;
  NewtonOptions nl_;
  std::vector<double> targets_;
  double grid_increment_mm_ = 0.0;
  double contact_tol_ = 0.0;    // gap below which a node touches a tool
  double attach_tol_ = 0.0;     // search tolerance next to a touching neighbour
  std::vector<char> released_;  // nodes released by the last solve (no immediate re-contact)
  // A released node may not touch again before the punch has moved one grid increment further:
  // without this hysteresis a node whose reaction hovers around zero attaches and releases at
  // every step, and the contact-event step shrinks to nothing (measured: ex1, 40 elements,
  // sticking, 0.037 mm grid: 20 000 steps stuck at 26.63 mm).
  std::vector<double> hold_until_mm_;
  RunTimings timings_;
  int friction_fallbacks_ = 0;      // solves redone with lagged friction
  std::vector<char> was_released_;  // nodes released from a tool at any earlier solve
  // First squeezed state (travel, initial radius, tools, overlap) and the largest overlap.
  double squeeze_travel_mm_ = -1.0, squeeze_r0_mm_ = 0.0, squeeze_first_mm_ = 0.0;
  double squeeze_max_mm_ = 0.0;
  std::string squeeze_tools_;
  // First ironed element longer than kIroningElementRatio initial thicknesses (travel, length).
  double coarse_ironing_travel_mm_ = -1.0, coarse_ironing_length_mm_ = 0.0;
};

// Ironing thins a squeezed element as a whole (AxisymModel::add_squeeze); on elements longer than
// this many thicknesses the ironing force is overestimated (measured, ex3: 13 elements of 4.1
// thicknesses spike the punch force to 66.6 kN at 37.5 mm against 38.7-40.0 kN with 26-52
// elements of 1.1-2.1 thicknesses).
constexpr double kIroningElementRatio = 3.0;

void Driver::attach(AxisymState& s, int node, int tool) {
  const RigidTool& t = model_.tools()[tool];
  const ClosestPoint c = t.closest(s.x[node]);
  NodeContact& nc = s.contact[node];
  const double keep_force = nc.tool == tool ? nc.normal_force_N : 0.0;
  // A node that left a sticking tool (its reaction pulled) and touches it again is the edge of
  // the stuck patch: stuck, it pulls; free, it runs into the tool (measured: ex1 sticking, one
  // attach-release round at every step). The consistent state is touching with zero reaction
  // and zero friction, so it slides without friction until both neighbours touch the tool.
  const bool slip = t.sticking() && (nc.tool == tool ? nc.slip_edge : was_released_[node] != 0);
  const NodeContact before = nc;
  nc = NodeContact{};
  nc.tool = tool;
  nc.slip_edge = slip;
  if (before.tool == tool) {  // the squeeze state is kept while the node stays on its tool
    nc.squeeze_tool = before.squeeze_tool;
    nc.clearance_mm = before.clearance_mm;
    nc.squeeze_force_N = before.squeeze_force_N;
  }
  nc.normal = c.normal;
  nc.normal_force_N = keep_force;
  nc.on_die_face = t.kind() == ToolKind::kDie && c.primitive == 0;
  nc.on_holder_face = t.kind() == ToolKind::kBlankHolder;
  const double h = model_.node_thickness(s, node);
  Eigen::Vector2d x = c.point + 0.5 * h * c.normal;
  if (node == 0 && model_.initial_radius(0) == 0.0) {
    // On the axis the contact normal is vertical by symmetry and the node stays on the axis.
    nc.normal = Eigen::Vector2d(0.0, c.normal.y() >= 0.0 ? 1.0 : -1.0);
    x = Eigen::Vector2d(0.0, c.point.y() + 0.5 * h * nc.normal.y());
  }
  s.x[node] = x;
}

void Driver::maintain_contacts(AxisymState& s, const std::vector<char>& released) {
  model_.place_tools(s);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (!eligible(i)) continue;
    if (s.contact[i].tool >= 0) {
      const RigidTool& t = model_.tools()[s.contact[i].tool];
      // A node that has run past the inner edge of a fixed-gap holder's face leaves it (the
      // closest point would be the edge itself, and re-attaching there would pin the node).
      if (t.kind() == ToolKind::kBlankHolder && s.x[i].x() < t.profile().front().p0.x()) {
        s.contact[i] = NodeContact{};
        continue;
      }
      attach(s, i, s.contact[i].tool);  // back onto the surface, normal refreshed
      if (s.contact[i].slip_edge) {
        const int ti = s.contact[i].tool;
        const bool axis = i == 0 && model_.initial_radius(0) == 0.0;
        const bool next = i + 1 < model_.num_nodes() && s.contact[i + 1].tool == ti;
        const bool prev = axis ? next : i > 0 && s.contact[i - 1].tool == ti;
        if (next && prev) s.contact[i].slip_edge = false;  // inside the patch now: stuck
      }
      continue;
    }
    if (!released.empty() && released[i]) continue;
    if (!hold_until_mm_.empty() && travel(s) < hold_until_mm_[i]) continue;
    int best = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < model_.tools().size(); ++t) {
      const double g = model_.tools()[t].gap(s.x[i], model_.node_thickness(s, i));
      // Search tolerance: touching, or within a small fraction of the thickness of a tool that
      // a neighbour touches. Without it a node that lifted off by micrometres (a rigid band
      // riding on the punch) is never pulled back, and the contact patch breaks up.
      // Only holes inside a patch are filled this way (both neighbours touch the tool; on the
      // axis the one neighbour): the front of a patch advances by exact contact events, so
      // outputs stay smooth functions of the parameters.
      const int ti = static_cast<int>(t);
      const bool next = i + 1 < model_.num_nodes() && s.contact[i + 1].tool == ti;
      const bool prev = (i == 0 && model_.initial_radius(0) == 0.0)
                            ? next
                            : (i > 0 && s.contact[i - 1].tool == ti);
      const double tol = (next && prev) ? attach_tol_ : contact_tol_;
      if (g <= tol && g < best_gap) {
        best_gap = g;
        best = static_cast<int>(t);
      }
    }
    if (best >= 0) attach(s, i, best);
  }
}

bool Driver::solve(Solved* out, double dt_predicted, std::string* why,
                   const std::vector<double>* hardening_from) {
  AxisymState& s = out->state;
  model_.place_tools(s);
  model_.update_sandwiched(&s);
  model_.update_squeezed(&s);
  model_.freeze_material(hardening_from ? *hardening_from : s.eps_bar, dt_predicted);
  released_.assign(model_.num_nodes(), 0);
  constexpr int kMaxRounds = 20;
  for (int round = 0; round < kMaxRounds; ++round) {
    model_.update_holder(&s);
    std::optional<AxisymStepProblem> problem;
    Eigen::VectorXd x;
    // A new step problem from the start velocity, its flow directions warm-started from the
    // previous converged solve (measured on ex1, 48 elements, frictionless: 26 % fewer iterations
    // than starting them at zero).
    auto start_problem = [&] {
      problem.emplace(model_, &s);
      x = problem->start(s.v);
      problem->warm_start(out->directions);
    };
    start_problem();
    if (options_.verbose) {
      int nc = 0;
      for (int i = 0; i < model_.num_nodes(); ++i) nc += s.contact[i].tool >= 0;
      std::fprintf(stderr, "  solve at travel %.5f mm, round %d, %d contact nodes\n", travel(s),
                   round, nc);
    }
    // Every solve's work counts in the timings, also a solve redone with lagged friction.
    auto newton = [&](const NewtonOptions& o) {
      const NewtonSummary sum = solve_newton(*problem, o, &x);
      timings_.assembly_s += sum.assembly_s;
      timings_.linear_solve_s += sum.factorisation_s;
      timings_.factorisations += sum.factorisations;
      return sum;
    };
    if (model_.consistent_friction()) {
      // Friction consistent with the current normal reactions (quadratic convergence; measured
      // on ex1, 48 elements, friction 0.2: 2.7x fewer iterations). At high friction its
      // unsymmetric Newton can stall; then the step is solved again with the lagged, relaxed
      // normal reactions, which converge to the same solution.
      NewtonOptions first = nl_;
      first.max_iterations = std::min(nl_.max_iterations, kConsistentIterations);
      out->summary = newton(first);
      if (!out->summary.converged) {
        ++friction_fallbacks_;
        model_.set_consistent_friction(false);
        start_problem();
        out->summary = newton(nl_);
        model_.set_consistent_friction(true);
      }
    } else {
      out->summary = newton(nl_);
    }
    if (!out->summary.converged) {
      *why = out->summary.message;
      return false;
    }
    problem->finish(x);
    out->directions = problem->directions();
    s.v = model_.to_global(s, x);
    // Contact release: a node whose reaction pulls on the tool leaves it (active-set check). The
    // threshold ignores tensile reactions at round-off level of the largest contact force, which
    // would otherwise make a node touching with zero force chatter in and out.
    constexpr double kReleaseFraction = 1e-4;
    const std::vector<double>& N = problem->normal_reactions();
    double scale = 0.0;
    for (int i = 0; i < model_.num_nodes(); ++i) scale = std::max(scale, std::abs(N[i]));
    // Only a node at the edge of its contact patch may separate, and only if its reaction,
    // averaged with its neighbours on the same tool (weights 1/4, 1/2, 1/4; the axis node is its
    // own mirror image), pulls on the tool. A bending-stiff shell on a faceted contact picks up
    // alternating (checkerboard) nodal reactions once elements are shorter than the thickness;
    // releasing on the raw reaction makes the contact set chatter and the patch break up.
    auto same_tool = [&](int j, int tool) {
      return j >= 0 && j < model_.num_nodes() && s.contact[j].tool == tool;
    };
    std::vector<int> release;
    for (int i = 0; i < model_.num_nodes(); ++i) {
      const int tool = s.contact[i].tool;
      // A squeezed node touches both tools whatever its reaction on one of them.
      if (tool < 0 || model_.sandwiched(s.contact[i]) || s.contact[i].squeeze_tool >= 0) continue;
      const bool on_axis = i == 0 && model_.initial_radius(0) == 0.0;
      const bool next = same_tool(i + 1, tool);
      const bool prev = on_axis ? next : same_tool(i - 1, tool);
      if (next && prev) continue;  // interior: the patch shrinks from its edges
      double smoothed = 0.5 * N[i];
      smoothed += 0.25 * (next ? N[i + 1] : N[i]);
      smoothed += 0.25 * (prev ? N[on_axis ? i + 1 : i - 1] : N[i]);
      if (smoothed < -kReleaseFraction * scale) release.push_back(i);
    }
    for (int i : release) {
      if (options_.verbose) {
        std::fprintf(stderr, "  release node %d (tool %d, r0 %.3g mm, reaction %.4g N)\n", i,
                     s.contact[i].tool, model_.initial_radius(i), N[i]);
      }
      s.contact[i] = NodeContact{};
      released_[i] = 1;
      was_released_[i] = 1;
      hold_until_mm_[i] = travel(s) + travel_increment();
    }
    const bool any = !release.empty();
    out->active_set_rounds = round + 1;
    if (!any) {
      // Fixed-gap holder: the pressure of this converged state sets the holder forces (and so
      // the friction on both flange faces) of the next solve. Coupling them inside the Newton
      // iteration does not converge: friction depends on the pressure, the pressure on the draw-in
      // velocity, and the loop gain is the penalty stiffness (measured: ex3 with a 1.04 mm gap
      // stalled at |r|/|f| ~ 0.5 for any penalty from 1 to 1e3 reference viscosities). Lagging
      // them by one converged state costs O(dt) in the friction force, small at the travel step
      // the explicit geometry update needs anyway.
      if (model_.fixed_gap_holder()) {
        const std::vector<double>& hf = problem->holder_forces();
        for (int i = 0; i < model_.num_nodes(); ++i) {
          s.contact[i].holder_force_N = AxisymModel::in_gap(s.contact[i]) ? hf[i] : 0.0;
        }
      }
      // Squeeze forces: lagged one converged state, as the fixed-gap holder's.
      const std::vector<double>& sq = problem->squeeze_forces();
      for (int i = 0; i < model_.num_nodes(); ++i) {
        NodeContact& c = s.contact[i];
        c.squeeze_force_N = c.squeeze_tool >= 0 ? sq[i] : 0.0;
      }
      out->punch_force = problem->punch_force();
      out->punch_node_force = problem->punch_node_forces();
      out->max_rate = problem->max_point_rate();
      out->point_rates = problem->point_rates();
      out->resultants = problem->resultants();
      return true;
    }
  }
  *why = "contact active set did not settle";
  return false;
}

double Driver::choose_dt(const Solved& from, double cap_factor,
                         std::vector<char>* /*released*/) const {
  // To the next grid point in equal strain-capped sub-steps; a cut-back divides further.
  const double cap =
      cap_factor * step_to_next_target(targets_, travel(from.state),
                                       scene_.process.punch_speed_mm_per_s,
                                       scene_.numerics.max_strain_increment, from.max_rate);
  // Next contact event (paper eq. 53, any tool, any free node), looked for a little beyond the
  // cap so that the step fraction can approach it gradually.
  const double frac = scene_.numerics.step_fraction;
  const double horizon = cap / frac;
  double dt_event = std::numeric_limits<double>::infinity();
  const AxisymState& s = from.state;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (!eligible(i) || s.contact[i].tool >= 0 || released_[i]) continue;
    if (travel(s) < hold_until_mm_[i]) continue;
    const Eigen::Vector2d v = s.v.segment<2>(3 * i);
    const double h = model_.node_thickness(s, i);
    for (const RigidTool& tool : model_.tools()) {
      dt_event = std::min(dt_event, tool.contact_time(s.x[i], v, h, horizon));
    }
  }
  if (dt_event <= cap) return std::max(dt_event, 1e-12 * cap);
  if (std::isfinite(dt_event)) return std::min(cap, frac * dt_event);
  return cap;
}

bool Driver::advance(const Solved& from, double dt, AxisymState* to, std::string* why) {
  *to = from.state;
  AxisymState& s = *to;
  const int nn = model_.num_nodes();
  for (int i = 0; i < nn; ++i) s.x[i] += dt * from.state.v.segment<2>(3 * i);
  for (std::size_t t = 0; t < s.tool_offset.size(); ++t) {
    s.tool_offset[t] += dt * model_.tools()[t].velocity();
  }
  const std::size_t np = model_.rule().zeta.size();
  for (int e = 0; e < model_.num_elements(); ++e) {
    for (std::size_t k = 0; k < np; ++k) s.eps_bar[e * np + k] += dt * from.point_rates[e][k];
  }
  s.time_s += dt;
  maintain_contacts(s, released_);
  return update_thickness(s, why);
}

bool Driver::update_thickness(AxisymState& s, std::string* why) const {
  // Thickness from the constant element volume (exact incompressibility; numerics.md 3.6).
  for (int e = 0; e < model_.num_elements(); ++e) {
    const Axisym2Geometry g = model_.geometry(s, e);
    const double area = 2.0 * std::numbers::pi * g.mid_radius() * g.length();
    const double h = model_.element_volume(e) / area;
    if (!(h > 0.0) || !std::isfinite(h) || g.mid_radius() <= 0.0) {
      *why = fmt::format("element {} degenerated (thickness {:.3g} mm)", e, h);
      return false;
    }
    // Beyond these a membrane-shell answer means nothing: thinning to 5 % is fracture (necking
    // has long run away), thickening to 3x means the mesh is folding onto itself (measured: a
    // cup whose flange locks in a fixed-gap holder tangles at the holder edge, h = 13 h0).
    const double h0 = scene_.blank.thickness_mm;
    if (h < kMinThicknessRatio * h0 || h > kMaxThicknessRatio * h0) {
      *why = fmt::format(
          "element {} (initial radius {:.3g} mm) reached thickness {:.3g} mm = {:.3g} x initial, "
          "outside [{}, {}] x initial: {}",
          e, model_.initial_mid_radius(e), h, h / h0, kMinThicknessRatio, kMaxThicknessRatio,
          h < kMinThicknessRatio * h0 ? "the sheet has necked through (fracture)"
                                      : "the mesh is folding onto itself");
      return false;
    }
    s.thickness[e] = h;
  }
  return true;
}

void Driver::note_squeeze(const AxisymState& s) {
  // Overlaps below 2 % of the initial thickness are contact tolerance, not a squeeze.
  const double tol = 0.02 * scene_.blank.thickness_mm;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const NodeContact& c = s.contact[i];
    if (c.squeeze_tool >= 0 && coarse_ironing_travel_mm_ < 0.0) {
      for (int e : {i - 1, i}) {
        if (e < 0 || e >= model_.num_elements()) continue;
        const double l = model_.geometry(s, e).length();
        if (l > kIroningElementRatio * scene_.blank.thickness_mm) {
          coarse_ironing_travel_mm_ = travel(s);
          coarse_ironing_length_mm_ = l;
        }
      }
    }
    if (c.tool < 0 || model_.sandwiched(c)) continue;
    const double h = model_.node_thickness(s, i);
    for (std::size_t t = 0; t < model_.tools().size(); ++t) {
      const RigidTool& other = model_.tools()[t];
      if (static_cast<int>(t) == c.tool || other.kind() == ToolKind::kBlankHolder) continue;
      const double overlap = -other.gap(s.x[i], h);
      if (overlap <= tol) continue;
      squeeze_max_mm_ = std::max(squeeze_max_mm_, overlap);
      if (squeeze_travel_mm_ < 0.0) {
        squeeze_travel_mm_ = travel(s);
        squeeze_r0_mm_ = model_.initial_radius(i);
        squeeze_first_mm_ = overlap;
        squeeze_tools_ = model_.tools()[c.tool].name() + "' and '" + other.name();
      }
    }
  }
}

void Driver::finish_result(double total_s, RunResult* result) {
  timings_.total_s = total_s;
  result->timings = timings_;
  result->friction_fallbacks = friction_fallbacks_;
  if (squeeze_travel_mm_ >= 0.0) {
    result->warnings.push_back(fmt::format(
        "from punch travel {:.2f} mm the sheet is squeezed between tools '{}' (node at initial "
        "radius {:.3g} mm overlaps the second tool by {:.3g} mm, up to {:.3g} mm later, more "
        "than the ironing constraint allows): results beyond that travel are not trustworthy",
        squeeze_travel_mm_, squeeze_tools_, squeeze_r0_mm_, squeeze_first_mm_, squeeze_max_mm_));
  }
  if (coarse_ironing_travel_mm_ >= 0.0) {
    result->warnings.push_back(fmt::format(
        "from punch travel {:.2f} mm the sheet is ironed on an element {:.3g} mm long, more than "
        "{} initial thicknesses: a coarse element is thinned as a whole, which overestimates the "
        "ironing force; refine the mesh (blank.elements)",
        coarse_ironing_travel_mm_, coarse_ironing_length_mm_, kIroningElementRatio));
  }
}

bool Driver::take_step(const Solved& from, double dt, Solved* to, std::string* why) {
  to->directions = from.directions;
  if (scene_.numerics.time_integration == TimeIntegration::kEuler) {
    return advance(from, dt, &to->state, why) && solve(to, dt, why);
  }
  // Heun (explicit trapezoidal rule): predict with the start velocity, solve there, then redo the
  // update with the mean of both velocities and strain rates. The plain forward update lags the
  // moving contact front by a whole step, which costs O(dt) in the strain distribution with a
  // large constant; the corrected update is second order.
  // The predictor's solve hardens from the start of the step, like the start state's own solve:
  // both rates then see sigma_y(eps_bar_n + dt eps_dot), and their mean moves a yield-stress
  // difference between two flowing elements to zero in one step (AxisymModel::freeze_material).
  // Hardening from the predicted eps_bar_n + dt eps_dot_n instead counts the start rate's
  // hardening twice and halves that damping (measured, ex1, 24 elements, 0.05 element lengths
  // per step, rms step-to-step alternation of the element strain increments over their mean, at
  // the pole / mid-radius / near the rim: theta 1/2 as before 0.19 / 0.19 / 0.73, theta 1 with
  // this start 0.07 / 0.05 / 0.19; at 0.025 element lengths 0.04 / 0.03 / 0.10 -> 0.03 / 0.02 /
  // 0.06). What is left is the explicit geometry update's own limit.
  Solved pred;
  pred.directions = from.directions;
  if (!advance(from, dt, &pred.state, why) || !solve(&pred, dt, why, &from.state.eps_bar)) {
    return false;
  }
  Solved mid;
  mid.state = from.state;
  mid.state.v = 0.5 * (from.state.v + pred.state.v);
  mid.point_rates = from.point_rates;
  for (std::size_t e = 0; e < mid.point_rates.size(); ++e) {
    for (std::size_t k = 0; k < mid.point_rates[e].size(); ++k) {
      mid.point_rates[e][k] = 0.5 * (from.point_rates[e][k] + pred.point_rates[e][k]);
    }
  }
  if (!advance(mid, dt, &to->state, why)) return false;
  // Nodes the predictor found touching at the end of the step touch in the corrected state too.
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const int tool = pred.state.contact[i].tool;
    if (tool >= 0 && to->state.contact[i].tool < 0 && eligible(i)) attach(to->state, i, tool);
  }
  if (!update_thickness(to->state, why)) return false;
  to->state.v = pred.state.v;  // the best start for the corrected solve
  to->directions = pred.directions;
  return solve(to, dt, why);
}

// Consecutive cut-back steps after which a run is stopped as collapsing.
constexpr int kMaxStepsWithCutbacks = 25;
// Consecutive steps without punch progress after which a run is stopped.
constexpr int kMaxStalledSteps = 200;

RunResult Driver::run() {
  const auto t_start = Clock::now();
  RunResult result;
  result.geometry = Geometry::kAxisymmetric;
  result.dofs = model_.num_dofs();
  result.built.push_back(fmt::format(
      "model: axisymmetric 2-node viscous shell, {} elements, {} unknowns, {} thickness points",
      model_.num_elements(), model_.num_dofs(), model_.rule().zeta.size()));
  result.built.push_back(
      "nonlinear solver: primal-dual Newton with Armijo line search on the flow potential"
      " (solver/newton.h)");
  result.built.push_back(
      "linear solver: block tridiagonal LDL^T (block LU with consistent Coulomb friction)");
  for (std::string& line : tool_components(scene_)) result.built.push_back(std::move(line));
  double shortest = std::numeric_limits<double>::infinity();
  for (int e = 0; e < model_.num_elements(); ++e)
    shortest = std::min(shortest, model_.initial_length(e));
  if (shortest < scene_.blank.thickness_mm) {
    // A shell discretisation finer than the thickness resolves nothing real and makes the nodal
    // contact reactions oscillate (measured: ex1 thinning stops converging below l = h).
    result.warnings.push_back(fmt::format(
        "shortest element {:.3g} mm is shorter than the thickness {:.3g} mm: contact reactions "
        "oscillate and strain profiles become noisy; use fewer elements",
        shortest, scene_.blank.thickness_mm));
  }
  Solved current;
  current.state = model_.initial_state();
  hold_until_mm_.assign(model_.num_nodes(), -std::numeric_limits<double>::infinity());
  was_released_.assign(model_.num_nodes(), 0);
  maintain_contacts(current.state, {});
  std::string why;
  const double V = scene_.process.punch_speed_mm_per_s;
  if (!solve(&current, travel_increment() / V, &why)) {
    result.termination = Termination::kFailed;
    result.message = "the first step did not converge: " + why;
    result.profiles.push_back(make_profile(model_, current.state, 0.0, {}));
    finish_result(seconds_since(t_start), &result);
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
    StepRecord rec;
    rec.step = step;
    rec.punch_travel_mm = T;
    rec.punch_force_N = current.punch_force;
    rec.iterations = current.summary.iterations;
    rec.residual_norm = current.summary.residual_norm;
    rec.update_norm = current.summary.update_norm;
    rec.cutbacks = cutbacks_since_success;
    fill_geometry(model_, current.state, &rec);
    result.steps.push_back(rec);
    note_squeeze(current.state);
    result.total_iterations += rec.iterations;
    result.max_condition_estimate =
        std::max(result.max_condition_estimate, current.summary.condition_estimate);
    if (options_.on_step) options_.on_step(rec);
    while (next_output < outputs.size() && std::abs(outputs[next_output] - T) <= 1e-9 * total) {
      result.profiles.push_back(
          make_profile(model_, current.state, T, current.resultants, current.punch_node_force));
      ++next_output;
    }
    if (scene_.output.history)
      result.history.push_back(
          make_profile(model_, current.state, T, current.resultants, current.punch_node_force));
    if (T >= total * (1.0 - 1e-12)) break;

    // Next configuration, with cut-back on failure.
    Solved next;
    bool ok = false;
    cutbacks_since_success = 0;
    const std::vector<double> holds_before = hold_until_mm_;
    while (!ok) {
      const auto t0 = Clock::now();
      const double dt = choose_dt(current, cap_factor, nullptr);
      timings_.contact_s += seconds_since(t0);
      ok = take_step(current, dt, &next, &why);
      if (ok) break;
      if (cutbacks_since_success >= scene_.numerics.max_cutbacks) {
        result.termination = Termination::kFailed;
        result.message = fmt::format("stopped at punch travel {:.4f} mm after {} cut-backs: {}", T,
                                     cutbacks_since_success, why);
        result.profiles.push_back(
            make_profile(model_, current.state, T, current.resultants, current.punch_node_force));
        finish_result(seconds_since(t_start), &result);
        return result;
      }
      if (options_.verbose) {
        std::fprintf(stderr, "  cut-back at travel %.5f mm: %s\n", T, why.c_str());
      }
      ++cutbacks_since_success;
      ++result.total_cutbacks;
      cap_factor *= 0.5;
      // The released set belongs to `current`; a retry must not inherit the failed attempt's.
      released_.assign(model_.num_nodes(), 0);
      hold_until_mm_ = holds_before;
    }
    cap_factor = std::min(1.0, 2.0 * cap_factor);
    // Steps that do not advance the punch (contact events piling up at one instant) must not go
    // on for ever: a run that cannot leave an instant stops with the reason.
    stalled_steps = travel(next.state) - T < 1e-6 * travel_increment() ? stalled_steps + 1 : 0;
    if (stalled_steps >= kMaxStalledSteps) {
      result.termination = Termination::kFailed;
      result.message = fmt::format(
          "stopped at punch travel {:.4f} mm: {} consecutive steps advanced the punch by less than "
          "1e-6 of the travel increment (contact events pile up at one instant)",
          T, stalled_steps);
      current = std::move(next);
      break;
    }
    steps_with_cutbacks = cutbacks_since_success > 0 ? steps_with_cutbacks + 1 : 0;
    if (steps_with_cutbacks >= kMaxStepsWithCutbacks) {
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
  result.profiles.push_back(make_profile(model_, current.state, travel(current.state),
                                         current.resultants, current.punch_node_force));
  if (result.completed()) {
    result.message = fmt::format("completed: punch travel {:.4f} mm in {} steps",
                                 travel(current.state), result.steps.size());
  }
  finish_result(seconds_since(t_start), &result);
  return result;
}

}  // namespace

RunResult simulate_axisymmetric(const Scene& scene, const RunOptions& options) {
  Driver driver(scene, options);
  return driver.run();
}

}  // namespace vs
