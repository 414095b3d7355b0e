#include "linalg/supernodal_factor.h"

#include <algorithm>

namespace vs {

template <typename Scalar>
bool SupernodalFactor<Scalar>::assign(const cholmod_factor& L) {
  n_ = 0;
  if (!SupernodalStructure::readable(L)) return false;
  const bool same_structure = st_.matches(L);
  if (!same_structure) st_.assign(L);
  const double* x = static_cast<const double*>(L.x);
  x_.resize(L.xsize);
  std::transform(x, x + L.xsize, x_.data(), [](double v) { return static_cast<Scalar>(v); });
  y_.resize(L.n);
  for (auto& w : work_) w.resize(std::max<size_t>(L.maxesize, 1));
  n_ = static_cast<int>(L.n);
  if (!same_structure) cut_tree();
  return true;
}

template <typename Scalar>
void SupernodalFactor<Scalar>::cut_tree() {
  std::vector<double> entries(static_cast<size_t>(st_.num_supernodes()));
  for (int j = 0; j < st_.num_supernodes(); ++j) entries[j] = static_cast<double>(st_.entries(j));
  cut_ = vs::cut_tree(st_.parents(), entries);
  slot_.assign(static_cast<size_t>(n_), -1);
  top_columns_.clear();
  for (int j : cut_.top)
    for (int k = st_.super[j]; k < st_.super[j + 1]; ++k) {
      slot_[k] = static_cast<int>(top_columns_.size());
      top_columns_.push_back(k);
    }
  for (auto& a : acc_) a.resize(std::max<size_t>(top_columns_.size(), 1));
}

template <typename Scalar>
void SupernodalFactor<Scalar>::forward(const std::vector<int>& supernodes, Scalar* acc,
                                       Scalar* work) const {
  using ConstBlock = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>, 0,
                                Eigen::OuterStride<>>;
  using Vector = Eigen::Map<Eigen::Matrix<Scalar, Eigen::Dynamic, 1>>;
  if (acc) std::fill(acc, acc + top_columns_.size(), Scalar(0));
  Vector y(y_.data(), n_);
  for (int s : supernodes) {
    const int k1 = st_.super[s], nscol = st_.columns(s);
    const int nsrow = st_.rows(s), nb = nsrow - nscol;
    const int* rows = st_.row_indices(s);
    const ConstBlock Ls(x_.data() + st_.px[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y.segment(k1, nscol);
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().solveInPlace(ys);
    if (nb > 0) {
      Vector w(work, nb);
      w.noalias() = Ls.bottomRows(nb) * ys;
      for (int i = 0; i < nb; ++i) {
        const int row = rows[nscol + i];
        if (acc && slot_[row] >= 0) {
          acc[slot_[row]] += w[i];
        } else {
          y_[row] -= w[i];
        }
      }
    }
  }
}

template <typename Scalar>
void SupernodalFactor<Scalar>::backward(const std::vector<int>& supernodes, Scalar* work) const {
  using ConstBlock = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>, 0,
                                Eigen::OuterStride<>>;
  using Vector = Eigen::Map<Eigen::Matrix<Scalar, Eigen::Dynamic, 1>>;
  Vector y(y_.data(), n_);
  for (auto it = supernodes.rbegin(); it != supernodes.rend(); ++it) {
    const int s = *it;
    const int k1 = st_.super[s], nscol = st_.columns(s);
    const int nsrow = st_.rows(s), nb = nsrow - nscol;
    const int* rows = st_.row_indices(s);
    const ConstBlock Ls(x_.data() + st_.px[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y.segment(k1, nscol);
    if (nb > 0) {
      Vector w(work, nb);
      for (int i = 0; i < nb; ++i) w[i] = y_[rows[nscol + i]];
      ys.noalias() -= Ls.bottomRows(nb).transpose() * w;
    }
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().transpose().solveInPlace(ys);
  }
}

template <typename Scalar>
void SupernodalFactor<Scalar>::solve(const Eigen::VectorXd& r, Eigen::VectorXd* z) const {
  for (int i = 0; i < n_; ++i) y_[i] = static_cast<Scalar>(r[st_.perm[i]]);
    // Forward: L y = P r, the parts in parallel, then their top-set updates in part order and the
    // top set; backward: L' x = y, the top set, then the parts in parallel.
#pragma omp parallel for schedule(static, 1) if (n_ >= SupernodalStructure::kParallelFrom)
  for (int p = 0; p < kParts; ++p) forward(cut_.part[p], acc_[p].data(), work_[p].data());
  for (int p = 0; p < kParts; ++p)
    for (size_t k = 0; k < top_columns_.size(); ++k) y_[top_columns_[k]] -= acc_[p][k];
  forward(cut_.top, nullptr, work_[0].data());
  backward(cut_.top, work_[0].data());
#pragma omp parallel for schedule(static, 1) if (n_ >= SupernodalStructure::kParallelFrom)
  for (int p = 0; p < kParts; ++p) backward(cut_.part[p], work_[p].data());
  z->resize(n_);
  for (int i = 0; i < n_; ++i) (*z)[st_.perm[i]] = static_cast<double>(y_[i]);
}

template class SupernodalFactor<float>;
template class SupernodalFactor<double>;

}  // namespace vs
