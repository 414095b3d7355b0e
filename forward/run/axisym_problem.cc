#include "run/axisym_problem.h"

#include <algorithm>

namespace vs {

double AxisymStepProblem::evaluate(const Eigen::VectorXd& x, double theta, BlockTridiag* K,
                                   Eigen::VectorXd* residual) {
  model_.evaluate(*state_, x, theta > 0.0 ? StiffnessKind::kTangent : StiffnessKind::kSecant,
                  &sys_, theta);
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
  (void)x;
  std::vector<double> n;
  reactions(sys_, &n);
  for (int i = 0; i < model_.num_nodes(); ++i) state_->contact[i].normal_force_N = n[i];
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
  // Effective strain rates at every thickness point (for hardening and the step size).
  const Eigen::VectorXd v = model_.to_global(*state_, x);
  point_rates_.assign(model_.num_elements(), {});
  max_rate_ = 0.0;
  const ThicknessRule& rule = model_.rule();
  const ViscousLaw& law = model_.law();
  for (int e = 0; e < model_.num_elements(); ++e) {
    const Vec5 g = axisym2_B(model_.geometry(*state_, e)) * v.segment<6>(3 * e);
    const double h = state_->thickness[e];
    auto& pr = point_rates_[e];
    pr.resize(rule.zeta.size());
    for (std::size_t k = 0; k < rule.zeta.size(); ++k) {
      const double z = rule.zeta[k] * h;
      pr[k] = law.effective_rate(Eigen::Vector2d(g(0) + z * g(2), g(1) + z * g(3)));
      max_rate_ = std::max(max_rate_, pr[k]);
    }
  }
}

}  // namespace vs
