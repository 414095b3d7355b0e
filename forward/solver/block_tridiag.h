// Symmetric block-tridiagonal matrix with 3x3 blocks: the exact structure of the axisymmetric
// meridian chain (node i couples only to i-1 and i+1). Factorised by block LDL^T in O(n) with a
// Cholesky of every pivot block, which doubles as the positive-definiteness check. The 3x3 kernels
// are written out (block_tridiag.cc): Eigen's LLT solve with a matrix right-hand side goes through
// its dynamic-size triangular solver, which costs more than the arithmetic at this size.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace vs {

class BlockTridiag {
 public:
  using Block = Eigen::Matrix3d;

  explicit BlockTridiag(int blocks = 0) { resize(blocks); }
  void resize(int blocks);
  void set_zero();
  int blocks() const { return static_cast<int>(diag_.size()); }

  Block& diag(int i) { return diag_[i]; }
  const Block& diag(int i) const { return diag_[i]; }
  // Coupling block K(i+1, i); K(i, i+1) is its transpose.
  Block& lower(int i) { return lower_[i]; }
  const Block& lower(int i) const { return lower_[i]; }

  // Replaces row and column of dof (block i, component a) by the identity.
  void fix_dof(int i, int a);

  // y = K x.
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;

  // Factorises; false if a pivot block is not positive definite.
  bool factorize();
  // Solves K x = b with the last factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The same, overwriting b with x (no allocation).
  void solve_in_place(Eigen::VectorXd* b) const;

 private:
  std::vector<Block> diag_, lower_;
  // Cholesky factor L of every pivot block P_i = L L^T (lower triangle; the diagonal holds
  // 1 / L(a, a)).
  std::vector<Block> pivot_;
  std::vector<Block> W_;  // W_i = lower(i-1) * P_(i-1)^-1
};

}  // namespace vs
