// The two-thread numeric factorisation into CHOLMOD's factor (linalg/supernodal_cholesky.h): the
// factor CHOLMOD computes, to round-off; solves with it; the same bits on one thread and on two;
// a matrix that is not positive definite is refused (and SparseSpdSolver then falls back); the
// tree cut gives both parts work.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "linalg/sparse_spd_solver.h"
#include "linalg/supernodal_cholesky.h"

namespace vs {
namespace {

// A 2D grid of 3-dof nodes coupled like a plate (a dense 3x3 block per link), plus a diagonal
// shift: SPD, with supernodes of several columns.
SparseMatrix plate_matrix(int m, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  Eigen::Matrix3d K;
  K << 4.0, 1.0, 0.5, 1.0, 3.0, 0.25, 0.5, 0.25, 2.0;
  auto link = [&](int a, int b, double c) {
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) {
        t.emplace_back(3 * a + p, 3 * a + q, c * K(p, q));
        t.emplace_back(3 * b + p, 3 * b + q, c * K(p, q));
        t.emplace_back(3 * a + p, 3 * b + q, -c * K(p, q));
        t.emplace_back(3 * b + p, 3 * a + q, -c * K(p, q));
      }
  };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double c = 1.0 + 0.3 * std::sin(0.7 * i + 1.3 * j);
      if (i + 1 < m) link(id(i, j), id(i + 1, j), c);
      if (j + 1 < m) link(id(i, j), id(i, j + 1), c);
      if (i + 1 < m && j + 1 < m) link(id(i, j), id(i + 1, j + 1), 0.25 * c);
      for (int p = 0; p < 3; ++p) t.emplace_back(3 * id(i, j) + p, 3 * id(i, j) + p, shift);
    }
  SparseMatrix A(3 * m * m, 3 * m * m);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

Eigen::VectorXd load(int n) {
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::sin(0.37 * i) + 0.5 * std::cos(0.011 * i * i);
  return b;
}

struct Threads {
  int was = omp_get_max_threads();
  ~Threads() { omp_set_num_threads(was); }
};

TEST(SupernodalCholesky, ReproducesCholmodsFactorAndGivesTheSameBitsOnAnyTeam) {
  Threads keep;
  const SparseMatrix A = plate_matrix(40, 1e-3);  // 4 800 unknowns
  // CHOLMOD's factorisation, then ours into the same storage.
  struct Wrapper : Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> {
    cholmod_factor* factor() { return m_cholmodFactor; }
  } cholmod;
  cholmod.compute(A);
  ASSERT_EQ(cholmod.info(), Eigen::Success);
  cholmod_factor* L = cholmod.factor();
  ASSERT_TRUE(L->is_super);
  const double* x = static_cast<const double*>(L->x);
  const std::vector<double> reference(x, x + L->xsize);
  SupernodalCholesky numeric;
  ASSERT_TRUE(numeric.analyse(*L));
  EXPECT_TRUE(numeric.fits(*L));
  EXPECT_FALSE(numeric.cut().part[0].empty());
  EXPECT_FALSE(numeric.cut().part[1].empty());
  EXPECT_LT(numeric.cut().top_fraction, 0.5);
  std::vector<std::vector<double>> ours;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::fill(static_cast<double*>(L->x), static_cast<double*>(L->x) + L->xsize, -7.0);
    ASSERT_TRUE(numeric.factorize(A, L));
    ours.emplace_back(x, x + L->xsize);
  }
  EXPECT_EQ(ours[0], ours[1]);  // the same bits on one thread and on two
  // CHOLMOD's values to round-off, in the lower triangles (the upper part of a diagonal block is
  // not part of the factor).
  double largest = 0.0, diff = 0.0;
  for (size_t s = 0; s < L->nsuper; ++s) {
    const int* super = static_cast<const int*>(L->super);
    const int* pi = static_cast<const int*>(L->pi);
    const int* px = static_cast<const int*>(L->px);
    const int nscol = super[s + 1] - super[s], nsrow = pi[s + 1] - pi[s];
    for (int c = 0; c < nscol; ++c)
      for (int r = c; r < nsrow; ++r) {
        const size_t k = static_cast<size_t>(px[s]) + static_cast<size_t>(c) * nsrow + r;
        largest = std::max(largest, std::abs(reference[k]));
        diff = std::max(diff, std::abs(ours[0][k] - reference[k]));
      }
  }
  EXPECT_LT(diff, 1e-12 * largest);
  // CHOLMOD's solve with our factor.
  cholmod.factorize(A);  // CHOLMOD's values again ...
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  const Eigen::VectorXd x_cholmod = cholmod.solve(b);
  ASSERT_TRUE(numeric.factorize(A, L));  // ... and ours
  const Eigen::VectorXd x_ours = cholmod.solve(b);
  EXPECT_LT((x_ours - x_cholmod).norm(), 1e-10 * x_cholmod.norm());
  EXPECT_LT((A * x_ours - b).norm(), 1e-10 * b.norm());
}

TEST(SupernodalCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  const SparseMatrix A = plate_matrix(30, 1e-3);
  SparseMatrix B = A;
  B.coeffRef(1000, 1000) = -5.0;  // a negative pivot in the middle
  SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
  solver.analyze(A);
  ASSERT_TRUE(solver.factorize(A));  // CHOLMOD's (allocates the factor)
  ASSERT_TRUE(solver.factorize(A));  // ours
  EXPECT_EQ(solver.fallbacks(), 0);
  // Refused by ours and by CHOLMOD: the fallback factorises (LDL' of an indefinite matrix).
  solver.factorize(B);
  EXPECT_EQ(solver.fallbacks(), 1);
  EXPECT_EQ(solver.active(), SparseSolverKind::kSimplicialLDLT);
  // And back: a positive definite matrix is factorised again, the solve is right.
  ASSERT_TRUE(solver.factorize(A));
  EXPECT_EQ(solver.active(), SparseSolverKind::kCholmodSupernodal);
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  EXPECT_LT((A * solver.solve(b) - b).norm(), 1e-10 * b.norm());
}

TEST(SupernodalCholesky, RefusesAFactorThatIsNotSupernodal) {
  cholmod_factor L{};
  L.is_super = 0;
  L.is_ll = 1;
  SupernodalCholesky numeric;
  EXPECT_FALSE(numeric.analyse(L));
  EXPECT_FALSE(numeric.analysed());
}

}  // namespace
}  // namespace vs
