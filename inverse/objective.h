// The one objective both optimisers use: residuals of the free parameters (memoised forward
// runs) and their finite-difference Jacobian. The least-squares cost is 0.5 |r|^2.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "fd_jacobian.h"
#include "forward_cache.h"

namespace vs {

class Objective {
 public:
  Objective(ForwardCache* cache, FdOptions fd);

  int num_parameters() const { return cache_->num_free(); }
  int num_residuals() const { return cache_->pipeline().num_residuals(); }
  // Free parameters' bounds, scales, initial values and addresses, in order.
  const Eigen::VectorXd& lower() const { return lower_; }
  const Eigen::VectorXd& upper() const { return upper_; }
  const Eigen::VectorXd& scale() const { return scale_; }
  const Eigen::VectorXd& initial() const { return initial_; }
  const std::vector<std::string>& names() const { return names_; }

  std::shared_ptr<const Evaluation> evaluate(const Eigen::VectorXd& x) {
    return cache_->evaluate(x);
  }
  // d r / d x at x (x must evaluate successfully; its residuals are reused). Columns whose
  // `held` entry is true (parameters held on a bound by the active-set solver) are not
  // differentiated and stay zero: no forward runs are spent on them.
  FdJacobian jacobian(const Eigen::VectorXd& x, const std::vector<bool>& held = {});

  ForwardCache& cache() { return *cache_; }
  const FdOptions& fd_options() const { return fd_; }

 private:
  ForwardCache* cache_;
  FdOptions fd_;
  Eigen::VectorXd lower_, upper_, scale_, initial_;
  std::vector<std::string> names_;
};

}  // namespace vs
