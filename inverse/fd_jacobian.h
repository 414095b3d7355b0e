// Finite-difference Jacobian of a residual vector, with steps relative to each parameter's
// scale and all perturbed evaluations handed over as one batch (so the caller can run them in
// parallel). Near a bound the stencil becomes one-sided instead of stepping outside: a forward
// model is often undefined there (negative friction, n > 1). A perturbed run that fails on one
// side is retried one-sided on the other side (second batch) before the Jacobian gives up.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vs {

enum class FdMethod {
  kCentral,  // (r(x+h) - r(x-h)) / 2h: 2 runs per parameter, error O(h^2) + noise/h
  kRidders,  // Richardson extrapolation of central differences at h, h/2, ...: 2L runs per
             // parameter; more accurate for a smooth model, no help against solver noise
};

struct FdOptions {
  FdMethod method = FdMethod::kCentral;
  // Step = relative_step * scale. Forward-solver noise eps_s gives an error ~ eps_s / step, the
  // truncation ~ step^2 x the curvature of the outputs over the parameter's scale. The
  // textbook optimum eps_s^(1/3) (2e-3 at eps_s = 1e-8) assumes a curvature of order one; the
  // forming outputs are nearly linear over a few % of each parameter, and the measured fits
  // (data/calibration/README.md, "Status": the bundled examples at 0.002, 0.01, 0.05 and 0.1)
  // need the fewest forward runs at 0.05 (54 against 72 at 2e-3 for the four-parameter fit,
  // 12 against 9 for friction alone, same results to 1e-5) and a Jacobian whose noise error is
  // 25x smaller, which matters when the lead's faster forward defaults raise eps_s.
  double relative_step = 0.05;
  int ridders_levels = 3;  // Ridders: steps h, h/2, ..., h/2^(levels-1)

  bool IsValid(std::string* why) const;
};

// Evaluates residual vectors at a batch of points; std::nullopt marks a failed evaluation.
using BatchResiduals =
    std::function<std::vector<std::optional<Eigen::VectorXd>>(const std::vector<Eigen::VectorXd>&)>;

struct FdJacobian {
  bool ok = false;
  std::string message;       // which parameter's perturbation failed
  Eigen::MatrixXd jacobian;  // d residual / d x, m x p, in the units of x
};

// `residual_at_x` is r(x) (already known, not re-evaluated). Bounds may be infinite.
FdJacobian fd_jacobian(const Eigen::VectorXd& x, const Eigen::VectorXd& residual_at_x,
                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                       const Eigen::VectorXd& scale, const FdOptions& options,
                       const BatchResiduals& evaluate);

}  // namespace vs
