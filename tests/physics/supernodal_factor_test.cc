// The single-precision copy of a CHOLMOD supernodal factor (linalg/supernodal_factor.h):
// its solve agrees with the double-precision solve to single-precision accuracy (so the
// permutation and the supernodal traversal are right), and as the preconditioner of conjugate
// gradients it solves a matrix with a 1e8 stiffness contrast to 1e-10 in a few iterations. The
// solves run the parts of the cut elimination tree in parallel: the same bits on one thread and
// on several, and a new cut when the factor's structure changes.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "linalg/preconditioned_cg.h"
#include "linalg/sparse_cholesky_solver.h"
#include "linalg/sparse_spd_solver.h"

namespace vs {
namespace {

// The 5-point Laplacian on an m x m grid with Dirichlet sides, the coefficient c(i, j) on the
// links, plus a small diagonal shift: SPD, with cond ~ contrast * m^2.
SparseMatrix grid_matrix(int m, double contrast) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  auto coef = [m, contrast](int i, int j) {
    return (i > m / 3 && i < 2 * m / 3 && j > m / 4) ? contrast : 1.0;  // a stiff block
  };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = id(i, j);
      const double c = coef(i, j);
      t.emplace_back(a, a, 4.0 * c + 1e-3);
      if (i + 1 < m) t.emplace_back(a, id(i + 1, j), -c), t.emplace_back(id(i + 1, j), a, -c);
      if (j + 1 < m) t.emplace_back(a, id(i, j + 1), -c), t.emplace_back(id(i, j + 1), a, -c);
    }
  SparseMatrix A(m * m, m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::VectorXd load(int n) {
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::sin(0.37 * i) + 0.5 * std::cos(0.011 * i * i);
  return b;
}

TEST(SinglePrecisionFactor, SolveAgreesWithTheDoubleSolveToSinglePrecision) {
  const SparseMatrix A = grid_matrix(60, 1.0);  // 3 600 unknowns, cond ~ 2e3
  SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
  solver.analyze(A);
  ASSERT_TRUE(solver.factorize(A));
  ASSERT_EQ(solver.active(), SparseSolverKind::kCholmodSupernodal);
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  const Eigen::VectorXd x = solver.solve(b);
  Eigen::VectorXd z;
  solver.precondition(b, &z);
  const double rel = (z - x).norm() / x.norm();
  EXPECT_LT(rel, 1e-4);   // single precision times a moderate condition number
  EXPECT_GT(rel, 1e-12);  // and really computed in single precision
  // Switched off, the preconditioner is the double solve.
  solver.set_single_precision(false);
  solver.precondition(b, &z);
  EXPECT_EQ((z - x).norm(), 0.0);
}

TEST(SinglePrecisionFactor, PreconditionsAStiffContrastMatrixToDoublePrecision) {
  // A 1e8 stiffness contrast (the shell's near-rigid zones): cond(A) ~ 1e11.
  const SparseMatrix A = grid_matrix(60, 1e8);
  SparseCholeskySolver solver(SparseSolverKind::kCholmodSupernodal);
  solver.set_matrix(&A);
  ASSERT_TRUE(solver.factorize());
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  Eigen::VectorXd x;
  int iterations = -1;
  ASSERT_TRUE(solver.solve_preconditioned(b, &x, 1e-10, 10, &iterations));
  EXPECT_LE(iterations, 4);
  const Eigen::VectorXd r = b - A * x;
  EXPECT_LT(r.norm(), 1e-10 * b.norm());
}

// Restores the OpenMP team size at the end of a test.
struct Threads {
  int was = omp_get_max_threads();
  ~Threads() { omp_set_num_threads(was); }
};

TEST(SinglePrecisionFactor, ParallelPartsGiveTheSameBitsOnOneThreadAndOnTwo) {
  Threads keep;
  const SparseMatrix A = grid_matrix(70, 1.0);  // 4 900 unknowns: above the parallel threshold
  SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
  solver.analyze(A);
  ASSERT_TRUE(solver.factorize(A));
  ASSERT_NE(solver.held_cholmod_factor(), nullptr);
  SupernodalFactor<float> f32;
  SupernodalFactor<double> f64;
  ASSERT_TRUE(f32.assign(*solver.held_cholmod_factor()));
  ASSERT_TRUE(f64.assign(*solver.held_cholmod_factor()));
  // A grid's tree splits: two parts of real work and a small top set.
  EXPECT_GT(f32.top_fraction(), 0.0);
  EXPECT_LT(f32.top_fraction(), 0.35);
  EXPECT_GT(f32.largest_part_fraction(), 0.3);
  EXPECT_LT(f32.largest_part_fraction(), 0.6);
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  const Eigen::VectorXd x = solver.solve(b);
  Eigen::VectorXd z1, z2, d1, d2;
  omp_set_num_threads(1);
  f32.solve(b, &z1);
  f64.solve(b, &d1);
  omp_set_num_threads(2);
  f32.solve(b, &z2);
  f64.solve(b, &d2);
  EXPECT_EQ((z1 - z2).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((d1 - d2).cwiseAbs().maxCoeff(), 0.0);
  // And the traversal is right: the double one is CHOLMOD's solve to round-off.
  EXPECT_LT((d1 - x).norm(), 1e-12 * x.norm());
  EXPECT_LT((z1 - x).norm(), 1e-4 * x.norm());
}

TEST(SinglePrecisionFactor, CutsTheTreeAgainWhenTheStructureChanges) {
  SupernodalFactor<double> f;
  for (int m : {60, 45, 60}) {
    const SparseMatrix A = grid_matrix(m, 1.0);
    SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
    solver.analyze(A);
    ASSERT_TRUE(solver.factorize(A));
    ASSERT_NE(solver.held_cholmod_factor(), nullptr);
    ASSERT_TRUE(f.assign(*solver.held_cholmod_factor()));
    const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
    const Eigen::VectorXd x = solver.solve(b);
    Eigen::VectorXd z;
    f.solve(b, &z);
    EXPECT_LT((z - x).norm(), 1e-12 * x.norm()) << m;
  }
}

TEST(SinglePrecisionFactor, RefusesAFactorThatIsNotSupernodal) {
  cholmod_factor L{};
  L.is_super = 0;
  L.is_ll = 1;
  SinglePrecisionFactor f;
  EXPECT_FALSE(f.assign(L));
  EXPECT_TRUE(f.empty());
}

}  // namespace
}  // namespace vs
