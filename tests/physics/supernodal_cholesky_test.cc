// The two-thread numeric factorisation into CHOLMOD's factor (linalg/supernodal_cholesky.h): the
// factor CHOLMOD computes, to round-off; solves with it; the same bits on one thread and on two;
// a matrix that is not positive definite is refused (and SparseSpdSolver then falls back); the
// tree cut gives both parts work.
#include "linalg/supernodal_cholesky.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "linalg/sparse_spd_solver.h"

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

// CHOLMOD's factor of A in a wrapper whose factor is writable.
struct Wrapper : Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> {
  cholmod_factor* factor() { return m_cholmodFactor; }
};

// Largest difference between the lower triangles of two factors' blocks, and the largest entry.
std::pair<double, double> factor_difference(const cholmod_factor& L, const double* a,
                                            const double* b) {
  const int* super = static_cast<const int*>(L.super);
  const int* pi = static_cast<const int*>(L.pi);
  const int* px = static_cast<const int*>(L.px);
  double diff = 0.0, largest = 0.0;
  for (size_t s = 0; s < L.nsuper; ++s) {
    const int nscol = super[s + 1] - super[s], nsrow = pi[s + 1] - pi[s];
    for (int c = 0; c < nscol; ++c)
      for (int r = c; r < nsrow; ++r) {
        const size_t k = static_cast<size_t>(px[s]) + static_cast<size_t>(c) * nsrow + r;
        largest = std::max(largest, std::abs(a[k]));
        diff = std::max(diff, std::abs(a[k] - b[k]));
      }
  }
  return {diff, largest};
}

TEST(SupernodalCholesky, ReproducesCholmodsFactorAndGivesTheSameBitsOnAnyTeam) {
  Threads keep;
  const SparseMatrix A = plate_matrix(40, 1e-3);  // 4 800 unknowns
  // CHOLMOD's factorisation, then ours into the same storage.
  Wrapper cholmod;
  cholmod.compute(A);
  ASSERT_EQ(cholmod.info(), Eigen::Success);
  cholmod_factor* L = cholmod.factor();
  ASSERT_TRUE(L->is_super);
  const double* x = static_cast<const double*>(L->x);
  const std::vector<double> reference(x, x + L->xsize);
  SupernodalCholesky numeric;
  ASSERT_TRUE(numeric.analyze(*L));
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
  const auto [diff, largest] = factor_difference(*L, reference.data(), ours[0].data());
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

TEST(SupernodalCholesky, LargeDenseBlocksGoThroughTheChunkedKernels) {
  // A dense 300 x 300 block coupled to a plate: supernodes of more than 96 columns (the kernels'
  // chunk), updates with more than 96 rows and columns, several chunks in every kernel.
  SparseMatrix P = plate_matrix(24, 1e-3);  // 1 728 unknowns
  const int n = static_cast<int>(P.rows()), m = 300;
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < P.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(P, k); it; ++it)
      t.emplace_back(it.row(), it.col(), it.value());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double v = (i == j ? 2.0 * m : 0.0) + std::cos(0.1 * (i + 1) * (j + 1));
      t.emplace_back(n - m + i, n - m + j, v);
    }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  Wrapper cholmod;
  cholmod.compute(A);
  ASSERT_EQ(cholmod.info(), Eigen::Success);
  cholmod_factor* L = cholmod.factor();
  int widest = 0;
  for (size_t s = 0; s < L->nsuper; ++s) {
    const int* super = static_cast<const int*>(L->super);
    widest = std::max(widest, super[s + 1] - super[s]);
  }
  EXPECT_GT(widest, 2 * 96);
  const double* x = static_cast<const double*>(L->x);
  const std::vector<double> reference(x, x + L->xsize);
  SupernodalCholesky numeric;
  ASSERT_TRUE(numeric.analyze(*L));
  ASSERT_TRUE(numeric.factorize(A, L));
  const auto [diff, largest] = factor_difference(*L, reference.data(), x);
  EXPECT_LT(diff, 1e-12 * largest);
}

TEST(SupernodalCholesky, RefusesAPatternOutsideTheFactorAndNonFiniteValues) {
  const SparseMatrix A = plate_matrix(30, 1e-3);
  Wrapper cholmod;
  cholmod.compute(A);
  cholmod_factor* L = cholmod.factor();
  SupernodalCholesky numeric;
  ASSERT_TRUE(numeric.analyze(*L));
  ASSERT_TRUE(numeric.factorize(A, L));
  // An entry coupling two far-apart unknowns: not in L's structure.
  SparseMatrix B = A;
  const int n = static_cast<int>(A.rows());
  B.coeffRef(0, n - 1) = 1e-3;
  B.coeffRef(n - 1, 0) = 1e-3;
  B.makeCompressed();
  EXPECT_FALSE(numeric.factorize(B, L));
  // A NaN on the diagonal (Eigen's LLT alone would take it).
  SparseMatrix C = A;
  C.coeffRef(n / 2, n / 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(numeric.factorize(C, L));
  ASSERT_TRUE(numeric.factorize(A, L));  // and back
}

TEST(SupernodalCholesky, ANewAnalysisIsFollowed) {
  // The product's solver: two patterns one after the other, each factorised twice (CHOLMOD's,
  // then the two-thread one), the solves right each time.
  SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
  for (int m : {30, 24, 30}) {
    const SparseMatrix A = plate_matrix(m, 1e-3);
    const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
    solver.analyze(A);
    for (int k = 0; k < 2; ++k) {
      ASSERT_TRUE(solver.factorize(A));
      EXPECT_LT((A * solver.solve(b) - b).norm(), 1e-10 * b.norm()) << m << " " << k;
    }
  }
  EXPECT_EQ(solver.fallbacks(), 0);
}

// SparseSpdSolver orders by CHOLMOD's nested dissection (sparse_spd_solver.cc), not by CHOLMOD's
// default choice (AMD here). Which ordering is better depends on the matrix: on this grid AMD's
// factor is 3 % smaller, on the 3D forming matrix 8 % larger (experiments/09_linear_solver).
TEST(SparseSpdSolver, OrdersByNestedDissection) {
  const SparseMatrix A = plate_matrix(60, 1e-3);  // 10 800 unknowns
  SparseSpdSolver solver(SparseSolverKind::kCholmodSupernodal);
  solver.analyze(A);
  ASSERT_TRUE(solver.factorize(A));
  const cholmod_factor* L = solver.held_cholmod_factor();
  ASSERT_NE(L, nullptr);
  EXPECT_EQ(L->ordering, CHOLMOD_NESDIS);
  const Eigen::VectorXd b = load(static_cast<int>(A.rows()));
  EXPECT_LT((A * solver.solve(b) - b).norm(), 1e-10 * b.norm());
  Wrapper amd;  // CHOLMOD's default choice
  amd.compute(A);
  ASSERT_EQ(amd.info(), Eigen::Success);
  EXPECT_EQ(amd.factor()->ordering, CHOLMOD_AMD);
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
  EXPECT_FALSE(numeric.analyze(L));
  EXPECT_FALSE(numeric.analyzed());
}

}  // namespace
}  // namespace vs
