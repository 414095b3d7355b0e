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

void AxisymStepProblem::update_lagged(const Eigen::VectorXd& x) {
  // Reactions of the iterate just evaluated (one iteration behind x), as in the paper's nodal
  // stick/slip check at the end of each iteration.
  // The lag is a fixed point N -> v -> N that can overshoot and oscillate with period two when
  // the regularised friction is steep; each node's update is relaxed, halving the factor whenever
  // its change reverses sign and growing it back while the change keeps its sign.
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
    const double change = n[i] - c.normal_force_N;
    if (change * last_change_[i] < 0.0) {
      relax_[i] = std::max(0.125, 0.5 * relax_[i]);
    } else {
      relax_[i] = std::min(1.0, 1.5 * relax_[i]);
    }
    last_change_[i] = change;
    c.normal_force_N += relax_[i] * change;
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
