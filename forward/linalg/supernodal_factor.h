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
// n = 16 in ex4a, 1.1e7 at n = 32). Measured (experiments/09_linear_solver, warm): n = 16
// CHOLMOD's solve 1.96-2.15 ms, this traversal in double 1.5 ms, in single 0.86 ms; n = 32: 23-26 /
// 16-17 / 6-9 ms.
//
// Two threads (the solves run between the parallel assemblies, on one core while the other
// waited). The supernodal elimination tree (parent of s = the supernode holding the first row
// below its diagonal block; a parent always comes after its children) is cut into a top set and
// disjoint subtrees, the subtrees packed into kParts parts of about equal work (entries of L):
//   forward:  the parts in parallel, each its supernodes ascending; an update of a row of the top
//             set goes into the part's own accumulator (the rows below a supernode are its
//             ancestors: in its own subtree or in the top set, never in another part); then the
//             accumulators are subtracted in part order and the top set is solved ascending;
//   backward: the top set descending, then the parts in parallel, each descending (a supernode
//             reads its ancestors, all final by then, and writes only its own columns).
// The cut depends only on the factor's structure (kept while that does not change) and the
// order of every sum is fixed, so the result has the same bits for any number of threads. The
// cut: starting from the roots, the subtree of largest work is moved to the top set (its
// children become subtrees) while that lowers the critical path, top work + largest part
// (longest-processing-time packing), over at most kMaxCuts cuts; the best cut is kept.
#pragma once

#include <cholmod.h>

#include <Eigen/Core>
#include <vector>

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

  static constexpr int kParts = 2;
  // The cut: the fraction of the factor's entries in the top set and in the largest part.
  double top_fraction() const { return top_fraction_; }
  double largest_part_fraction() const { return largest_part_fraction_; }

 private:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  void cut_tree();
  void forward(const std::vector<int>& supernodes, Vector* acc, Vector* work) const;
  void backward(const std::vector<int>& supernodes, Vector* work) const;

  int n_ = 0;
  std::vector<int> perm_, super_, pi_, px_, s_;
  std::vector<Scalar> x_;
  // The cut (see above): the supernodes of each part and of the top set, ascending; the slot of
  // every column of the top set in the accumulators (-1 elsewhere).
  std::vector<int> part_[kParts], top_, slot_, top_columns_;
  double top_fraction_ = 0.0, largest_part_fraction_ = 0.0;
  mutable Vector y_, acc_[kParts], work_[kParts];
};

extern template class SupernodalFactor<float>;
extern template class SupernodalFactor<double>;
using SinglePrecisionFactor = SupernodalFactor<float>;

}  // namespace vs
