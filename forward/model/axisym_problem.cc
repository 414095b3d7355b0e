#include "model/axisym_problem.h"

#include <algorithm>
#include <utility>

namespace vs {

AxisymStepProblem::AxisymStepProblem(const AxisymModel& model, AxisymState* state)
    : model_(model),
      state_(state),
      ball_(model.law().A()),
      dual_(2 * model.rule().zeta.size() * model.num_elements(), 0.0) {}

AxisymSystem& AxisymStepProblem::elements_at(const Eigen::VectorXd& x, StiffnessKind kind,
                                             const std::vector<double>& n, long n_id,
                                             double theta) {
  for (Slot& slot : slots_) {
    if (!slot.valid || slot.x.size() != x.size() || slot.x != x) continue;
    const AxisymSystem& sys = slot.sys;
    const bool split = sys.element_kind == StiffnessKind::kTangent && sys.element_weight < 0.0;
    const bool serves = kind == StiffnessKind::kTangent
                            ? sys.element_kind == kind && slot.directions_id == n_id &&
                                  (split || sys.element_weight == theta)
                            : sys.element_kind == kind || split;
    if (serves) return slot.sys;
  }
  Slot& slot = slots_[1 - last_];
  slot.x = x;
  model_.evaluate_elements(*state_, x, kind, &slot.sys, &n, theta == 1.0 ? 1.0 : -1.0);
  slot.valid = true;
  slot.directions_id = n_id;
  return slot.sys;
}

double AxisymStepProblem::evaluate(const Eigen::VectorXd& x, double theta,
                                   Eigen::VectorXd* residual, double* potential) {
  const StiffnessKind kind = theta > 0.0 ? StiffnessKind::kTangent : StiffnessKind::kSecant;
  AxisymSystem& sys = elements_at(x, kind, dual_, dual_id_, theta);
  last_ = &sys == &slots_[0].sys ? 0 : 1;
  last_theta_ = theta;
  model_.assemble(*state_, x, kind, &sys, theta);
  // Consistent friction: the residual used N(x); the lag becomes N(x) too, so that the line
  // search's merit is the friction potential with N frozen at this iterate (its gradient here is
  // the residual) and the trial points find the same N.
  bool relagged = false;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    NodeContact& c = state_->contact[i];
    if (c.tool < 0 || !model_.consistent_friction(c)) continue;
    c.normal_force_N = model_.node_force(sys, i).dot(c.normal);
    relagged = true;
  }
  std::swap(linear_.matrix(), sys.K);
  *residual = sys.residual;
  *potential = relagged ? model_.potential(*state_, x, sys) : sys.potential;
  return sys.element_force.norm();
}

void AxisymStepProblem::set_direction(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  // The dual update needs the flow directions and cut-off rates at x: the last evaluation's.
  has_dual_step_ = false;
  trial_alpha_ = -1.0;
  const AxisymSystem& sys = slots_[last_].sys;
  if (sys.element_kind != StiffnessKind::kTangent || slots_[last_].x != x) return;
  model_.point_rate_increments(*state_, dx, &rate_step_);
  const Eigen::Matrix2d& A = model_.law().A();
  dual_step_.resize(dual_.size());
  for (std::size_t k = 0; k < dual_.size(); k += 2) {
    const Eigen::Vector2d m(sys.directions[k], sys.directions[k + 1]);
    const Eigen::Vector2d n(dual_[k], dual_[k + 1]);
    const Eigen::Vector2d dd(rate_step_[k], rate_step_[k + 1]);
    const double eh = sys.cutoff_rates[k / 2];
    // A constant viscosity (eh = 0) has no rank-one part: its directions stay put.
    const Eigen::Vector2d dn =
        eh > 0.0 ? flow_direction_increment(A, m, eh, n, dd) : Eigen::Vector2d::Zero();
    dual_step_[k] = dn(0);
    dual_step_[k + 1] = dn(1);
  }
  has_dual_step_ = true;
}

void AxisymStepProblem::trial_directions(double alpha) {
  trial_alpha_ = alpha;
  if (!has_dual_step_) {
    trial_dual_ = dual_;
    trial_dual_id_ = dual_id_;
    return;
  }
  trial_dual_.resize(dual_.size());
  for (std::size_t k = 0; k < dual_.size(); k += 2) {
    const Eigen::Vector2d v = ball_.project(Eigen::Vector2d(
        dual_[k] + alpha * dual_step_[k], dual_[k + 1] + alpha * dual_step_[k + 1]));
    trial_dual_[k] = v(0);
    trial_dual_[k + 1] = v(1);
  }
  trial_dual_id_ = next_id_++;
}

double AxisymStepProblem::potential(const Eigen::VectorXd& x_trial, double alpha) {
  // Summed with the tangent (at the directions and weight the step would give): if the line
  // search accepts x_trial, the next evaluate() is there and finds these sums.
  trial_directions(alpha);
  // A step from weight 1 keeps weight 1 when accepted; from a smaller one the weight moves on.
  AxisymSystem& sys = elements_at(x_trial, StiffnessKind::kTangent, trial_dual_, trial_dual_id_,
                                  last_theta_ == 1.0 ? 1.0 : -1.0);
  return model_.potential(*state_, x_trial, sys);
}

void AxisymStepProblem::step_taken(double alpha) {
  // Usually the line search's last trial was at this alpha: its directions are the new ones.
  if (!(has_dual_step_ && trial_alpha_ == alpha)) trial_directions(alpha);
  std::swap(dual_, trial_dual_);
  dual_id_ = trial_dual_id_;
  has_dual_step_ = false;
  trial_alpha_ = -1.0;
}

void AxisymStepProblem::reactions(const AxisymSystem& sys, std::vector<double>* normal) const {
  normal->assign(model_.num_nodes(), 0.0);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const NodeContact& c = state_->contact[i];
    if (c.tool >= 0) (*normal)[i] = model_.node_force(sys, i).dot(c.normal);
  }
}

namespace {

// One relaxed step of a lagged nodal force towards its latest value. The lag is a fixed point
// N -> v -> N that can overshoot and oscillate when the regularised friction is steep; the factor
// halves whenever the change reverses sign and grows back while it keeps its sign.
// Floor 0.02 and growth 1.2: the die and holder friction of the cup (ex3) cycles with period ~3
// (which a sign test catches only partly) at floor 0.125 / growth 1.5 and stalled at
// |dx|/|x| ~ 1e-5 after 100 iterations (15.8 mm, travel step 0.025 mm); these values converge
// there with no cut-back and leave ex1/ex2 iteration counts within +-10 %.
void relaxed_update(double target, double* value, double* relax, double* last_change) {
  constexpr double kMin = 0.02;
  constexpr double kGrow = 1.2;
  const double change = target - *value;
  if (change * *last_change < 0.0) {
    *relax = std::max(kMin, 0.5 * *relax);
  } else {
    *relax = std::min(1.0, kGrow * *relax);
  }
  *last_change = change;
  *value += *relax * change;
}

}  // namespace

bool AxisymStepProblem::update_lagged(const Eigen::VectorXd& x) {
  // Reactions of the iterate just evaluated (one iteration behind x), as in the paper's nodal
  // stick/slip check at the end of each iteration, each node's update relaxed.
  (void)x;
  std::vector<double> n;
  reactions(slots_[last_].sys, &n);
  const int nn = model_.num_nodes();
  if (relax_.size() != static_cast<std::size_t>(nn)) {
    relax_.assign(nn, 1.0);
    last_change_.assign(nn, 0.0);
  }
  for (int i = 0; i < nn; ++i) {
    NodeContact& c = state_->contact[i];
    if (c.tool >= 0 && model_.consistent_friction(c)) continue;  // set by evaluate()
    relaxed_update(n[i], &c.normal_force_N, &relax_[i], &last_change_[i]);
  }
  return true;  // the next evaluate() is a new one anyway (no full-step evaluation here)
}

void AxisymStepProblem::warm_start(const std::vector<double>& directions) {
  if (directions.size() != dual_.size()) return;
  dual_ = directions;
  dual_id_ = next_id_++;
}

Eigen::VectorXd AxisymStepProblem::start(const Eigen::VectorXd& v_global) const {
  Eigen::VectorXd x = model_.to_local(*state_, v_global);
  std::vector<char> mask;
  Eigen::VectorXd values;
  model_.prescribed(*state_, &mask, &values);
  for (int k = 0; k < x.size(); ++k) {
    if (mask[k]) x(k) = values(k);
  }
  return x;
}

void AxisymStepProblem::finish(const Eigen::VectorXd& x) {
  // One pass: reactions, and the effective strain rates at every thickness point (for hardening
  // and the step size) and the stress resultants (for outputs and equilibrium checks).
  AxisymSystem sys;
  sys.keep_element_states = true;
  model_.evaluate(*state_, x, StiffnessKind::kNone, &sys);
  reactions(sys, &normal_);
  if (model_.fixed_gap_holder()) holder_forces_ = model_.holder_forces_from_gap(*state_, sys);
  squeeze_forces_ = model_.squeeze_forces(*state_, sys);
  // The punch's force on the sheet: at a node touching it, the node force (element forces minus
  // holder loads: the punch's reaction and friction) plus the friction of a squeezing second tool
  // (which the element forces also balance); at a node the punch squeezes, that friction.
  punch_force_ = 0.0;
  punch_node_forces_.assign(model_.num_nodes(), 0.0);
  for (int i = 0; i < model_.num_nodes(); ++i) {
    const NodeContact& c = state_->contact[i];
    const double f_squeeze = sys.squeeze_friction.empty() ? 0.0 : sys.squeeze_friction[i];
    const Eigen::Vector2d t(c.normal.y(), -c.normal.x());
    if (c.tool == model_.punch_index()) {
      punch_node_forces_[i] = model_.node_force(sys, i).y() + f_squeeze * t.y();
    } else if (c.tool >= 0 && c.squeeze_tool == model_.punch_index()) {
      punch_node_forces_[i] = -f_squeeze * t.y();
    }
    punch_force_ += punch_node_forces_[i];
  }
  point_rates_ = std::move(sys.point_rates);
  resultants_ = std::move(sys.resultants);
  max_rate_ = 0.0;
  for (const auto& pr : point_rates_) {
    for (double r : pr) max_rate_ = std::max(max_rate_, r);
  }
}

}  // namespace vs
