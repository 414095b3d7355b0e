#include "shell3d/forming/forming_driver.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "run/built_components.h"
#include "run/travel_grid.h"
#include "shell3d/forming/forming_fields.h"
#include "shell3d/forming/forming_model.h"
#include "shell3d/forming/forming_step.h"
#include "shell3d/lagrange9.h"
#include "shell3d/quadrature.h"

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

class Driver {
 public:
  Driver(const Scene& scene, const RunOptions& options)
      : scene_(scene), options_(options), model_(scene) {
    contact_tol_ = 1e-8 * scene.blank.thickness_mm;
    attach_tol_ = 1e-2 * scene.blank.thickness_mm;
    nl_.kind = scene.numerics.solver;
    nl_.tolerance = scene.numerics.tolerance;
    nl_.max_iterations = scene.numerics.max_iterations;
    nl_.verbose = options.verbose;
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
    // Steps end on a fixed travel grid, as in the axisymmetric driver (forward/run/simulate.cc):
    // the spacing is the smaller of the absolute cap and the cap relative to the smallest initial
    // element size, the stability limit of the explicit geometry update (mechanism switching in
    // the nearly rigid regions makes the load curve jitter above it). Measured on ex4a sticking,
    // n = 4, 8-20 mm: the step-to-step force jitter is 0.64 % rms on the old 0.5 mm grid, 0.31 %
    // at 0.05 element sizes, 0.18 % at the default 0.025 (experiments/05_shell3d).
    grid_increment_mm_ =
        std::min(scene.numerics.max_travel_increment_mm,
                 scene.numerics.max_travel_increment_per_length * shortest_element_size(model_));
    targets_ = travel_grid(scene.process.punch_travel_mm, grid_increment_mm_,
                           scene.process.output_travels_mm);
  }

  RunResult run();

 private:
  void attach(FormingState& s, int node, int tool) const;
  void maintain_contacts(FormingState& s) const;
  bool solve(Solved* out, double dt_predicted, std::string* why);
  bool advance(const Solved& from, double dt, FormingState* to, std::string* why);
  bool update_thickness(FormingState& s, std::string* why) const;
  bool take_step(const Solved& from, double dt, Solved* to, std::string* why);
  double choose_dt(const Solved& from, double cap_factor) const;
  double travel(const FormingState& s) const {
    return s.time_s * scene_.process.punch_speed_mm_per_s;
  }
  StepRecord record(const Solved& s, int step, int cutbacks) const;
  ShellStage stage(const FormingState& s) const;
  RunResult finish(RunResult result, Clock::time_point t_start);

  const Scene& scene_;
  RunOptions options_;
  std::shared_ptr<ShellFields> fields_ = std::make_shared<ShellFields>();
  FormingModel model_;
  SparseCholeskySolver linear_;
  NewtonOptions nl_;
  std::vector<double> targets_;
  double grid_increment_mm_ = 0.0;
  double contact_tol_ = 0.0;
  double attach_tol_ = 0.0;
  std::vector<char> released_;  // nodes released by the last solve (no immediate re-contact)
  double assembly_s_ = 0.0, factorisation_s_ = 0.0;
  int factorisations_ = 0;
  mutable double contact_s_ = 0.0;
};

void Driver::attach(FormingState& s, int node, int tool) const {
  const auto p = model_.project(tool, s.x[node], s.thickness[node], model_.on_axis(node));
  NodeContact3& c = s.contact[node];
  const double keep = c.tool == tool ? c.normal_force_N : 0.0;
  c = NodeContact3{};
  c.tool = tool;
  c.normal = p.normal;
  c.normal_force_N = keep;
  c.on_die_face = p.on_die_face;
  s.x[node] = p.surface_point;
}

void Driver::maintain_contacts(FormingState& s) const {
  const auto t0 = Clock::now();
  const int nn = model_.num_nodes();
  const int nt = static_cast<int>(model_.tools().size());
  for (int i = 0; i < nn; ++i) {
    if (!model_.contact_eligible(i)) continue;
    if (s.contact[i].tool >= 0) {
      attach(s, i, s.contact[i].tool);  // back onto the surface, normal refreshed
      continue;
    }
    if (!released_.empty() && released_[i]) continue;
    int best = -1;
    double best_gap = std::numeric_limits<double>::infinity();
    for (int t = 0; t < nt; ++t) {
      const double g = model_.project(t, s.x[i], s.thickness[i], model_.on_axis(i)).gap;
      // Holes inside a contact patch are filled within a small fraction of the thickness (as
      // the axisymmetric driver does): a node most of whose neighbours touch this tool.
      int touching = 0;
      const auto& nb = model_.neighbours(i);
      for (int j : nb) touching += s.contact[j].tool == t ? 1 : 0;
      const double tol = 2 * touching > static_cast<int>(nb.size()) ? attach_tol_ : contact_tol_;
      if (g <= tol && g < best_gap) {
        best_gap = g;
        best = t;
      }
    }
    if (best >= 0) attach(s, i, best);
  }
  contact_s_ += seconds_since(t0);
}

bool Driver::solve(Solved* out, double dt_predicted, std::string* why) {
  FormingState& s = out->state;
  model_.place_tools(s);
  model_.freeze_material(s, dt_predicted);
  released_.assign(model_.num_nodes(), 0);
  constexpr int kMaxRounds = 20;
  constexpr double kReleaseFraction = 1e-4;
  constexpr double kStickingPullOff = 0.25;
  for (int round = 0; round < kMaxRounds; ++round) {
    model_.update_holder(&s);  // the flange on the die face may have changed (released nodes)
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
      const double threshold = kReleaseFraction * scale +
                               (model_.tools()[tool].sticking() ? kStickingPullOff * full : 0.0);
      if (other > 0 && smoothed[i] < -threshold) {
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
    for (int i : release) {
      s.contact[i] = NodeContact3{};
      released_[i] = 1;
    }
    contact_s_ += seconds_since(t0);
    if (options_.verbose) {
      std::fprintf(
          stderr,
          "  contact round %d: %d iterations (%d Newton, %d chord, %d direct), %zu released\n",
          round, out->summary.iterations, out->summary.newton_steps, out->summary.chord_steps,
          out->summary.picard_steps, release.size());
    }
    if (release.empty()) {
      out->punch_force = problem.punch_force();
      out->max_rate = problem.max_point_rate();
      out->point_rates = problem.point_rates();
      return true;
    }
  }
  *why = "contact active set did not settle";
  return false;
}

double Driver::choose_dt(const Solved& from, double cap_factor) const {
  const auto t0 = Clock::now();
  const double cap =
      cap_factor * step_to_next_target(targets_, travel(from.state),
                                       scene_.process.punch_speed_mm_per_s,
                                       scene_.numerics.max_strain_increment, from.max_rate);
  // Next contact event (eqs. 81-85 corrected): every free node against every tool, in the
  // tool's meridian plane (r, z); the circumferential velocity does not change the gap of an
  // axisymmetric tool to first order.
  const double frac = scene_.numerics.step_fraction;
  const double horizon = cap / frac;
  double dt_event = std::numeric_limits<double>::infinity();
  const FormingState& s = from.state;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (!model_.contact_eligible(i) || s.contact[i].tool >= 0 || released_[i]) continue;
    const Vec3& x = s.x[i];
    const Vec3& v = s.velocity[i];
    const double r = model_.on_axis(i) ? 0.0 : std::hypot(x.x(), x.y());
    const double vr = r > 0.0 ? (x.x() * v.x() + x.y() * v.y()) / r : 0.0;
    for (const RigidTool& tool : model_.tools()) {
      dt_event = std::min(dt_event,
                          tool.contact_time(Eigen::Vector2d(r, x.z()), Eigen::Vector2d(vr, v.z()),
                                            s.thickness[i], horizon));
    }
  }
  contact_s_ += seconds_since(t0);
  if (dt_event <= cap) return std::max(dt_event, 1e-12 * cap);
  if (std::isfinite(dt_event)) return std::min(cap, frac * dt_event);
  return cap;
}

bool Driver::update_thickness(FormingState& s, std::string* why) const {
  // Exact incompressibility of the mid-surface at each node (numerics.md 3.6 in 3D; see
  // FormingModel::area_stretch).
  const std::vector<double> stretch = model_.area_stretch(s.x);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const double h = model_.initial_thickness() / stretch[i];
    if (!(h > 0.0) || !std::isfinite(h)) {
      *why = fmt::format("node {} degenerated (thickness {:.3g} mm)", i, h);
      return false;
    }
    s.thickness[i] = h;
  }
  return true;
}

bool Driver::advance(const Solved& from, double dt, FormingState* to, std::string* why) {
  *to = from.state;
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
  model_.place_tools(s);
  maintain_contacts(s);
  return update_thickness(s, why);
}

bool Driver::take_step(const Solved& from, double dt, Solved* to, std::string* why) {
  if (scene_.numerics.time_integration == TimeIntegration::kEuler) {
    return advance(from, dt, &to->state, why) && solve(to, dt, why);
  }
  // Heun: predict with the start velocity, solve there, redo the update with the mean of both
  // velocities, director angular velocities and strain rates (second order, as vs::simulate).
  Solved pred;
  if (!advance(from, dt, &pred.state, why) || !solve(&pred, dt, why)) return false;
  const std::vector<char> released_pred = released_;
  Solved mid;
  mid.state = from.state;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    mid.state.velocity[i] = 0.5 * (from.state.velocity[i] + pred.state.velocity[i]);
    mid.state.omega[i] = 0.5 * (from.state.omega[i] + pred.state.omega[i]);
  }
  mid.point_rates = from.point_rates;
  for (std::size_t e = 0; e < mid.point_rates.size(); ++e) {
    for (std::size_t k = 0; k < mid.point_rates[e].size(); ++k) {
      mid.point_rates[e][k] = 0.5 * (from.point_rates[e][k] + pred.point_rates[e][k]);
    }
  }
  released_ = released_pred;
  if (!advance(mid, dt, &to->state, why)) return false;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const int tool = pred.state.contact[i].tool;
    if (tool >= 0 && to->state.contact[i].tool < 0 && model_.contact_eligible(i)) {
      attach(to->state, i, tool);
    }
  }
  if (!update_thickness(to->state, why)) return false;
  to->state.velocity = pred.state.velocity;
  to->state.omega = pred.state.omega;
  return solve(to, dt, why);
}

StepRecord Driver::record(const Solved& cur, int step, int cutbacks) const {
  const FormingState& s = cur.state;
  StepRecord rec;
  rec.step = step;
  rec.time_s = s.time_s;
  rec.punch_travel_mm = travel(s);
  rec.punch_force_N = cur.punch_force;
  rec.iterations = cur.summary.iterations;
  rec.residual_norm = cur.summary.residual_norm;
  rec.update_norm = cur.summary.update_norm;
  rec.cutbacks = cutbacks;
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

ShellStage Driver::stage(const FormingState& s) const {
  ShellStage st;
  st.punch_travel_mm = travel(s);
  st.x = s.x;
  st.thickness_mm = s.thickness;
  st.contact_tool.resize(s.contact.size());
  for (std::size_t i = 0; i < s.contact.size(); ++i) st.contact_tool[i] = s.contact[i].tool;
  const int fp = model_.flow_points(), nt = model_.thickness_points(), nip = fp / nt;
  st.eps_effective.assign(model_.num_elements(), 0.0);
  for (int e = 0; e < model_.num_elements(); ++e) {
    double sum = 0.0;
    for (int ip = 0; ip < nip; ++ip)
      sum += s.eps_bar[static_cast<std::size_t>(e * fp + ip * nt + nt / 2)];
    st.eps_effective[e] = sum / nip;
  }
  return st;
}

RunResult Driver::finish(RunResult result, Clock::time_point t_start) {
  result.timings.total_s = seconds_since(t_start);
  result.timings.assembly_s = assembly_s_;
  result.timings.linear_solve_s = factorisation_s_;
  result.timings.factorisations = factorisations_;
  result.timings.contact_s = contact_s_;
  const double h0 = scene_.blank.thickness_mm;
  // As the axisymmetric profiles: one set per output travel reached, then the final state (which
  // may repeat the last output travel).
  for (const ShellStage& st : fields_->stages) {
    for (Profile& p : shell_profiles(fields_->mesh, st, h0))
      result.profiles.push_back(std::move(p));
  }
  result.shell = fields_;
  return result;
}

constexpr int kMaxStepsWithCutbacks = 25;

RunResult Driver::run() {
  const auto t_start = Clock::now();
  RunResult result;
  result.geometry = Geometry::kShell3d;
  fields_->mesh = model_.mesh();
  result.dofs = model_.num_dofs();
  result.built.push_back(fmt::format(
      "model: 3D 9-node viscous shell ({}), {} blank, {} elements, {} nodes, {} unknowns, {} "
      "thickness points",
      scene_.numerics.element_rule == ShellElementRule::kMitc9 ? "MITC9" : "paper selective rule",
      scene_.blank.symmetry == BlankSymmetry::kFull ? "full" : "quarter", model_.num_elements(),
      model_.num_nodes(), model_.num_dofs(), model_.thickness_points()));
  result.built.push_back(
      "nonlinear solver: primal-dual Newton with full-step evaluation and chord steps "
      "(solver/newton.h)");
  result.built.push_back(fmt::format(
      "linear solver: {} (sparse, fixed pattern, analysis once)",
      model_.num_dofs() < kAutoCholmodDofs ? "Eigen SimplicialLDLT" : "CHOLMOD supernodal LL^T"));
  for (std::string& line : tool_components(scene_)) result.built.push_back(std::move(line));
  Solved current;
  current.state = model_.initial_state();
  model_.place_tools(current.state);
  maintain_contacts(current.state);
  std::string why;
  const double V = scene_.process.punch_speed_mm_per_s;
  if (!solve(&current, grid_increment_mm_ / V, &why)) {
    result.termination = Termination::kFailed;
    result.message = "the first step did not converge: " + why;
    fields_->stages.push_back(stage(current.state));
    return finish(std::move(result), t_start);
  }
  const double total = scene_.process.punch_travel_mm;
  const auto& outputs = scene_.process.output_travels_mm;
  std::size_t next_output = 0;
  double cap_factor = 1.0;
  int cutbacks = 0, steps_with_cutbacks = 0;
  for (int step = 0;; ++step) {
    const double T = travel(current.state);
    const StepRecord rec = record(current, step, cutbacks);
    result.steps.push_back(rec);
    result.total_iterations += rec.iterations;
    if (options_.on_step) options_.on_step(rec);
    while (next_output < outputs.size() && std::abs(outputs[next_output] - T) <= 1e-9 * total) {
      fields_->stages.push_back(stage(current.state));
      ++next_output;
    }
    if (T >= total * (1.0 - 1e-12)) break;
    Solved next;
    bool ok = false;
    cutbacks = 0;
    while (!ok) {
      const double dt = choose_dt(current, cap_factor);
      ok = take_step(current, dt, &next, &why);
      if (ok) break;
      if (cutbacks >= scene_.numerics.max_cutbacks) {
        result.termination = Termination::kFailed;
        result.message = fmt::format("stopped at punch travel {:.4f} mm after {} cut-backs: {}", T,
                                     cutbacks, why);
        fields_->stages.push_back(stage(current.state));
        return finish(std::move(result), t_start);
      }
      if (options_.verbose) {
        std::fprintf(stderr, "  cut-back at travel %.5f mm: %s\n", T, why.c_str());
      }
      ++cutbacks;
      ++result.total_cutbacks;
      cap_factor *= 0.5;
      released_.assign(model_.num_nodes(), 0);
    }
    cap_factor = std::min(1.0, 2.0 * cap_factor);
    steps_with_cutbacks = cutbacks > 0 ? steps_with_cutbacks + 1 : 0;
    current = std::move(next);
    if (steps_with_cutbacks >= kMaxStepsWithCutbacks) {
      result.termination = Termination::kFailed;
      result.message = fmt::format(
          "stopped at punch travel {:.4f} mm: {} consecutive steps needed cut-backs (last: {}); "
          "the step size keeps collapsing",
          travel(current.state), steps_with_cutbacks, why);
      break;
    }
  }
  fields_->stages.push_back(stage(current.state));
  if (result.completed()) {
    result.message = fmt::format("completed: punch travel {:.4f} mm in {} steps",
                                 travel(current.state), result.steps.size());
  }
  return finish(std::move(result), t_start);
}

}  // namespace

RunResult simulate_shell3d(const Scene& scene, const RunOptions& options) {
  Driver driver(scene, options);
  return driver.run();
}

}  // namespace vs::shell3d
