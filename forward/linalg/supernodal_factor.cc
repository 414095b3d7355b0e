#include "linalg/supernodal_factor.h"

#include <algorithm>

namespace vs {

namespace {

template <typename T>
std::vector<T> copy_array(const void* p, size_t n) {
  const T* a = static_cast<const T*>(p);
  return std::vector<T>(a, a + n);
}

}  // namespace

template <typename Scalar>
bool SupernodalFactor<Scalar>::assign(const cholmod_factor& L) {
  n_ = 0;
  if (!L.is_super || !L.is_ll || L.itype != CHOLMOD_INT || L.xtype != CHOLMOD_REAL ||
      L.dtype != CHOLMOD_DOUBLE || L.x == nullptr) {
    return false;
  }
  const size_t nsuper = L.nsuper;
  perm_ = copy_array<int>(L.Perm, L.n);
  super_ = copy_array<int>(L.super, nsuper + 1);
  pi_ = copy_array<int>(L.pi, nsuper + 1);
  px_ = copy_array<int>(L.px, nsuper + 1);
  s_ = copy_array<int>(L.s, L.ssize);
  const double* x = static_cast<const double*>(L.x);
  x_.resize(L.xsize);
  std::transform(x, x + L.xsize, x_.begin(), [](double v) { return static_cast<Scalar>(v); });
  y_.resize(static_cast<Eigen::Index>(L.n));
  work_.resize(static_cast<Eigen::Index>(std::max<size_t>(L.maxesize, 1)));
  n_ = static_cast<int>(L.n);
  return true;
}

template <typename Scalar>
void SupernodalFactor<Scalar>::solve(const Eigen::VectorXd& r, Eigen::VectorXd* z) const {
  using ConstBlock = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>, 0,
                                Eigen::OuterStride<>>;
  for (int i = 0; i < n_; ++i) y_[i] = static_cast<Scalar>(r[perm_[i]]);
  const int nsuper = static_cast<int>(super_.size()) - 1;
  // Forward: L y = P r.
  for (int s = 0; s < nsuper; ++s) {
    const int k1 = super_[s], nscol = super_[s + 1] - k1;
    const int nsrow = pi_[s + 1] - pi_[s], nb = nsrow - nscol;
    const int* rows = s_.data() + pi_[s];
    const ConstBlock Ls(x_.data() + px_[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y_.segment(k1, nscol);
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().solveInPlace(ys);
    if (nb > 0) {
      auto w = work_.head(nb);
      w.noalias() = Ls.bottomRows(nb) * ys;
      for (int i = 0; i < nb; ++i) y_[rows[nscol + i]] -= w[i];
    }
  }
  // Backward: L' x = y.
  for (int s = nsuper - 1; s >= 0; --s) {
    const int k1 = super_[s], nscol = super_[s + 1] - k1;
    const int nsrow = pi_[s + 1] - pi_[s], nb = nsrow - nscol;
    const int* rows = s_.data() + pi_[s];
    const ConstBlock Ls(x_.data() + px_[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y_.segment(k1, nscol);
    if (nb > 0) {
      auto w = work_.head(nb);
      for (int i = 0; i < nb; ++i) w[i] = y_[rows[nscol + i]];
      ys.noalias() -= Ls.bottomRows(nb).transpose() * w;
    }
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().transpose().solveInPlace(ys);
  }
  z->resize(n_);
  for (int i = 0; i < n_; ++i) (*z)[perm_[i]] = static_cast<double>(y_[i]);
}

template class SupernodalFactor<float>;
template class SupernodalFactor<double>;

}  // namespace vs
