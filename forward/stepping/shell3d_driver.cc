// The 3D shell geometry behind the one step driver (stepping/step_driver.h): the forming model's
// state, its contact search and release (mesh neighbours, patch sums, sticking pull-off), the
// sparse solve (full-step evaluation, chord steps, friction refresh), the nodal thickness from the
// area stretch, and the output stages of a run.
#include "stepping/shell3d_driver.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "contact/overlap_monitor.h"
#include "element/lagrange9.h"
#include "element/quadrature.h"
#include "model/forming_fields.h"
#include "model/forming_model.h"
#include "model/forming_step.h"
#include "model/ironing.h"
#include "run/built_components.h"
#include "stepping/step_driver.h"
#include "stepping/travel_grid.h"

namespace vs::shell3d {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A converged configuration: state plus what the step control needs.
struct Solved {
  FormingState state;
  double punch_force = 0.0;
  double max_rate = 0.0;
  std::vector<std::vector<double>> point_rates;
  std::vector<std::vector<Mat3>> membrane;  // per element and in-plane point, global [N/mm]
  NewtonSummary summary;
};

// Rotates the unit vector d by the rotation vector phi (Rodrigues).
Vec3 rotate(const Vec3& d, const Vec3& phi) {
  const double angle = phi.norm();
  if (angle == 0.0) return d;
  return Eigen::AngleAxisd(angle, phi / angle) * d;
}

}  // namespace

double shortest_element_size(const FormingModel& model) {
  double shortest = std::numeric_limits<double>::infinity();
  const std::vector<Vec3>& x0 = model.mesh().nodes;
  const Rule1D q = gauss_legendre(3);
  for (const auto& el : model.mesh().elements) {
    double area = 0.0;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const Shape9 sh = lagrange9(q.x[i], q.x[j]);
        Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
        for (int a = 0; a < 9; ++a) {
          gr += sh.dr(a) * x0[el[a]];
          gs += sh.ds(a) * x0[el[a]];
        }
        area += gr.cross(gs).norm() * q.w[i] * q.w[j];
      }
    shortest = std::min(shortest, std::sqrt(area));
  }
  return shortest;
}

namespace {

class Shell3dStepper {
 public:
  using State = FormingState;
  using Solved = shell3d::Solved;

  Shell3dStepper(const Scene& scene, const RunOptions& options, const StepDriverOptions& driver)
      : scene_(scene), options_(options), driver_(driver), model_(scene) {
    contact_tol_ = driver.contact_tolerance * scene.blank.thickness_mm;
    attach_tol_ = driver.attach_tolerance * scene.blank.thickness_mm;
    punch_attach_tol_ = driver.punch_attach_tolerance * scene.blank.thickness_mm;
    nl_.kind = scene.numerics.solver;
    nl_.tolerance = scene.numerics.tolerance;
    nl_.max_iterations = scene.numerics.max_iterations;
    nl_.verbose = options.verbose;
    set_newton_force_scales(driver, model_.hardening().curve_stress(0.0), scene.blank.thickness_mm,
                            scene.blank.radius_mm, &nl_);
    // Assembly costs more than a potential here: the full Newton step is evaluated completely.
    // Chord steps: measured on ex4a (n = 4, punch friction 0.2, 10 mm, speed setting):
    // factorisations 572 -> 280 with the same answers; the Newton tail of the regularised
    // Coulomb friction converges only linearly, so a reused factorisation loses little per
    // iteration there. Accepting any non-growing chord update stalled (contraction 0.93 over 100
    // iterations); a chord start of 1e-2 / 3e-2 / 1e-1 gave 1 133 / 1 057 / 989 factorisations
    // over 30 mm at equal run time (more residual evaluations).
    nl_.full_step_evaluation = true;
    nl_.chord_start = 3e-2;
    nl_.chord_contraction = 0.5;
    // Krylov steps on the held factorisation (solver/newton.h). Measured on ex4a (friction 0.2,
    // implicit at 0.25 element lengths, no events; quiet 2-core machine): n = 16 to 30 mm,
    // 758 -> 127 factorisations and 171 -> 91 s wall with the same outputs to 4 digits; to
    // 10 mm, at most 6 / 10 / 15 CG iterations: 42 / 38 / 48 s, floor 3e-3 / 1e-2 / 3e-2:
    // 37.0 / 38.0 / 39.7 s. Re-measured with the capped CHOLMOD teams and the single-precision
    // preconditioner (a CG iteration ~1.7 ms at n = 16 against 68 ms for a factorisation): at
    // most 10 / 16 / 24 iterations, 16.2 / 16.6 / 16.4 s to 10 mm.
    nl_.krylov_max_iterations = model_.num_dofs() >= options.krylov_min_unknowns ? 10 : 0;
    nl_.krylov_tolerance = 1e-2;
    linear_.set_parallel_factorisation(options.parallel_factorisation);
    // The single-precision factor with the Krylov steps: below, a run keeps the exact path.
    linear_.set_single_precision_preconditioner(options.single_precision_preconditioner &&
                                                nl_.krylov_max_iterations > 0);
    fields_->mesh = model_.mesh();
  }

  // --- the Stepper interface of step_driver.h
  int num_nodes() const { return model_.num_nodes(); }
  int num_unknowns() const { return model_.num_dofs(); }
  bool contact_eligible(int node) const { return model_.contact_eligible(node); }
  bool in_contact(const FormingState& s, int node) const { return s.contact[node].tool >= 0; }
  // The spacing of the travel grid is the smaller of the absolute cap and the cap relative to
  // the smallest initial element size, the stability limit of the explicit geometry update
  // (mechanism switching in the nearly rigid regions makes the load curve jitter above it).
  // Measured on ex4a sticking, n = 4, 8-20 mm: the step-to-step force jitter is 0.64 % rms on
  // the old 0.5 mm grid, 0.31 % at 0.05 element sizes, 0.18 % at the default 0.025
  // (experiments/05_shell3d).
  double shortest_element_mm() const { return shortest_element_size(model_); }
  void set_grid_increment(double mm) {
    grid_increment_mm_ = mm;
    model_.set_squeeze_correction_time(ironing_correction_time_s(scene_, mm));
  }
  FormingState initial_state() const { return model_.initial_state(); }
  void place_tools(const FormingState& s) { model_.place_tools(s); }
  void maintain_contacts(FormingState& s, const ContactHolds& holds);
  bool solve(Solved* out, double dt_predicted, const std::vector<double>* hardening_from,
             ContactHolds& holds, std::string* why);
  double contact_time(const FormingState& s, int node, double horizon) const;
  void move(const Solved& from, double dt, FormingState* to) const;
  bool update_thickness(FormingState& s, std::string* why) const;
  Solved blend(const Solved& a, const Solved& b, double w) const;
  void couple_geometry(const Solved* ref, double scale_s) {
    if (!ref) {
      model_.set_geometry_coupling(nullptr);
      return;
    }
    coupling_.scale_s = scale_s;
    coupling_.membrane = ref->membrane;
    coupling_.v_ref = ref->state.velocity;
    model_.set_geometry_coupling(&coupling_);
  }
  void set_tolerance(double tolerance) { nl_.tolerance = tolerance; }
  void attach_touching(const FormingState& predicted, FormingState* corrected,
                       const ContactHolds& holds);
  void start_from(const Solved& from, Solved* to) const {
    to->state.velocity = from.state.velocity;
    to->state.omega = from.state.omega;
  }
  const std::vector<double>& eps_bar(const FormingState& s) const { return s.eps_bar; }
  StepRecord record(const Solved& s) const;
  void output(const Solved& s, double /*travel*/, RunResult* /*result*/) {
    fields_->stages.push_back(stage(s));
  }
  void history(const Solved& /*s*/, double /*travel*/, RunResult* /*result*/) const {}
  void observe(const Solved& s) {
    if (fields_->initial.x.empty()) fields_->initial = stage(s);  // zero travel
    note_overlaps(s.state);
  }
  void start(RunResult* result) const;
  void finish(RunResult* result) const;

 private:
  void attach(FormingState& s, int node, int tool) const;
  double travel(const FormingState& s) const {
    return s.time_s * scene_.process.punch_speed_mm_per_s;
  }
  ShellStage stage(const Solved& solved) const;
  // Contact nodes that overlap a second tool (not the holder) beyond the tolerance.
  void note_overlaps(const FormingState& s);

  const Scene& scene_;
  RunOptions options_;
  StepDriverOptions driver_;
  std::shared_ptr<ShellFields> fields_ = std::make_shared<ShellFields>();
  FormingModel model_;
  GeometryCoupling3 coupling_;  // the implicit update's, while couple_geometry() has set it
  SparseCholeskySolver linear_;
  NewtonOptions nl_;
  double grid_increment_mm_ = 0.0;
  double contact_tol_ = 0.0;
  double attach_tol_ = 0.0;
  double punch_attach_tol_ = 0.0;
  double assembly_s_ = 0.0, factorisation_s_ = 0.0;
  int factorisations_ = 0;
  int krylov_steps_ = 0, krylov_iterations_ = 0;
  mutable double contact_s_ = 0.0;
  OverlapMonitor overlaps_{scene_.blank.thickness_mm};  // a sheet squeezed through a second tool
};

void Shell3dStepper::note_overlaps(const FormingState& s) {
  const auto t0 = Clock::now();
  const auto& tools = model_.tools();
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const NodeContact3& c = s.contact[i];
    if (c.tool < 0 || c.sandwiched) continue;
    for (int t = 0; t < static_cast<int>(tools.size()); ++t) {
      if (t == c.tool || tools[t].kind() == ToolKind::kBlankHolder) continue;
      const double overlap = -model_.project(t, s.x[i], s.thickness[i], model_.on_axis(i)).gap;
      overlaps_.note(
          travel(s), overlap, tools[c.tool].name(), tools[t].name(),
          [&] {
            const Vec3& x0 = model_.initial_position(i);
            return fmt::format("initial position ({:.3g}, {:.3g}) mm", x0.x(), x0.y());
          },
          c.squeeze_tool == t);
    }
  }
  contact_s_ += seconds_since(t0);
}

void Shell3dStepper::attach(FormingState& s, int node, int tool) const {
  const auto p = model_.project(tool, s.x[node], s.thickness[node], model_.on_axis(node));
  NodeContact3& c = s.contact[node];
  const double keep = c.tool == tool ? c.normal_force_N : 0.0;
  const NodeContact3 before = c;
  c = NodeContact3{};
  if (before.tool == tool) {  // the holder and squeeze state is kept while the node stays on it
    c.holder_force_N = before.holder_force_N;
    c.squeeze_tool = before.squeeze_tool;
    c.clearance_mm = before.clearance_mm;
    c.squeeze_force_N = before.squeeze_force_N;
  }
  c.tool = tool;
  c.normal = p.normal;
  c.normal_force_N = keep;
  c.on_die_face = p.on_die_face;
  s.x[node] = p.surface_point;
}

void Shell3dStepper::maintain_contacts(FormingState& s, const ContactHolds& holds) {
  const auto t0 = Clock::now();
  const int nn = model_.num_nodes();
  const int nt = static_cast<int>(model_.tools().size());
  for (int i = 0; i < nn; ++i) {
    if (!model_.contact_eligible(i)) continue;
    if (s.contact[i].tool >= 0) {
      if (model_.past_holder_edge(s, i)) {
        s.contact[i] = NodeContact3{};
        continue;
      }
      attach(s, i, s.contact[i].tool);  // back onto the surface, normal refreshed
      continue;
    }
    if (!holds.may_touch(i, travel(s))) continue;
    int best = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    for (int t = 0; t < nt; ++t) {
      if (holds.defers(model_.tools()[t].sticking())) continue;
      const double g = model_.project(t, s.x[i], s.thickness[i], model_.on_axis(i)).gap;
      // Holes inside a contact patch are filled within a small fraction of the thickness (as
      // the axisymmetric driver does): a node most of whose neighbours touch this tool; within a
      // larger one on a punch (StepDriverOptions::punch_attach_tolerance).
      int touching = 0;
      const auto& nb = model_.neighbours(i);
      for (int j : nb) touching += s.contact[j].tool == t ? 1 : 0;
      const bool next_to_patch = 2 * touching > static_cast<int>(nb.size());
      const double tol = !next_to_patch                 ? contact_tol_
                         : model_.tools()[t].is_punch() ? punch_attach_tol_
                                                        : attach_tol_;
      if (g <= tol && g < best_gap) {
        best_gap = g;
        best = t;
      }
    }
    if (best >= 0) attach(s, i, best);
  }
  contact_s_ += seconds_since(t0);
}

bool Shell3dStepper::solve(Solved* out, double dt_predicted,
                           const std::vector<double>* hardening_from, ContactHolds& holds,
                           std::string* why) {
  FormingState& s = out->state;
  model_.place_tools(s);
  // Backward Euler hardens the Heun predictor from the start of the step, as the axisymmetric
  // stepper (FormingModel::freeze_material); the midpoint weight, kept for comparison, hardens
  // from the state's own eps_bar.
  model_.freeze_material(
      hardening_from != nullptr && model_.hardening_theta() == 1.0 ? *hardening_from : s.eps_bar,
      dt_predicted);
  holds.new_solve(model_.num_nodes());
  constexpr double kStickingPullOff = 0.25;
  for (int round = 0; round < driver_.max_contact_rounds; ++round) {
    model_.update_holder(&s);  // the flange on the die face may have changed (released nodes)
    model_.update_squeezed(&s);
    const std::vector<char> last_mask = model_.prescribed_mask();
    model_.prepare(s);
    FormingStepProblem problem(model_, &s, &linear_);
    Eigen::VectorXd x = problem.start();
    // The last factorisation (of the previous round, or of the previous solve: the Heun
    // predictor's for the corrector, the last step's for the predictor) starts the solve with
    // chord steps when the constraints are the same (solver/newton.h); the nodal frames
    // differ slightly, which only makes it a chord. Measured on ex4a (n = 4, friction 0.2,
    // 30 mm, speed setting): 1 311 -> 1 133 factorisations, the same answers.
    const bool reuse = last_mask == model_.prescribed_mask();
    out->summary = solve_newton(problem, nl_, &x, reuse);
    assembly_s_ += out->summary.assembly_s;
    factorisation_s_ += out->summary.factorisation_s;
    factorisations_ += out->summary.factorisations;
    krylov_steps_ += out->summary.krylov_steps;
    krylov_iterations_ += out->summary.krylov_iterations;
    if (!out->summary.converged) {
      *why = out->summary.message;
      return false;
    }
    problem.finish(x);
    model_.to_global(x, &s.velocity, &s.omega);
    // Contact release (active-set check): a node at the edge of its patch leaves the tool when
    // the normal contact force of its element patch (its own reaction plus those of every node
    // sharing an element with it and touching the same tool) pulls on the tool. The nodal
    // normal reactions of 9-node elements pressed onto a curved tool alternate in sign (corner /
    // midside / centre; with sticking friction they are small differences of the tangential
    // reactions, which carry the membrane tension); releasing on the raw reaction breaks the
    // patch up. The threshold is relative to the largest full reaction, and a tool never loses
    // its last contact nodes in one round (the problem would lose its load).
    // Sticking contact: the stuck material is rigid (stresses at the cut-off level), so the load
    // enters the patch as a tangential line force at its edge and the normal reactions there are
    // small differences of order round-off of the discretisation; a sticking node is released only
    // when the patch's normal force pulls off by more than kStickingPullOff of the patch's full
    // reaction (measured on ex4a: any smaller threshold makes the patch edge chatter).
    const auto t0 = Clock::now();
    const std::vector<double>& N = problem.normal_reactions();
    const std::vector<double>& F = problem.reaction_magnitudes();
    double scale = 0.0;
    for (double v : F) scale = std::max(scale, v);
    const int ntools = static_cast<int>(model_.tools().size());
    std::vector<double> smoothed(model_.num_nodes(), 0.0);
    std::vector<int> candidates;
    std::vector<int> kept_per_tool(ntools, 0);
    std::vector<double> best_per_tool(ntools, -std::numeric_limits<double>::infinity());
    for (int i = 0; i < model_.num_nodes(); ++i) {
      const int tool = s.contact[i].tool;
      if (tool < 0) continue;
      double sum = N[i], full = F[i];
      int other = 0;
      for (int j : model_.neighbours(i)) {
        if (s.contact[j].tool == tool) {
          sum += N[j];
          full += F[j];
        } else if (model_.contact_eligible(j)) {
          ++other;
        }
      }
      smoothed[i] = sum;
      best_per_tool[tool] = std::max(best_per_tool[tool], smoothed[i]);
      const double threshold = driver_.release_fraction * scale +
                               (model_.tools()[tool].sticking() ? kStickingPullOff * full : 0.0);
      // A node sandwiched in a fixed gap, or squeezed between two tools, touches both faces
      // whatever its reaction on one.
      if (other > 0 && smoothed[i] < -threshold && !s.contact[i].sandwiched &&
          s.contact[i].squeeze_tool < 0 && holds.may_release(model_.tools()[tool].sticking())) {
        candidates.push_back(i);
      } else {
        ++kept_per_tool[tool];
      }
    }
    std::vector<int> release;
    for (int i : candidates) {
      const int tool = s.contact[i].tool;
      const bool last =
          kept_per_tool[tool] == 0 && smoothed[i] >= best_per_tool[tool] - 1e-9 * (scale + 1.0);
      if (!last) release.push_back(i);
    }
    std::vector<int> released_per_tool(options_.verbose ? ntools : 0, 0);
    for (int i : release) {
      if (options_.verbose) ++released_per_tool[s.contact[i].tool];
      s.contact[i] = NodeContact3{};
      holds.release(i, travel(s), driver_.hold_off_increments * grid_increment_mm_);
    }
    contact_s_ += seconds_since(t0);
    if (options_.verbose) {
      std::string by_tool;
      for (int t = 0; t < ntools; ++t) {
        if (released_per_tool[t] == 0) continue;
        by_tool += fmt::format("{}{} {}", by_tool.empty() ? " (" : ", ", model_.tools()[t].name(),
                               released_per_tool[t]);
      }
      if (!by_tool.empty()) by_tool += ")";
      std::fprintf(
          stderr,
          "  contact round %d: %d iterations (%d Newton, %d chord, %d direct), %zu released%s\n",
          round, out->summary.iterations, out->summary.newton_steps, out->summary.chord_steps,
          out->summary.picard_steps, release.size(), by_tool.c_str());
    }
    if (release.empty()) {
      // Fixed-gap holder: the pressure of this converged state sets the holder forces (and so the
      // friction on both flange faces) of the next solve (lagged, as the axisymmetric driver).
      if (model_.fixed_gap_holder()) model_.update_gap_holder_forces(x, &s);
      model_.update_squeeze_forces(x, &s);  // ironing: lagged the same way
      out->punch_force = problem.punch_force();
      out->max_rate = problem.max_point_rate();
      out->point_rates = problem.point_rates();
      out->membrane = problem.membrane_forces();
      return true;
    }
  }
  *why = "contact active set did not settle";
  return false;
}

double Shell3dStepper::contact_time(const FormingState& s, int i, double horizon) const {
  // Contact events (eqs. 81-85 corrected): a free node against every tool, in the tool's
  // meridian plane (r, z); the circumferential velocity does not change the gap of an
  // axisymmetric tool to first order. (Timed by the step driver's contact-event search.)
  const Vec3& x = s.x[i];
  const Vec3& v = s.velocity[i];
  const double r = model_.on_axis(i) ? 0.0 : std::hypot(x.x(), x.y());
  const double vr = r > 0.0 ? (x.x() * v.x() + x.y() * v.y()) / r : 0.0;
  double dt = std::numeric_limits<double>::infinity();
  for (const RigidTool& tool : model_.tools()) {
    dt = std::min(dt, tool.contact_time(Eigen::Vector2d(r, x.z()), Eigen::Vector2d(vr, v.z()),
                                        s.thickness[i], horizon));
  }
  return dt;
}

bool Shell3dStepper::update_thickness(FormingState& s, std::string* why) const {
  // Exact incompressibility of the mid-surface at each node (numerics.md 3.6 in 3D; see
  // FormingModel::area_stretch).
  const std::vector<double> stretch = model_.area_stretch(s.x);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const double h = model_.initial_thickness() / stretch[i];
    if (!(h > 0.0) || !std::isfinite(h)) {
      *why = fmt::format("node {} degenerated (thickness {:.3g} mm)", i, h);
      return false;
    }
    // The same limits as the axisymmetric model (StepDriverOptions): beyond them a membrane-shell
    // answer means nothing.
    const double h0 = model_.initial_thickness();
    if (h < driver_.min_thickness_ratio * h0 || h > driver_.max_thickness_ratio * h0) {
      const Vec3& p = model_.initial_position(i);
      *why = fmt::format(
          "node {} (initial position x {:.3g}, y {:.3g} mm) reached thickness {:.3g} mm = {:.3g} "
          "x initial, outside [{}, {}] x initial: {}",
          i, p.x(), p.y(), h, h / h0, driver_.min_thickness_ratio, driver_.max_thickness_ratio,
          thickness_limit_reason(h, h0, driver_, shortest_element_mm(), "divisions"));
      return false;
    }
    s.thickness[i] = h;
  }
  return true;
}

void Shell3dStepper::move(const Solved& from, double dt, FormingState* to) const {
  FormingState& s = *to;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    s.x[i] += dt * from.state.velocity[i];
    s.director[i] = rotate(from.state.director[i], dt * from.state.omega[i]).normalized();
  }
  for (std::size_t t = 0; t < s.tool_offset.size(); ++t) {
    s.tool_offset[t] += dt * model_.tools()[t].velocity();
  }
  const std::size_t fp = static_cast<std::size_t>(model_.flow_points());
  for (std::size_t e = 0; e < from.point_rates.size(); ++e) {
    for (std::size_t k = 0; k < fp; ++k) s.eps_bar[e * fp + k] += dt * from.point_rates[e][k];
  }
  s.time_s += dt;
}

Solved Shell3dStepper::blend(const Solved& a, const Solved& b, double w) const {
  Solved mid;
  mid.state = a.state;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    mid.state.velocity[i] = (1.0 - w) * a.state.velocity[i] + w * b.state.velocity[i];
    mid.state.omega[i] = (1.0 - w) * a.state.omega[i] + w * b.state.omega[i];
  }
  mid.point_rates = blend_point_rates(a.point_rates, b.point_rates, w);
  return mid;
}

void Shell3dStepper::attach_touching(const FormingState& predicted, FormingState* corrected,
                                     const ContactHolds& /*holds*/) {
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const int tool = predicted.contact[i].tool;
    if (tool >= 0 && corrected->contact[i].tool < 0 && model_.contact_eligible(i)) {
      attach(*corrected, i, tool);
    }
  }
}

StepRecord Shell3dStepper::record(const Solved& cur) const {
  const FormingState& s = cur.state;
  StepRecord rec;
  const std::vector<double> area = model_.lumped_areas(s.x);
  double volume = 0.0;
  int thinnest = 0;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    rec.contact_nodes += s.contact[i].tool >= 0 ? 1 : 0;
    volume += s.thickness[i] * area[i];
    if (s.thickness[i] < s.thickness[thinnest]) thinnest = i;
  }
  rec.volume_mm3 = model_.symmetry_factor() * volume;
  rec.min_thickness_mm = s.thickness[thinnest];
  const Vec3& x0 = model_.initial_position(thinnest);
  rec.thinnest_r0_mm = std::hypot(x0.x(), x0.y());
  rec.thinnest_r_mm = std::hypot(s.x[thinnest].x(), s.x[thinnest].y());
  // Draw-in: mean inward displacement of the outer edge, measured along the initial radius.
  const auto& edge = model_.mesh().set("edge");
  double draw = 0.0;
  for (int i : edge) {
    const Vec3& p0 = model_.initial_position(i);
    const double r0 = std::hypot(p0.x(), p0.y());
    draw += (p0 - s.x[i]).head<2>().dot(p0.head<2>() / r0);
  }
  rec.rim_draw_in_mm = edge.empty() ? 0.0 : draw / static_cast<double>(edge.size());
  return rec;
}

ShellStage Shell3dStepper::stage(const Solved& solved) const {
  const FormingState& s = solved.state;
  ShellStage st;
  st.punch_travel_mm = travel(s);
  st.x = s.x;
  st.thickness_mm = s.thickness;
  st.contact_tool.resize(s.contact.size());
  for (std::size_t i = 0; i < s.contact.size(); ++i) st.contact_tool[i] = s.contact[i].tool;
  const int fp = model_.flow_points(), nt = model_.thickness_points(), nip = fp / nt;
  st.eps_effective.assign(model_.num_elements(), 0.0);
  st.effective_stress_MPa.assign(model_.num_elements(), 0.0);
  for (int e = 0; e < model_.num_elements(); ++e) {
    double sum = 0.0, stress = 0.0;
    for (int ip = 0; ip < nip; ++ip) {
      const int k = ip * nt + nt / 2;
      const double eps_bar = s.eps_bar[static_cast<std::size_t>(e * fp + k)];
      sum += eps_bar;
      const double rate =
          static_cast<std::size_t>(e) < solved.point_rates.size()
              ? solved.point_rates[static_cast<std::size_t>(e)][static_cast<std::size_t>(k)]
              : 0.0;
      stress += model_.law().effective_stress(model_.hardening().flow_stress(eps_bar), rate);
    }
    st.eps_effective[e] = sum / nip;
    st.effective_stress_MPa[e] = stress / nip;
  }
  return st;
}

void Shell3dStepper::start(RunResult* result) const {
  result->geometry = Geometry::kShell3d;
  result->dofs = model_.num_dofs();
  result->built.push_back(fmt::format(
      "model: 3D 9-node viscous shell ({}), {} blank, {} elements, {} nodes, {} unknowns, {} "
      "thickness points",
      scene_.numerics.element_rule == ShellElementRule::kMitc9 ? "MITC9" : "paper selective rule",
      scene_.blank.symmetry == BlankSymmetry::kFull ? "full" : "quarter", model_.num_elements(),
      model_.num_nodes(), model_.num_dofs(), model_.thickness_points()));
  result->built.push_back(
      "nonlinear solver: primal-dual Newton with full-step evaluation and chord steps "
      "(solver/newton.h)");
  result->built.push_back(
      fmt::format("linear solver: {} (sparse, fixed pattern, analysis once)",
                  auto_sparse_solver(model_.num_dofs()) == SparseSolverKind::kCholmodSupernodal
                      ? "CHOLMOD supernodal LL^T"
                      : "Eigen SimplicialLDLT"));
  result->built.push_back(model_.planar() != nullptr
                              ? "material: " + model_.planar()->description +
                                    " (material axes convected with the sheet per flow point)"
                              : fmt::format("material: Hill 1948 with normal anisotropy R = {}",
                                            scene_.material.r_value));
  for (std::string& line : tool_components(scene_)) result->built.push_back(std::move(line));
  // As the axisymmetric stepper: a shell discretisation finer than the thickness resolves nothing
  // real. The measure is the element size sqrt(A_e) (two node intervals of a 9-node element).
  const double size = shortest_element_mm();
  if (size < scene_.blank.thickness_mm) {
    result->warnings.push_back(fmt::format(
        "smallest element size {:.3g} mm is shorter than the thickness {:.3g} mm: contact "
        "reactions oscillate and strain profiles become noisy; use fewer divisions",
        size, scene_.blank.thickness_mm));
  }
}

void Shell3dStepper::finish(RunResult* result) const {
  for (std::string& w : overlaps_.warnings()) result->warnings.push_back(std::move(w));
  result->timings.assembly_s = assembly_s_;
  result->timings.linear_solve_s = factorisation_s_;
  result->timings.factorisations = factorisations_;
  result->timings.krylov_steps = krylov_steps_;
  result->timings.krylov_iterations = krylov_iterations_;
  result->timings.factorisation_fallbacks = linear_.solver().fallbacks();
  result->timings.contact_s += contact_s_;
  const double h0 = scene_.blank.thickness_mm;
  // As the axisymmetric profiles: one set per output travel reached, then the final state (which
  // may repeat the last output travel).
  for (const ShellStage& st : fields_->stages) {
    for (Profile& p : shell_profiles(fields_->mesh, st, h0))
      result->profiles.push_back(std::move(p));
  }
  result->shell = fields_;
}

}  // namespace

RunResult simulate_shell3d(const Scene& scene, const RunOptions& options) {
  return run_stepper<Shell3dStepper>(scene, options);
}

}  // namespace vs::shell3d
