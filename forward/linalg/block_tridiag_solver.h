// LinearSolver over a BlockTridiag matrix it owns (the axisymmetric meridian chain): the problem
// assembles into matrix(), the Newton loop factorises and solves (block LDL^T, or block LU once
// the matrix is made unsymmetric by consistent Coulomb friction).
#pragma once

#include "linalg/block_tridiag.h"
#include "linalg/linear_solver.h"

namespace vs {

class BlockTridiagSolver : public LinearSolver {
 public:
  BlockTridiag& matrix() { return K_; }
  const BlockTridiag& matrix() const { return K_; }

  bool factorize() override {
    factorized_ = true;
    return K_.factorize();
  }
  void solve_in_place(Eigen::VectorXd* b) const override { K_.solve_in_place(b); }
  double condition_estimate() const override { return K_.condition_estimate(); }
  bool has_factorization() const override { return factorized_; }
  std::string name() const override { return "block tridiagonal LDL^T / LU"; }

 private:
  BlockTridiag K_;
  bool factorized_ = false;
};

}  // namespace vs
