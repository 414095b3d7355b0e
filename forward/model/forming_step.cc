#include "model/forming_step.h"

#include <algorithm>

namespace vs::shell3d {

double FormingStepProblem::evaluate(const Eigen::VectorXd& x, double theta,
                                    Eigen::VectorXd* residual, double* potential) {
  model_.evaluate(*state_, x, theta > 0.0 ? Shell9Stiffness::kTangent : Shell9Stiffness::kSecant,
                  theta, &sys_);
  *residual = sys_.residual;
  *potential = sys_.potential;
  return sys_.internal_force.norm();
}

double FormingStepProblem::evaluate_residual(const Eigen::VectorXd& x, Eigen::VectorXd* residual,
                                             double* potential) {
  model_.evaluate(*state_, x, Shell9Stiffness::kNone, 0.0, &sys_);
  *residual = sys_.residual;
  *potential = sys_.potential;
  return sys_.internal_force.norm();
}

void FormingStepProblem::reactions(const Eigen::VectorXd& f, std::vector<double>* normal,
                                   std::vector<double>* magnitude) const {
  const int nn = model_.num_nodes();
  normal->assign(nn, 0.0);
  if (magnitude) magnitude->assign(nn, 0.0);
  const ShellModel& m = model_.shell_model();
  for (int i = 0; i < nn; ++i) {
    const NodeContact3& c = state_->contact[i];
    if (c.tool < 0) continue;
    const Vec3 fg = model_.frame(i) * f.segment<3>(m.dof(i, 0));
    (*normal)[i] = fg.dot(c.normal);
    if (magnitude) (*magnitude)[i] = fg.norm();
  }
}

bool FormingStepProblem::update_lagged(const Eigen::VectorXd& /*x*/) {
  // Only Coulomb contact uses the normal forces.
  bool friction = false;
  for (const NodeContact3& c : state_->contact) {
    if (c.tool < 0) continue;
    const RigidTool& t = model_.tools()[c.tool];
    friction = friction || (!t.sticking() && t.friction() > 0.0);
  }
  if (!friction) return false;
  std::vector<double> n;
  reactions(sys_.internal_force - sys_.external_force, &n);
  const int nn = model_.num_nodes();
  if (relax_.size() != static_cast<std::size_t>(nn)) {
    relax_.assign(nn, 1.0);
    last_change_.assign(nn, 0.0);
  }
  for (int i = 0; i < nn; ++i) {
    NodeContact3& c = state_->contact[i];
    const double change = n[i] - c.normal_force_N;
    relax_[i] = change * last_change_[i] < 0.0 ? std::max(0.125, 0.5 * relax_[i])
                                               : std::min(1.0, 1.5 * relax_[i]);
    last_change_[i] = change;
    c.normal_force_N += relax_[i] * change;
  }
  return true;
}

bool FormingStepProblem::refresh(const Eigen::VectorXd& x, Eigen::VectorXd* residual,
                                 double* potential) {
  model_.refresh_friction(*state_, x, &sys_);
  *residual = sys_.residual;
  *potential = sys_.potential;
  return true;
}

Eigen::VectorXd FormingStepProblem::start() const {
  Eigen::VectorXd x = model_.to_local(state_->velocity, state_->omega);
  const auto& mask = model_.prescribed_mask();
  const auto& value = model_.prescribed_value();
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (mask[static_cast<std::size_t>(k)]) x(k) = value[static_cast<std::size_t>(k)];
  return x;
}

void FormingStepProblem::finish(const Eigen::VectorXd& x) {
  FormingSystem sys;
  model_.evaluate(*state_, x, Shell9Stiffness::kNone, 0.0, &sys);
  // The tools' reactions balance the element forces minus the holder loads (a flange node's die
  // reaction carries the holder force).
  const Eigen::VectorXd reaction = sys.internal_force - sys.external_force;
  reactions(reaction, &normal_, &magnitude_);
  const ShellModel& m = model_.shell_model();
  punch_force_ = 0.0;
  for (int i = 0; i < model_.num_nodes(); ++i) {
    if (state_->contact[i].tool != model_.punch_index()) continue;
    punch_force_ += (model_.frame(i) * reaction.segment<3>(m.dof(i, 0))).z();
  }
  punch_force_ *= model_.symmetry_factor();
  // Ironing: a squeezed node's reaction also carries the friction of its second face.
  punch_force_ += model_.squeeze_punch_friction_z();
  model_.point_rates(*state_, x, &rates_, &membrane_);
  max_rate_ = 0.0;
  for (const auto& r : rates_)
    for (double v : r) max_rate_ = std::max(max_rate_, v);
}

}  // namespace vs::shell3d
