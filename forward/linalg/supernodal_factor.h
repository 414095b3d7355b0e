// A copy of a CHOLMOD supernodal Cholesky factor (in single precision: SinglePrecisionFactor),
// and the two triangular solves with it: the preconditioner of the Krylov steps and the solve of
// the chord steps (linalg/sparse_cholesky_solver.h, solver/newton.h).
//
// CHOLMOD stores P A P' = L L' with L in supernodes: supernode s holds the columns
// k1 = super[s] .. k2 - 1 (nscol = k2 - k1) and the rows s[pi[s]] .. s[pi[s+1] - 1] (nsrow, the
// first nscol of them k1 .. k2 - 1), its values a dense nsrow x nscol column-major block at
// x[px[s]]: the lower-triangular diagonal block L_ss over the rectangle L_bs below it.
// A x = b is then x = P' L^-T L^-1 P b, with (P b)_i = b[Perm[i]]:
//   forward, s ascending:  y_s = L_ss^-1 y_s;  y[rows below] -= L_bs y_s
//   backward, s descending: y_s -= L_bs' y[rows below];  y_s = L_ss^-T y_s
//
// Why single precision is a sound preconditioner. Rounding L to float perturbs each entry by a
// relative 6e-8, and the float triangular solves are backward stable (the computed y solves
// (L + dL) y = b with |dL| <= c nscol eps |L|). So the preconditioner is M = (L + E)(L + E)' with
// |E| <~ 1e-6 |L| entrywise, and M^-1 A = I + O(|L^-1 E|): with the entrywise relative error the
// perturbation grows with cond(L) = sqrt(cond(A)), not with cond(A); at the shell's cond(A) ~ 1e10
// that is ~1e-1 at worst, a contraction CG removes in a step or two. The conjugate-gradient
// recurrences themselves stay in double precision. What it buys: the triangular solves stream the
// factor once forward and once backward, and they are bound by that traffic (2e6 entries at
// n = 16 in ex4a, 1.1e7 at n = 32). Measured on one thread (experiments/09_linear_solver, warm):
// n = 16 CHOLMOD's solve 1.96-2.15 ms, this traversal in double 1.5 ms, in single 0.86 ms; n = 32:
// 23-26 / 16-17 / 6-9 ms. On two threads (below) the single-precision one takes 0.46-0.49 ms at
// n = 16 and 2.75-2.82 ms at n = 32.
//
// Two threads (the solves run between the parallel assemblies, on one core while the other
// waited): the elimination tree is cut into a top set and two parts of equal work (entries of L;
// linalg/tree_cut.h):
//   forward:  the parts in parallel, each its supernodes ascending; an update of a row of the top
//             set goes into the part's own accumulator; then the accumulators are subtracted in
//             part order and the top set is solved ascending;
//   backward: the top set descending, then the parts in parallel, each descending (a supernode
//             reads its ancestors, all final by then, and writes only its own columns).
// The cut depends only on the factor's structure (kept while that does not change) and the
// order of every sum is fixed, so the result has the same bits for any number of threads.
#pragma once

#include <cholmod.h>

#include <Eigen/Core>
#include <vector>

#include "linalg/aligned_buffer.h"
#include "linalg/supernodal_structure.h"
#include "linalg/tree_cut.h"

namespace vs {

// The factor copied to Scalar (float: the preconditioner; double: the same traversal at full
// precision, for comparison).
template <typename Scalar>
class SupernodalFactor {
 public:
  // Copies a supernodal LL' factor (int indices); false (and holds nothing) for any other kind.
  bool assign(const cholmod_factor& L);
  bool empty() const { return n_ == 0; }
  int size() const { return n_; }
  // z = (P' L L' P)^-1 r, the solves in Scalar.
  void solve(const Eigen::VectorXd& r, Eigen::VectorXd* z) const;

  static constexpr int kParts = TreeCut::kParts;
  // The cut: the fraction of the factor's entries in the top set and in the largest part.
  double top_fraction() const { return cut_.top_fraction; }
  double largest_part_fraction() const { return cut_.largest_part_fraction; }

 private:
  void cut_tree();
  void forward(const std::vector<int>& supernodes, Scalar* acc, Scalar* work) const;
  void backward(const std::vector<int>& supernodes, Scalar* work) const;

  int n_ = 0;
  SupernodalStructure st_;
  AlignedBuffer<Scalar> x_;  // 64-byte aligned: the same bits wherever the heap puts it
  TreeCut cut_;
  // The slot of every column of the top set in the accumulators (-1 elsewhere).
  std::vector<int> slot_, top_columns_;
  mutable AlignedBuffer<Scalar> y_, acc_[kParts], work_[kParts];
};

extern template class SupernodalFactor<float>;
extern template class SupernodalFactor<double>;
using SinglePrecisionFactor = SupernodalFactor<float>;

}  // namespace vs
