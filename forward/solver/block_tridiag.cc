#include "solver/block_tridiag.h"

#include <cassert>

namespace vs {

void BlockTridiag::resize(int blocks) {
  diag_.assign(blocks, Block::Zero());
  lower_.assign(blocks > 0 ? blocks - 1 : 0, Block::Zero());
  pivot_.resize(blocks);
  W_.assign(blocks, Block::Zero());
}

void BlockTridiag::set_zero() {
  for (auto& b : diag_) b.setZero();
  for (auto& b : lower_) b.setZero();
}

void BlockTridiag::fix_dof(int i, int a) {
  diag_[i].row(a).setZero();
  diag_[i].col(a).setZero();
  diag_[i](a, a) = 1.0;
  if (i > 0) lower_[i - 1].row(a).setZero();         // K(i, i-1) row a
  if (i + 1 < blocks()) lower_[i].col(a).setZero();  // K(i+1, i) column a
}

Eigen::VectorXd BlockTridiag::multiply(const Eigen::VectorXd& x) const {
  const int n = blocks();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    y.segment<3>(3 * i) += diag_[i] * x.segment<3>(3 * i);
    if (i + 1 < n) {
      y.segment<3>(3 * (i + 1)) += lower_[i] * x.segment<3>(3 * i);
      y.segment<3>(3 * i) += lower_[i].transpose() * x.segment<3>(3 * (i + 1));
    }
  }
  return y;
}

bool BlockTridiag::factorize() {
  const int n = blocks();
  Block D = n > 0 ? diag_[0] : Block::Zero();
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      W_[i] = pivot_[i - 1].solve(lower_[i - 1].transpose()).transpose();
      D = diag_[i] - W_[i] * lower_[i - 1].transpose();
    }
    pivot_[i].compute(D);
    if (pivot_[i].info() != Eigen::Success) return false;
  }
  return true;
}

Eigen::VectorXd BlockTridiag::solve(const Eigen::VectorXd& b) const {
  const int n = blocks();
  assert(b.size() == 3 * n);
  Eigen::VectorXd y = b;
  for (int i = 1; i < n; ++i) y.segment<3>(3 * i) -= W_[i] * y.segment<3>(3 * (i - 1));
  Eigen::VectorXd x(3 * n);
  for (int i = n - 1; i >= 0; --i) {
    Eigen::Vector3d rhs = y.segment<3>(3 * i);
    if (i + 1 < n) rhs -= lower_[i].transpose() * x.segment<3>(3 * (i + 1));
    x.segment<3>(3 * i) = pivot_[i].solve(rhs);
  }
  return x;
}

}  // namespace vs
