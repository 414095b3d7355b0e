#include "run/axisym_problem.h"

#include <algorithm>

namespace vs {

double AxisymStepProblem::evaluate(const Eigen::VectorXd& x, double theta, BlockTridiag* K,
                                   Eigen::VectorXd* residual) {
  model_.evaluate(*state_, x, theta > 0.0 ? StiffnessKind::kTangent : StiffnessKind::kSecant, &sys_,
                  theta);
  std::swap(*K, sys_.K);
  *residual = sys_.residual;
  return sys_.element_force.norm();
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

void AxisymStepProblem::update_lagged(const Eigen::VectorXd& x) {
  // Reactions of the iterate just evaluated (one iteration behind x), as in the paper's nodal
  // stick/slip check at the end of each iteration, each node's update relaxed.
  (void)x;
  std::vector<double> n;
  reactions(sys_, &n);
  const int nn = model_.num_nodes();
  if (relax_.size() != static_cast<std::size_t>(nn)) {
    relax_.assign(nn, 1.0);
    last_change_.assign(nn, 0.0);
  }
  for (int i = 0; i < nn; ++i) {
    NodeContact& c = state_->contact[i];
    relaxed_update(n[i], &c.normal_force_N, &relax_[i], &last_change_[i]);
  }
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
  AxisymSystem sys;
  model_.evaluate(*state_, x, StiffnessKind::kNone, &sys);
  reactions(sys, &normal_);
  if (model_.fixed_gap_holder()) holder_forces_ = model_.holder_forces_from_gap(*state_, sys);
  punch_force_ = 0.0;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (state_->contact[i].tool == model_.punch_index()) {
      punch_force_ += model_.node_force(sys, i).y();
    }
  }
  // Effective strain rates at every thickness point (for hardening and the step size) and the
  // stress resultants (for outputs and equilibrium checks).
  model_.element_states(*state_, x, &point_rates_, &resultants_);
  max_rate_ = 0.0;
  for (const auto& pr : point_rates_) {
    for (double r : pr) max_rate_ = std::max(max_rate_, r);
  }
}

}  // namespace vs
