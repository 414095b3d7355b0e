#include "linalg/preconditioned_cg.h"

namespace vs {

PcgSummary preconditioned_cg(
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>& apply_A,
    const std::function<void(const Eigen::VectorXd&, Eigen::VectorXd*)>& apply_preconditioner,
    const Eigen::VectorXd& b, Eigen::VectorXd* x, double tolerance, int max_iterations) {
  PcgSummary sum;
  x->setZero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    sum.converged = true;
    sum.relative_residual = 0.0;
    return sum;
  }
  Eigen::VectorXd r = b, z, p, q;
  apply_preconditioner(r, &z);
  p = z;
  double rz = r.dot(z);
  for (int k = 1; k <= max_iterations; ++k) {
    apply_A(p, &q);
    const double curvature = p.dot(q);
    if (!(curvature > 0.0) || !(rz > 0.0)) return sum;  // not SPD along p (or M not SPD)
    const double alpha = rz / curvature;
    *x += alpha * p;
    r -= alpha * q;
    sum.iterations = k;
    sum.relative_residual = r.norm() / b_norm;
    if (sum.relative_residual <= tolerance) {
      sum.converged = true;
      return sum;
    }
    apply_preconditioner(r, &z);
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return sum;
}

}  // namespace vs
