// Preconditioned conjugate gradients (Hestenes-Stiefel with a preconditioner M ~ A, Saad,
// "Iterative Methods for Sparse Linear Systems", 2nd ed., algorithm 9.1) for a symmetric positive
// definite A, from x = 0. With z = M^-1 r, each iteration
//   alpha = (r, z) / (p, A p),  x += alpha p,  r -= alpha A p,
//   beta = (r_new, z_new) / (r, z),  p = z_new + beta p.
// It stops when |r| <= tolerance |b| (success), when (p, A p) <= 0 (A is not positive definite
// along p: failure), or after max_iterations (failure). In exact arithmetic the iterates of CG
// on a matrix with k distinct eigenvalues of M^-1 A reach the solution in k iterations (the
// unit test's closed form), and with M = A in one.
// Every iterate x_k (k >= 1) is a descent direction of the quadratic 1/2 x'Ax - b'x from 0:
// b' x_k > 0, the property the Newton loop's line search needs.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace vs {

struct PcgSummary {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 1.0;  // |b - A x| / |b| at the last iterate
};

// apply_A(p, &q): q = A p. apply_preconditioner(r, &z): z = M^-1 r.
PcgSummary preconditioned_cg(
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>& apply_A,
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>& apply_preconditioner,
    const Eigen::VectorXd& b, Eigen::VectorXd* x, double tolerance, int max_iterations);

}  // namespace vs
