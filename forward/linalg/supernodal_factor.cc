#include "linalg/supernodal_factor.h"

#include <algorithm>
#include <array>

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
  const bool same_structure =
      perm_ == copy_array<int>(L.Perm, L.n) && super_ == copy_array<int>(L.super, nsuper + 1) &&
      pi_ == copy_array<int>(L.pi, nsuper + 1) && px_ == copy_array<int>(L.px, nsuper + 1) &&
      s_ == copy_array<int>(L.s, L.ssize);
  if (!same_structure) {
    perm_ = copy_array<int>(L.Perm, L.n);
    super_ = copy_array<int>(L.super, nsuper + 1);
    pi_ = copy_array<int>(L.pi, nsuper + 1);
    px_ = copy_array<int>(L.px, nsuper + 1);
    s_ = copy_array<int>(L.s, L.ssize);
  }
  const double* x = static_cast<const double*>(L.x);
  x_.resize(L.xsize);
  std::transform(x, x + L.xsize, x_.begin(), [](double v) { return static_cast<Scalar>(v); });
  y_.resize(static_cast<Eigen::Index>(L.n));
  for (Vector& w : work_) w.resize(static_cast<Eigen::Index>(std::max<size_t>(L.maxesize, 1)));
  n_ = static_cast<int>(L.n);
  if (!same_structure) cut_tree();
  return true;
}

template <typename Scalar>
void SupernodalFactor<Scalar>::cut_tree() {
  const int nsuper = static_cast<int>(super_.size()) - 1;
  std::vector<int> column_super(static_cast<size_t>(n_)), parent(static_cast<size_t>(nsuper));
  std::vector<double> work(static_cast<size_t>(nsuper)), subtree(static_cast<size_t>(nsuper), 0.0);
  std::vector<std::vector<int>> children(static_cast<size_t>(nsuper));
  std::vector<int> roots;
  double total = 0.0;
  for (int s = 0; s < nsuper; ++s)
    for (int k = super_[s]; k < super_[s + 1]; ++k) column_super[k] = s;
  for (int s = 0; s < nsuper; ++s) {
    const int nscol = super_[s + 1] - super_[s], nsrow = pi_[s + 1] - pi_[s];
    parent[s] = nsrow > nscol ? column_super[s_[pi_[s] + nscol]] : -1;
    work[s] = static_cast<double>(nsrow) * nscol;
    total += work[s];
    subtree[s] += work[s];  // the children (smaller indices) have added theirs
    if (parent[s] >= 0) {
      subtree[parent[s]] += subtree[s];
      children[parent[s]].push_back(s);
    } else {
      roots.push_back(s);
    }
  }
  // Longest-processing-time packing of the subtrees: the parts' loads, and each subtree's part.
  auto pack = [&](std::vector<int> trees, std::vector<int>* part_of) {
    std::sort(trees.begin(), trees.end(), [&](int a, int b) {
      return subtree[a] != subtree[b] ? subtree[a] > subtree[b] : a < b;
    });
    std::array<double, kParts> load{};
    for (int t : trees) {
      const int p = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      load[p] += subtree[t];
      if (part_of) (*part_of)[t] = p;
    }
    return *std::max_element(load.begin(), load.end());
  };
  // Cut the heaviest subtree while that helps; replay the best number of cuts.
  constexpr int kMaxCuts = 256;
  auto cut = [&](std::vector<int>* trees, double* top_work, std::vector<int>* top) {
    auto heaviest = std::max_element(trees->begin(), trees->end(), [&](int a, int b) {
      return subtree[a] != subtree[b] ? subtree[a] < subtree[b] : a > b;
    });
    const int s = *heaviest;
    if (children[s].empty()) return false;
    trees->erase(heaviest);
    trees->insert(trees->end(), children[s].begin(), children[s].end());
    *top_work += work[s];
    if (top) top->push_back(s);
    return true;
  };
  std::vector<int> trees = roots;
  double top_work = 0.0;
  double best = pack(trees, nullptr);
  int best_cuts = 0;
  for (int k = 1; k <= kMaxCuts && cut(&trees, &top_work, nullptr); ++k) {
    const double critical = top_work + pack(trees, nullptr);
    if (critical < best) best = critical, best_cuts = k;
  }
  trees = roots;
  top_work = 0.0;
  top_.clear();
  for (int k = 0; k < best_cuts; ++k) cut(&trees, &top_work, &top_);
  std::vector<int> part_of(static_cast<size_t>(nsuper), -1);
  const double largest = pack(trees, &part_of);
  for (auto& p : part_) p.clear();
  for (int t : trees) {  // every supernode of the subtree under t
    std::vector<int> stack{t};
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      part_[part_of[t]].push_back(s);
      stack.insert(stack.end(), children[s].begin(), children[s].end());
    }
  }
  for (auto& p : part_) std::sort(p.begin(), p.end());
  std::sort(top_.begin(), top_.end());
  slot_.assign(static_cast<size_t>(n_), -1);
  top_columns_.clear();
  for (int s : top_)
    for (int k = super_[s]; k < super_[s + 1]; ++k) {
      slot_[k] = static_cast<int>(top_columns_.size());
      top_columns_.push_back(k);
    }
  for (Vector& a : acc_) a.resize(static_cast<Eigen::Index>(top_columns_.size()));
  top_fraction_ = total > 0.0 ? top_work / total : 0.0;
  largest_part_fraction_ = total > 0.0 ? largest / total : 0.0;
}

template <typename Scalar>
void SupernodalFactor<Scalar>::forward(const std::vector<int>& supernodes, Vector* acc,
                                       Vector* work) const {
  using ConstBlock = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>, 0,
                                Eigen::OuterStride<>>;
  if (acc) acc->setZero();
  for (int s : supernodes) {
    const int k1 = super_[s], nscol = super_[s + 1] - k1;
    const int nsrow = pi_[s + 1] - pi_[s], nb = nsrow - nscol;
    const int* rows = s_.data() + pi_[s];
    const ConstBlock Ls(x_.data() + px_[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y_.segment(k1, nscol);
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().solveInPlace(ys);
    if (nb > 0) {
      auto w = work->head(nb);
      w.noalias() = Ls.bottomRows(nb) * ys;
      for (int i = 0; i < nb; ++i) {
        const int row = rows[nscol + i];
        if (acc && slot_[row] >= 0) {
          (*acc)[slot_[row]] += w[i];
        } else {
          y_[row] -= w[i];
        }
      }
    }
  }
}

template <typename Scalar>
void SupernodalFactor<Scalar>::backward(const std::vector<int>& supernodes, Vector* work) const {
  using ConstBlock = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>, 0,
                                Eigen::OuterStride<>>;
  for (auto it = supernodes.rbegin(); it != supernodes.rend(); ++it) {
    const int s = *it;
    const int k1 = super_[s], nscol = super_[s + 1] - k1;
    const int nsrow = pi_[s + 1] - pi_[s], nb = nsrow - nscol;
    const int* rows = s_.data() + pi_[s];
    const ConstBlock Ls(x_.data() + px_[s], nsrow, nscol, Eigen::OuterStride<>(nsrow));
    auto ys = y_.segment(k1, nscol);
    if (nb > 0) {
      auto w = work->head(nb);
      for (int i = 0; i < nb; ++i) w[i] = y_[rows[nscol + i]];
      ys.noalias() -= Ls.bottomRows(nb).transpose() * w;
    }
    Ls.topRows(nscol).template triangularView<Eigen::Lower>().transpose().solveInPlace(ys);
  }
}

template <typename Scalar>
void SupernodalFactor<Scalar>::solve(const Eigen::VectorXd& r, Eigen::VectorXd* z) const {
  for (int i = 0; i < n_; ++i) y_[i] = static_cast<Scalar>(r[perm_[i]]);
  // Forward: L y = P r, the parts in parallel, then their top-set updates in part order and the
  // top set; backward: L' x = y, the top set, then the parts in parallel.
  constexpr int kParallelFrom = 2000;  // unknowns; only the team size depends on it, not the bits
#pragma omp parallel for schedule(static, 1) if (n_ >= kParallelFrom)
  for (int p = 0; p < kParts; ++p) forward(part_[p], &acc_[p], &work_[p]);
  for (int p = 0; p < kParts; ++p)
    for (size_t k = 0; k < top_columns_.size(); ++k) y_[top_columns_[k]] -= acc_[p][k];
  forward(top_, nullptr, &work_[0]);
  backward(top_, &work_[0]);
#pragma omp parallel for schedule(static, 1) if (n_ >= kParallelFrom)
  for (int p = 0; p < kParts; ++p) backward(part_[p], &work_[p]);
  z->resize(n_);
  for (int i = 0; i < n_; ++i) (*z)[perm_[i]] = static_cast<double>(y_[i]);
}

template class SupernodalFactor<float>;
template class SupernodalFactor<double>;

}  // namespace vs
