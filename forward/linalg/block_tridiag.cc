#include "linalg/block_tridiag.h"

#include <Eigen/LU>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace vs {

void BlockTridiag::resize(int blocks) {
  diag_.assign(blocks, Block::Zero());
  lower_.assign(blocks > 0 ? blocks - 1 : 0, Block::Zero());
  pivot_.assign(blocks, Block::Zero());
  W_.assign(blocks, Block::Zero());
  symmetric_ = true;
  fixed_.assign(3 * static_cast<std::size_t>(blocks), 0);
}

void BlockTridiag::set_zero() {
  for (auto& b : diag_) b.setZero();
  for (auto& b : lower_) b.setZero();
  symmetric_ = true;
  std::fill(fixed_.begin(), fixed_.end(), 0);
}

void BlockTridiag::unsymmetric() {
  if (!symmetric_) return;
  upper_.resize(lower_.size());
  for (std::size_t i = 0; i < lower_.size(); ++i) upper_[i] = lower_[i].transpose();
  symmetric_ = false;
}

void BlockTridiag::fix_dof(int i, int a) {
  diag_[i].row(a).setZero();
  diag_[i].col(a).setZero();
  diag_[i](a, a) = 1.0;
  fixed_[3 * static_cast<std::size_t>(i) + a] = 1;
  if (i > 0) lower_[i - 1].row(a).setZero();         // K(i, i-1) row a
  if (i + 1 < blocks()) lower_[i].col(a).setZero();  // K(i+1, i) column a
  if (!symmetric_) {
    if (i + 1 < blocks()) upper_[i].row(a).setZero();  // K(i, i+1) row a
    if (i > 0) upper_[i - 1].col(a).setZero();         // K(i-1, i) column a
  }
}

Eigen::VectorXd BlockTridiag::multiply(const Eigen::VectorXd& x) const {
  const int n = blocks();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * n);
  for (int i = 0; i < n; ++i) {
    y.segment<3>(3 * i) += diag_[i] * x.segment<3>(3 * i);
    if (i + 1 < n) {
      y.segment<3>(3 * (i + 1)) += lower_[i] * x.segment<3>(3 * i);
      y.segment<3>(3 * i) +=
          (symmetric_ ? Block(lower_[i].transpose()) : upper_[i]) * x.segment<3>(3 * (i + 1));
    }
  }
  return y;
}

namespace {

using Block = BlockTridiag::Block;

// Cholesky P = L L^T of a symmetric 3x3 block (lower triangle of P read); stores 1 / L(a, a) on
// the diagonal. False unless every pivot is positive (and finite).
bool cholesky3(const Block& P, Block* L) {
  Block& F = *L;
  const double l00 = P(0, 0);
  if (!(l00 > 0.0)) return false;
  F(0, 0) = 1.0 / std::sqrt(l00);
  F(1, 0) = P(1, 0) * F(0, 0);
  F(2, 0) = P(2, 0) * F(0, 0);
  const double l11 = P(1, 1) - F(1, 0) * F(1, 0);
  if (!(l11 > 0.0)) return false;
  F(1, 1) = 1.0 / std::sqrt(l11);
  F(2, 1) = (P(2, 1) - F(2, 0) * F(1, 0)) * F(1, 1);
  const double l22 = P(2, 2) - F(2, 0) * F(2, 0) - F(2, 1) * F(2, 1);
  if (!(l22 > 0.0) || !std::isfinite(l22)) return false;
  F(2, 2) = 1.0 / std::sqrt(l22);
  return true;
}

// y = L^-1 b (forward substitution).
Eigen::Vector3d lower_solve(const Block& F, const Eigen::Vector3d& b) {
  Eigen::Vector3d y;
  y(0) = b(0) * F(0, 0);
  y(1) = (b(1) - F(1, 0) * y(0)) * F(1, 1);
  y(2) = (b(2) - F(2, 0) * y(0) - F(2, 1) * y(1)) * F(2, 2);
  return y;
}

// x = L^-T y (back substitution).
Eigen::Vector3d upper_solve(const Block& F, const Eigen::Vector3d& y) {
  Eigen::Vector3d x;
  x(2) = y(2) * F(2, 2);
  x(1) = (y(1) - F(2, 1) * x(2)) * F(1, 1);
  x(0) = (y(0) - F(1, 0) * x(1) - F(2, 0) * x(2)) * F(0, 0);
  return x;
}

}  // namespace

void BlockTridiag::estimate_condition() {
  // pivot_ holds 1 / L(a, a) on its diagonal.
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (int i = 0; i < blocks(); ++i) {
    for (int a = 0; a < 3; ++a) {
      if (fixed_[3 * static_cast<std::size_t>(i) + a]) continue;
      const double l = 1.0 / pivot_[i](a, a);
      lo = std::min(lo, l);
      hi = std::max(hi, l);
    }
  }
  condition_estimate_ = hi > 0.0 ? (hi / lo) * (hi / lo) : 1.0;
}

bool BlockTridiag::factorize_unsymmetric() {
  // Block LU: U_0 = K_00, W_i = K(i, i-1) U_(i-1)^-1, U_i = K_ii - W_i K(i-1, i).
  const int n = blocks();
  pivot_inverse_.resize(n);
  for (int i = 0; i < n; ++i) {
    Block U = diag_[i];
    if (i > 0) {
      W_[i].noalias() = lower_[i - 1] * pivot_inverse_[i - 1];
      U.noalias() -= W_[i] * upper_[i - 1];
    }
    const Block S = 0.5 * (U + U.transpose());
    if (!cholesky3(S, &pivot_[i])) return false;
    pivot_inverse_[i] = U.inverse();
    if (!pivot_inverse_[i].allFinite()) return false;
  }
  estimate_condition();
  return true;
}

bool BlockTridiag::factorize() {
  if (!symmetric_) return factorize_unsymmetric();
  // Block elimination: P_0 = K_00; with C = K(i, i-1) and Y = L_(i-1)^-1 C^T,
  //   W_i = C P_(i-1)^-1 = (L_(i-1)^-T Y)^T,  P_i = K_ii - W_i C^T = K_ii - Y^T Y.
  const int n = blocks();
  for (int i = 0; i < n; ++i) {
    Block P = diag_[i];
    if (i > 0) {
      const Block& C = lower_[i - 1];
      Block Y;
      for (int j = 0; j < 3; ++j) Y.col(j) = lower_solve(pivot_[i - 1], C.row(j).transpose());
      for (int j = 0; j < 3; ++j) W_[i].row(j) = upper_solve(pivot_[i - 1], Y.col(j)).transpose();
      P.noalias() -= Y.transpose() * Y;
    }
    if (!cholesky3(P, &pivot_[i])) return false;
  }
  estimate_condition();
  return true;
}

Eigen::VectorXd BlockTridiag::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  solve_in_place(&x);
  return x;
}

void BlockTridiag::solve_in_place(Eigen::VectorXd* b) const {
  // Forward: y_i = b_i - W_i y_(i-1); backward: x_i = P_i^-1 (y_i - K(i+1, i)^T x_(i+1)). Both
  // sweeps overwrite b block by block.
  const int n = blocks();
  assert(b->size() == 3 * n);
  Eigen::VectorXd& y = *b;
  for (int i = 1; i < n; ++i) {
    const Eigen::Vector3d prev = y.segment<3>(3 * (i - 1));
    y.segment<3>(3 * i) -= W_[i] * prev;
  }
  if (!symmetric_) {
    for (int i = n - 1; i >= 0; --i) {
      Eigen::Vector3d rhs = y.segment<3>(3 * i);
      if (i + 1 < n) rhs -= upper_[i] * y.segment<3>(3 * (i + 1));
      y.segment<3>(3 * i) = pivot_inverse_[i] * rhs;
    }
    return;
  }
  for (int i = n - 1; i >= 0; --i) {
    Eigen::Vector3d rhs = y.segment<3>(3 * i);
    if (i + 1 < n) rhs -= lower_[i].transpose() * y.segment<3>(3 * (i + 1));
    y.segment<3>(3 * i) = upper_solve(pivot_[i], lower_solve(pivot_[i], rhs));
  }
}

}  // namespace vs
