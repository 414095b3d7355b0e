#include "objective.h"

#include <optional>

namespace vs {

Objective::Objective(ForwardCache* cache, FdOptions fd) : cache_(cache), fd_(fd) {
  const auto& free = cache_->free_indices();
  const auto p = static_cast<Eigen::Index>(free.size());
  lower_.resize(p);
  upper_.resize(p);
  scale_.resize(p);
  initial_.resize(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    const ParameterSpec& spec = cache_->parameters()[free[i]];
    lower_[i] = spec.lower;
    upper_[i] = spec.upper;
    scale_[i] = spec.scale;
    initial_[i] = spec.initial;
    names_.push_back(spec.address);
  }
}

FdJacobian Objective::jacobian(const Eigen::VectorXd& x, const std::vector<bool>& held) {
  const auto center = cache_->evaluate(x);
  if (!center->ok) {
    FdJacobian failed;
    failed.message = center->message;
    return failed;
  }
  BatchResiduals batch = [this](const std::vector<Eigen::VectorXd>& points) {
    std::vector<std::optional<Eigen::VectorXd>> values;
    for (const auto& e : cache_->evaluate_batch(points)) {
      values.push_back(e->ok ? std::optional<Eigen::VectorXd>(e->residuals) : std::nullopt);
    }
    return values;
  };
  // A held column gets an empty interval at x: fd_jacobian leaves it zero without a run.
  Eigen::VectorXd lower = lower_, upper = upper_;
  for (std::size_t j = 0; j < held.size(); ++j) {
    if (!held[j]) continue;
    lower[static_cast<Eigen::Index>(j)] = x[static_cast<Eigen::Index>(j)];
    upper[static_cast<Eigen::Index>(j)] = x[static_cast<Eigen::Index>(j)];
  }
  return fd_jacobian(x, center->residuals, lower, upper, scale_, fd_, batch);
}

}  // namespace vs
