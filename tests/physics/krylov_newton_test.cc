// Preconditioned conjugate gradients (linalg/preconditioned_cg.h) against closed forms, the
// sparse solver's PCG on its held factorisation, and the Newton loop's Krylov steps
// (solver/newton.h): the same answer as factorising every Newton matrix, with fewer
// factorisations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "linalg/preconditioned_cg.h"
#include "linalg/sparse_cholesky_solver.h"
#include "solver/newton.h"

namespace vs {
namespace {

auto apply_dense(const Eigen::MatrixXd& A) {
  return [&A](const Eigen::VectorXd& p, Eigen::VectorXd* q) { *q = A * p; };
}
void identity(const Eigen::VectorXd& r, Eigen::VectorXd* z) { *z = r; }

// A symmetric matrix Q diag(lambda) Q^T with a fixed orthogonal Q.
Eigen::MatrixXd with_eigenvalues(const std::vector<double>& lambda) {
  const int n = static_cast<int>(lambda.size());
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = std::sin(1.0 + 0.7 * i + 1.3 * j * j);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(M).householderQ();
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d(i) = lambda[static_cast<std::size_t>(i)];
  return Q * d.asDiagonal() * Q.transpose();
}

TEST(PreconditionedCg, ConvergesInAsManyIterationsAsDistinctEigenvalues) {
  // 12 unknowns, 3 distinct eigenvalues: the Krylov space of dimension 3 holds the solution.
  const Eigen::MatrixXd A =
      with_eigenvalues({1.0, 1.0, 1.0, 1.0, 5.0, 5.0, 5.0, 5.0, 20.0, 20.0, 20.0, 20.0});
  Eigen::VectorXd b(12);
  for (int i = 0; i < 12; ++i) b(i) = std::cos(0.3 * i);
  Eigen::VectorXd x;
  const PcgSummary s = preconditioned_cg(apply_dense(A), identity, b, &x, 1e-10, 50);
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(s.iterations, 3);
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  // Two iterations are not enough: the residual is then far from the tolerance.
  const PcgSummary two = preconditioned_cg(apply_dense(A), identity, b, &x, 1e-10, 2);
  EXPECT_FALSE(two.converged);
  EXPECT_GT(two.relative_residual, 1e-3);
  // Every iterate is a descent direction of 1/2 x'Ax - b'x from 0.
  EXPECT_GT(b.dot(x), 0.0);
}

TEST(PreconditionedCg, ExactPreconditionerConvergesInOneIteration) {
  const Eigen::MatrixXd A = with_eigenvalues({1.0, 2.0, 3.0, 10.0, 100.0, 1000.0});
  const Eigen::LLT<Eigen::MatrixXd> llt(A);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(6, 1.0, 6.0), x;
  const PcgSummary s = preconditioned_cg(
      apply_dense(A), [&](const Eigen::VectorXd& r, Eigen::VectorXd* z) { *z = llt.solve(r); }, b,
      &x, 1e-12, 10);
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_LT((x - llt.solve(b)).norm(), 1e-12 * x.norm());
}

TEST(PreconditionedCg, StopsOnNegativeCurvature) {
  const Eigen::MatrixXd A = with_eigenvalues({1.0, 2.0, -3.0, 4.0});
  Eigen::VectorXd b = Eigen::VectorXd::Ones(4), x;
  const PcgSummary s = preconditioned_cg(apply_dense(A), identity, b, &x, 1e-12, 20);
  EXPECT_FALSE(s.converged);
  // Zero right-hand side: x = 0 at once.
  const PcgSummary zero =
      preconditioned_cg(apply_dense(A), identity, Eigen::VectorXd::Zero(4), &x, 1e-12, 20);
  EXPECT_TRUE(zero.converged);
  EXPECT_EQ(zero.iterations, 0);
  EXPECT_EQ(x.norm(), 0.0);
}

// A chain of n unknowns, full symmetric storage: diag d_i, off-diagonal -c.
SparseMatrix chain_matrix(const Eigen::VectorXd& d, double c) {
  const Eigen::Index n = d.size();
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index i = 0; i < n; ++i) {
    t.emplace_back(static_cast<int>(i), static_cast<int>(i), d(i));
    if (i + 1 < n) {
      t.emplace_back(static_cast<int>(i), static_cast<int>(i + 1), -c);
      t.emplace_back(static_cast<int>(i + 1), static_cast<int>(i), -c);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(SparseCholeskySolver, PcgOnTheHeldFactorisationSolvesTheNewMatrix) {
  const int n = 200;
  Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 3.0);
  SparseMatrix A = chain_matrix(d, 1.0);
  SparseCholeskySolver solver(SparseSolverKind::kSimplicialLDLT);
  solver.set_matrix(&A);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), x;
  int iterations = -1;
  EXPECT_FALSE(solver.solve_preconditioned(b, &x, 1e-8, 20, &iterations));  // nothing held
  ASSERT_TRUE(solver.factorize());
  // The matrix changes in a few rows (a local change of stiffness): PCG on the old factor.
  for (int i = 90; i < 95; ++i) d(i) = 30.0;
  A = chain_matrix(d, 1.0);
  ASSERT_TRUE(solver.solve_preconditioned(b, &x, 1e-10, 20, &iterations));
  EXPECT_LE(iterations, 6);  // rank-5 change: at most 6 distinct eigenvalues of M^-1 A
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  // The old factorisation alone is not the new solution.
  Eigen::VectorXd old = b;
  solver.solve_in_place(&old);
  EXPECT_GT((A * old - b).norm(), 1e-2 * b.norm());
}

// Minimum of Phi(x) = sum_i (a_i x_i^2 / 2 + x_i^4 / 4) + c/2 sum (x_i - x_{i+1})^2 - b'x on a
// chain: residual A x + x^3 - b, secant matrix A + diag(x^2) (the direct iteration's), tangent
// A + 3 diag(x^2). Convex, so the loop converges from anywhere.
class QuarticChain : public NewtonProblem {
 public:
  explicit QuarticChain(int n) : a_(n), b_(n), solver_(SparseSolverKind::kSimplicialLDLT) {
    for (int i = 0; i < n; ++i) {
      a_(i) = 1.0 + 0.5 * std::sin(0.1 * i);
      b_(i) = 10.0 * std::cos(0.05 * i) + (i % 17 == 0 ? 30.0 : 0.0);
    }
    solver_.set_matrix(&K_);
  }
  LinearSolver& linear_solver() override { return solver_; }
  double evaluate(const Eigen::VectorXd& x, double theta, Eigen::VectorXd* r,
                  double* potential) override {
    Eigen::VectorXd d = a_ + 2.0 * kC * Eigen::VectorXd::Ones(a_.size());
    d += (1.0 + 2.0 * theta) * x.cwiseAbs2();
    K_ = chain_matrix(d, kC);
    return evaluate_residual(x, r, potential);
  }
  double evaluate_residual(const Eigen::VectorXd& x, Eigen::VectorXd* r,
                           double* potential) override {
    const Eigen::Index n = x.size();
    *r = a_.cwiseProduct(x) + x.cwiseAbs2().cwiseProduct(x) - b_;
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
      (*r)(i) += kC * (x(i) - x(i + 1));
      (*r)(i + 1) -= kC * (x(i) - x(i + 1));
    }
    *potential = phi(x);
    return b_.norm();
  }
  double potential(const Eigen::VectorXd& x, double /*alpha*/) override { return phi(x); }
  bool update_lagged(const Eigen::VectorXd& /*x*/) override { return false; }

 private:
  static constexpr double kC = 50.0;
  double phi(const Eigen::VectorXd& x) const {
    double p = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      p += 0.5 * a_(i) * x(i) * x(i) + 0.25 * std::pow(x(i), 4) - b_(i) * x(i);
      if (i + 1 < x.size()) p += 0.5 * kC * (x(i) - x(i + 1)) * (x(i) - x(i + 1));
    }
    return p;
  }
  Eigen::VectorXd a_, b_;
  SparseMatrix K_;
  SparseCholeskySolver solver_;
};

TEST(KrylovNewton, SameAnswerWithFewerFactorisations) {
  NewtonOptions o;
  o.tolerance = 1e-10;
  o.initial_theta = 1.0;
  o.picard_before_newton = 0;
  Eigen::VectorXd x_direct = Eigen::VectorXd::Zero(300), x_krylov = x_direct;
  QuarticChain direct(300), krylov(300);
  const NewtonSummary s_direct = solve_newton(direct, o, &x_direct);
  o.krylov_max_iterations = 30;
  o.krylov_tolerance = 1e-3;
  const NewtonSummary s_krylov = solve_newton(krylov, o, &x_krylov);
  ASSERT_TRUE(s_direct.converged) << s_direct.message;
  ASSERT_TRUE(s_krylov.converged) << s_krylov.message;
  EXPECT_EQ(s_direct.krylov_steps, 0);
  EXPECT_GT(s_krylov.krylov_steps, 0);
  EXPECT_GT(s_krylov.krylov_iterations, s_krylov.krylov_steps);
  EXPECT_LT(s_krylov.factorisations, s_direct.factorisations);
  EXPECT_LT((x_krylov - x_direct).norm(), 1e-8 * x_direct.norm());
  // The answer solves the problem: residual at the tolerance.
  Eigen::VectorXd r;
  double p = 0.0;
  const double scale = krylov.evaluate_residual(x_krylov, &r, &p);
  EXPECT_LT(r.norm(), 1e-9 * scale);
}

TEST(KrylovNewton, OptionsOutOfRangeAreRejected) {
  NewtonOptions o;
  std::string why;
  o.krylov_max_iterations = -1;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("krylov_max_iterations"), std::string::npos);
  o.krylov_max_iterations = 10;
  o.krylov_tolerance = 1.0;
  EXPECT_FALSE(o.IsValid(&why));
  EXPECT_NE(why.find("krylov_tolerance"), std::string::npos);
}

}  // namespace
}  // namespace vs
