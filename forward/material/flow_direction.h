// The flow direction of the viscous law as an unknown of its own: the primal-dual Newton method of
// Chan, Golub & Mulet (SIAM J. Sci. Comput. 20, 1999) for total-variation-like potentials, which
// the rigid-plastic flow potential phi = sigma_y e is.
//
// At a point (viscous_law.h) the stress is s = f(eh) m with the flow direction m = A d / (3 eh),
// eh = sqrt(e^2 + e_c^2). m lies in the unit ball of the dual norm |n|_* = sqrt(3 n^T A^-1 n)
// (|m|_* = e / eh < 1). The consistent tangent D = mu A + c (A d)(A d)^T, c = (f' eh - f)/(9 eh^3),
// is nearly singular along the flow (only hardening and cut-off remain), and its rank-one part
// swings wherever the rate d of a point turns (rigid zones, neutral fibres in bending): plain
// Newton then overshoots and needs many damped steps.
//
// Primal-dual: carry n (~ m) as an unknown with the multiplied-out equation 3 eh n - A d = 0 and
// linearise in (d, n). Eliminating dn point by point leaves, for the velocity update,
//   D(n) = mu A + 3 eh c sym(n (A d)^T)              (symmetrised, as Chan-Golub-Mulet do)
// with the unchanged residual as right-hand side, and afterwards
//   n_new = m + (A dd / 3 - n (m . dd)) / eh         (dd: the point's rate increment)
// projected back onto |n|_* <= 1. n = m gives Newton's tangent, n = 0 the secant matrix of the
// direct iteration. D(n) is positive semi-definite for |n|_*, |m|_* <= 1: with c = -sigma_y / (9
// eh^3) (rate-independent), D = (sigma_y / eh)(A / 3 - sym(n m^T)) + (hv / 3) A and
// |x.n| |x.m| <= (x^T A x / 3) |n|_* |m|_* by Cauchy-Schwarz in the A metric.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace vs {

// The dual-norm ball |n|_* <= 1 of a Hill matrix A.
class FlowDirectionBall {
 public:
  explicit FlowDirectionBall(const Eigen::Matrix2d& A);
  // n scaled onto the ball if outside it.
  Eigen::Vector2d project(const Eigen::Vector2d& n) const {
    const double norm2 = n.dot(Ainv3_ * n);
    return norm2 > 1.0 ? Eigen::Vector2d(n / std::sqrt(norm2)) : n;
  }

 private:
  Eigen::Matrix2d Ainv3_;  // 3 A^-1
};

// Full dual update dn = n_new - n at one point: current direction m and cut-off rate eh, dual n,
// rate increment dd (header comment).
inline Eigen::Vector2d flow_direction_increment(const Eigen::Matrix2d& A, const Eigen::Vector2d& m,
                                                double eh, const Eigen::Vector2d& n,
                                                const Eigen::Vector2d& dd) {
  const Eigen::Vector2d n_new = m + (A * dd / 3.0 - n * m.dot(dd)) / eh;
  return n_new - n;
}

}  // namespace vs
