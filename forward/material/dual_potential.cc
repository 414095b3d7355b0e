#include "material/dual_potential.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace vs {
namespace {

// The ray through s0 scaled to the minimum of J along it: c = dhat . s0 / sigma_bar(s0)^2.
bool scale_to_ray_minimum(const PlaneStressYield& yield, const PlaneVector& dhat, PlaneVector& s) {
  const double sb = yield.effective_stress(s);
  const double proj = dhat.dot(s);
  if (!(sb > 0.0) || !(proj > 0.0)) return false;
  s *= proj / (sb * sb);
  return true;
}

}  // namespace

DualPoint solve_dual(const PlaneStressYield& yield, const PlaneVector& d, const PlaneVector* guess,
                     const DualSolveOptions& options) {
  // |d| without overflow or underflow of the squares (near-rigid points have tiny rates).
  const double d_max = d.cwiseAbs().maxCoeff();
  const double d_norm = d_max > 0.0 ? d_max * (d / d_max).norm() : 0.0;
  PlaneVector dhat(1.0, 1.0, 0.0);
  dhat /= std::sqrt(2.0);
  if (d_norm > 0.0) {
    dhat = (d / d_max).normalized();
  } else if (guess != nullptr && yield.effective_stress(*guess) > 0.0) {
    dhat = yield.evaluate(*guess).gradient.normalized();
  }

  PlaneVector s = PlaneVector::Zero();
  bool started = false;
  if (guess != nullptr) {
    s = *guess;
    started = scale_to_ray_minimum(yield, dhat, s);
  }
  if (!started) {
    PlaneMatrix von_mises_dual;  // 3 P^-1 of von Mises (R = 1): the paper's D1 / mu
    von_mises_dual << 4.0, 2.0, 0.0, 2.0, 4.0, 0.0, 0.0, 0.0, 1.0;
    s = von_mises_dual * dhat;
    scale_to_ray_minimum(yield, dhat, s);
  }

  DualPoint out;
  out.converged = false;
  YieldPoint p = yield.evaluate(s);
  PlaneMatrix K;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (int it = 0;; ++it) {
    const PlaneVector F = p.value * p.gradient - dhat;  // grad J
    K = p.gradient * p.gradient.transpose() + p.value * p.hessian;
    out.iterations = it;
    if (F.norm() <= options.tolerance) {
      out.converged = true;
      break;
    }
    if (it >= options.max_iterations) break;
    PlaneVector step = -K.ldlt().solve(F);
    if (!step.allFinite() || !(step.dot(F) < 0.0)) step = -F;  // steepest descent safeguard
    // Backtracking on the convex J, with a round-off allowance so that the last quadratic steps
    // (which change J by less than its rounding) are taken in full.
    const double J0 = 0.5 * p.value * p.value - dhat.dot(s);
    const double slope = F.dot(step);
    const double slack = 8.0 * kEps * (std::abs(J0) + p.value * p.value);
    double alpha = 1.0;
    for (int k = 0; k < 40; ++k) {
      const PlaneVector trial = s + alpha * step;
      const double sb = yield.effective_stress(trial);
      if (0.5 * sb * sb - dhat.dot(trial) <= J0 + 1e-4 * alpha * slope + slack) break;
      alpha *= 0.5;
    }
    s += alpha * step;
    p = yield.evaluate(s);
  }

  // s* = g(dhat): e(dhat) = sigma_bar(s*), m = s* / sigma_bar(s*), H = K^-1 (header comment).
  out.rate = d_norm * p.value;
  if (d_norm > 0.0 && p.value > 0.0) out.direction = s / p.value;
  const PlaneMatrix H = K.inverse();
  out.hessian = 0.5 * (H + H.transpose());
  return out;
}

}  // namespace vs
