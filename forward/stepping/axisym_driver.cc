// The axisymmetric geometry behind the one step driver (stepping/step_driver.h): the meridian
// model's state, its contact search and release (chain neighbours, the axis node, sticking patch
// edges, fixed-gap holder and squeeze bookkeeping), the solve with consistent friction and its
// lagged fallback, the element thickness from volume, and the profiles and warnings of a run.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "contact/overlap_monitor.h"
#include "core/error.h"
#include "model/axisym_model.h"
#include "model/axisym_problem.h"
#include "model/ironing.h"
#include "run/built_components.h"
#include "run/simulate.h"
#include "stepping/axisym_observe.h"
#include "stepping/step_driver.h"
#include "stepping/travel_grid.h"

namespace vs {

namespace {

// Iterations allowed to a solve with consistent friction before it is redone with lagged friction.
constexpr int kConsistentIterations = 30;

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

class AxisymStepper {
 public:
  using State = AxisymState;
  using Solved = vs::Solved;

  AxisymStepper(const Scene& scene, const RunOptions& options, const StepDriverOptions& driver)
      : scene_(scene), options_(options), driver_(driver), model_(scene) {
    model_.set_consistent_friction(options.consistent_friction);
    contact_tol_ = driver.contact_tolerance * scene.blank.thickness_mm;
    attach_tol_ = driver.attach_tolerance * scene.blank.thickness_mm;
    nl_.kind = scene.numerics.solver;
    nl_.tolerance = scene.numerics.tolerance;
    nl_.max_iterations = scene.numerics.max_iterations;
    nl_.verbose = options.verbose;
    set_newton_force_scales(driver, model_.hardening().curve_stress(0.0), scene.blank.thickness_mm,
                            scene.blank.radius_mm, &nl_);
  }

  // --- the Stepper interface of step_driver.h
  int num_nodes() const { return model_.num_nodes(); }
  int num_unknowns() const { return model_.num_dofs(); }
  bool contact_eligible(int node) const {
    return !(node == model_.num_nodes() - 1 && scene_.blank.edge != EdgeCondition::kFree);
  }
  bool in_contact(const AxisymState& s, int node) const { return s.contact[node].tool >= 0; }
  double shortest_element_mm() const {
    double shortest = std::numeric_limits<double>::infinity();
    for (int e = 0; e < model_.num_elements(); ++e)
      shortest = std::min(shortest, model_.initial_length(e));
    return shortest;
  }
  void set_grid_increment(double mm) {
    grid_increment_mm_ = mm;
    model_.set_squeeze_correction_time(ironing_correction_time_s(scene_, mm));
  }
  AxisymState initial_state() const { return model_.initial_state(); }
  void place_tools(const AxisymState& s) { model_.place_tools(s); }
  void maintain_contacts(AxisymState& s, const ContactHolds& holds);
  // dt_predicted: step size expected after this solve (for the hardening seen by the solve);
  // hardening_from: the effective strains the solve's hardening starts from (null: the
  // state's own).
  bool solve(Solved* out, double dt_predicted, const std::vector<double>* hardening_from,
             ContactHolds& holds, std::string* why);
  double contact_time(const AxisymState& s, int node, double horizon) const;
  void move(const Solved& from, double dt, AxisymState* to) const;
  // Element thickness from its constant volume and current geometry; false if degenerate.
  bool update_thickness(AxisymState& s, std::string* why) const;
  Solved blend(const Solved& a, const Solved& b, double w) const;
  void couple_geometry(const Solved* ref, double scale_s) {
    if (!ref) {
      model_.set_geometry_coupling(nullptr);
      return;
    }
    coupling_.scale_s = scale_s;
    coupling_.resultants = ref->resultants;
    coupling_.v_ref = ref->state.v;
    model_.set_geometry_coupling(&coupling_);
  }
  void set_tolerance(double tolerance) { nl_.tolerance = tolerance; }
  void attach_touching(const AxisymState& predicted, AxisymState* corrected,
                       const ContactHolds& holds);
  void start_from(const Solved& from, Solved* to) const {
    to->state.v = from.state.v;
    to->directions = from.directions;
  }
  const std::vector<double>& eps_bar(const AxisymState& s) const { return s.eps_bar; }
  StepRecord record(const Solved& s) const {
    StepRecord rec;
    fill_geometry(model_, s.state, &rec);
    return rec;
  }
  void output(const Solved& s, double travel, RunResult* result) const {
    result->profiles.push_back(
        make_profile(model_, s.state, travel, s.resultants, s.punch_node_force));
  }
  void history(const Solved& s, double travel, RunResult* result) const {
    result->history.push_back(
        make_profile(model_, s.state, travel, s.resultants, s.punch_node_force));
  }
  // Squeeze check of a converged state: a node in contact with one tool whose other surface
  // lies inside another tool by more than 2 % of the thickness, i.e. more than the ironing
  // constraint (AxisymModel::update_squeezed) lets through: the run says so.
  void observe(const Solved& s) { note_squeeze(s.state); }
  void start(RunResult* result) const;
  // Timings, counters and the squeeze warnings into the result, on every way out of the run.
  void finish(RunResult* result) const;

 private:
  void note_squeeze(const AxisymState& s);
  void attach(AxisymState& s, int node, int tool, const ContactHolds& holds);
  double travel(const AxisymState& s) const {
    return s.time_s * scene_.process.punch_speed_mm_per_s;
  }

  const Scene& scene_;
  RunOptions options_;
  StepDriverOptions driver_;
  AxisymModel model_;
  NewtonOptions nl_;
  GeometryCoupling coupling_;  // the implicit update's, while couple_geometry() has set it
  double grid_increment_mm_ = 0.0;
  double contact_tol_ = 0.0;  // gap below which a node touches a tool
  double attach_tol_ = 0.0;   // search tolerance next to a touching neighbour
  RunTimings timings_;
  int friction_fallbacks_ = 0;                          // solves redone with lagged friction
  OverlapMonitor overlaps_{scene_.blank.thickness_mm};  // a sheet squeezed through a second tool
  // First ironed element longer than kIroningElementRatio initial thicknesses (travel, length).
  double coarse_ironing_travel_mm_ = -1.0, coarse_ironing_length_mm_ = 0.0;
};

// Ironing thins a squeezed element as a whole (AxisymModel::add_squeeze); on elements longer than
// this many thicknesses the ironing force is overestimated (measured, ex3: 13 elements of 4.1
// thicknesses spike the punch force to 66.6 kN at 37.5 mm against 38.7-40.0 kN with 26-52
// elements of 1.1-2.1 thicknesses).
constexpr double kIroningElementRatio = 3.0;

void AxisymStepper::attach(AxisymState& s, int node, int tool, const ContactHolds& holds) {
  const RigidTool& t = model_.tools()[tool];
  const ClosestPoint c = t.closest(s.x[node]);
  NodeContact& nc = s.contact[node];
  const double keep_force = nc.tool == tool ? nc.normal_force_N : 0.0;
  // A node that left a sticking tool (its reaction pulled) and touches it again is the edge of
  // the stuck patch: stuck, it pulls; free, it runs into the tool (measured: ex1 sticking, one
  // attach-release round at every step). The consistent state is touching with zero reaction
  // and zero friction, so it slides without friction until both neighbours touch the tool.
  const bool slip =
      t.sticking() && (nc.tool == tool ? nc.slip_edge : holds.was_released[node] != 0);
  const NodeContact before = nc;
  nc = NodeContact{};
  nc.tool = tool;
  nc.slip_edge = slip;
  if (before.tool == tool) {  // the squeeze state is kept while the node stays on its tool
    nc.holder_force_N = before.holder_force_N;
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

void AxisymStepper::maintain_contacts(AxisymState& s, const ContactHolds& holds) {
  model_.place_tools(s);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (!contact_eligible(i)) continue;
    if (s.contact[i].tool >= 0) {
      const RigidTool& t = model_.tools()[s.contact[i].tool];
      // A node that has run past the inner edge of a fixed-gap holder's face leaves it (the
      // closest point would be the edge itself, and re-attaching there would pin the node).
      if (t.kind() == ToolKind::kBlankHolder && s.x[i].x() < t.profile().front().p0.x()) {
        s.contact[i] = NodeContact{};
        continue;
      }
      attach(s, i, s.contact[i].tool, holds);  // back onto the surface, normal refreshed
      if (s.contact[i].slip_edge) {
        const int ti = s.contact[i].tool;
        const bool axis = i == 0 && model_.initial_radius(0) == 0.0;
        const bool next = i + 1 < model_.num_nodes() && s.contact[i + 1].tool == ti;
        const bool prev = axis ? next : i > 0 && s.contact[i - 1].tool == ti;
        if (next && prev) s.contact[i].slip_edge = false;  // inside the patch now: stuck
      }
      continue;
    }
    if (!holds.may_touch(i, travel(s))) continue;
    int best = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < model_.tools().size(); ++t) {
      if (holds.defers(model_.tools()[t].sticking())) continue;
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
    if (best >= 0) attach(s, i, best, holds);
  }
}

bool AxisymStepper::solve(Solved* out, double dt_predicted,
                          const std::vector<double>* hardening_from, ContactHolds& holds,
                          std::string* why) {
  AxisymState& s = out->state;
  model_.place_tools(s);
  model_.update_sandwiched(&s);
  model_.update_squeezed(&s);
  model_.freeze_material(hardening_from ? *hardening_from : s.eps_bar, dt_predicted);
  holds.new_solve(model_.num_nodes());
  for (int round = 0; round < driver_.max_contact_rounds; ++round) {
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
      if (smoothed < -driver_.release_fraction * scale &&
          holds.may_release(model_.tools()[tool].sticking())) {
        release.push_back(i);
      }
    }
    for (int i : release) {
      if (options_.verbose) {
        std::fprintf(stderr, "  release node %d (tool %d, r0 %.3g mm, reaction %.4g N)\n", i,
                     s.contact[i].tool, model_.initial_radius(i), N[i]);
      }
      s.contact[i] = NodeContact{};
      holds.release(i, travel(s), driver_.hold_off_increments * grid_increment_mm_);
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

double AxisymStepper::contact_time(const AxisymState& s, int node, double horizon) const {
  const Eigen::Vector2d v = s.v.segment<2>(3 * node);
  const double h = model_.node_thickness(s, node);
  double dt = std::numeric_limits<double>::infinity();
  for (const RigidTool& tool : model_.tools()) {
    dt = std::min(dt, tool.contact_time(s.x[node], v, h, horizon));
  }
  return dt;
}

void AxisymStepper::move(const Solved& from, double dt, AxisymState* to) const {
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
}

Solved AxisymStepper::blend(const Solved& a, const Solved& b, double w) const {
  Solved mid;
  mid.state = a.state;
  mid.state.v = (1.0 - w) * a.state.v + w * b.state.v;
  mid.point_rates = blend_point_rates(a.point_rates, b.point_rates, w);
  return mid;
}

void AxisymStepper::attach_touching(const AxisymState& predicted, AxisymState* corrected,
                                    const ContactHolds& holds) {
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const int tool = predicted.contact[i].tool;
    if (tool >= 0 && corrected->contact[i].tool < 0 && contact_eligible(i)) {
      attach(*corrected, i, tool, holds);
    }
  }
}

bool AxisymStepper::update_thickness(AxisymState& s, std::string* why) const {
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
    if (h < driver_.min_thickness_ratio * h0 || h > driver_.max_thickness_ratio * h0) {
      *why = fmt::format(
          "element {} (initial radius {:.3g} mm) reached thickness {:.3g} mm = {:.3g} x initial, "
          "outside [{}, {}] x initial: {}",
          e, model_.initial_mid_radius(e), h, h / h0, driver_.min_thickness_ratio,
          driver_.max_thickness_ratio,
          thickness_limit_reason(h, h0, driver_, shortest_element_mm(), "elements"));
      return false;
    }
    s.thickness[e] = h;
  }
  return true;
}

void AxisymStepper::note_squeeze(const AxisymState& s) {
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
      overlaps_.note(
          travel(s), -other.gap(s.x[i], h), model_.tools()[c.tool].name(), other.name(),
          [&] { return fmt::format("initial radius {:.3g} mm", model_.initial_radius(i)); },
          c.squeeze_tool == static_cast<int>(t));
    }
  }
}

void AxisymStepper::start(RunResult* result) const {
  result->geometry = Geometry::kAxisymmetric;
  result->dofs = model_.num_dofs();
  result->built.push_back(fmt::format(
      "model: axisymmetric 2-node viscous shell, {} elements, {} unknowns, {} thickness points",
      model_.num_elements(), model_.num_dofs(), model_.rule().zeta.size()));
  result->built.push_back(
      "nonlinear solver: primal-dual Newton with Armijo line search on the flow potential"
      " (solver/newton.h)");
  result->built.push_back(
      "linear solver: block tridiagonal LDL^T (block LU with consistent Coulomb friction)");
  for (std::string& line : tool_components(scene_)) result->built.push_back(std::move(line));
  const double shortest = shortest_element_mm();
  if (shortest < scene_.blank.thickness_mm) {
    // A shell discretisation finer than the thickness resolves nothing real and makes the nodal
    // contact reactions oscillate (measured: ex1 thinning stops converging below l = h).
    result->warnings.push_back(fmt::format(
        "shortest element {:.3g} mm is shorter than the thickness {:.3g} mm: contact reactions "
        "oscillate and strain profiles become noisy; use fewer elements",
        shortest, scene_.blank.thickness_mm));
  }
}

void AxisymStepper::finish(RunResult* result) const {
  result->timings.assembly_s = timings_.assembly_s;
  result->timings.linear_solve_s = timings_.linear_solve_s;
  result->timings.factorisations = timings_.factorisations;
  result->friction_fallbacks = friction_fallbacks_;
  for (std::string& w : overlaps_.warnings()) result->warnings.push_back(std::move(w));
  if (coarse_ironing_travel_mm_ >= 0.0) {
    result->warnings.push_back(fmt::format(
        "from punch travel {:.2f} mm the sheet is ironed on an element {:.3g} mm long, more than "
        "{} initial thicknesses: a coarse element is thinned as a whole, which overestimates the "
        "ironing force; refine the mesh (blank.elements)",
        coarse_ironing_travel_mm_, coarse_ironing_length_mm_, kIroningElementRatio));
  }
}

}  // namespace

RunResult simulate_axisymmetric(const Scene& scene, const RunOptions& options) {
  return run_stepper<AxisymStepper>(scene, options);
}

}  // namespace vs
