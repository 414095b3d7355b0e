#include "linalg/supernodal_cholesky.h"

#include <omp.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <atomic>
#include <cstring>

namespace vs {

namespace {

using Block = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
using ConstBlock = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
using Ref = Eigen::Ref<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
using ConstRef = Eigen::Ref<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

// The dense kernels work on chunks of at most kChunk rows, columns and depth. Eigen's blocked
// products, triangular solves and LLT pack their operands into buffers of at most that size
// squared, which then lie on the stack (below EIGEN_STACK_ALLOCATION_LIMIT, 128 KB), aligned to
// the 32 bytes of an AVX packet. Larger buffers come from malloc, which the project's Eigen
// settings (cmake/vs_arch.cmake: EIGEN_MALLOC_ALREADY_ALIGNED with 16-byte alignment) take as
// aligned although glibc only guarantees 16 bytes, and the packing's aligned 32-byte stores then
// fault (measured: a segmentation fault in gemm_pack_lhs on a 16-mod-32 heap address, ex4a
// n = 16).
constexpr Eigen::Index kChunk = 96;  // 96 * 96 * 8 bytes = 72 KB

// C -= A B' (C m x n, A m x k, B n x k); lower_only: only the chunks of C on or below its
// diagonal (C square).
void subtract_product(Ref C, ConstRef A, ConstRef B, bool lower_only) {
  const Eigen::Index m = C.rows(), n = C.cols(), k = A.cols();
  for (Eigen::Index j0 = 0; j0 < n; j0 += kChunk) {
    const Eigen::Index nj = std::min(kChunk, n - j0);
    for (Eigen::Index i0 = lower_only ? j0 : 0; i0 < m; i0 += kChunk) {
      const Eigen::Index mi = std::min(kChunk, m - i0);
      for (Eigen::Index p0 = 0; p0 < k; p0 += kChunk) {
        const Eigen::Index kp = std::min(kChunk, k - p0);
        C.block(i0, j0, mi, nj).noalias() -=
            A.block(i0, p0, mi, kp) * B.block(j0, p0, nj, kp).transpose();
      }
    }
  }
}

// X L' = B for X in place of B (B m x n, L n x n lower triangular).
void solve_right_transposed(ConstRef L, Ref B) {
  const Eigen::Index m = B.rows(), n = B.cols();
  for (Eigen::Index k0 = 0; k0 < n; k0 += kChunk) {
    const Eigen::Index kb = std::min(kChunk, n - k0);
    const auto Lkk = L.block(k0, k0, kb, kb);
    for (Eigen::Index r0 = 0; r0 < m; r0 += kChunk) {
      auto Bk = B.block(r0, k0, std::min(kChunk, m - r0), kb);
      Lkk.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(Bk);
    }
    const Eigen::Index rest = n - k0 - kb;
    if (rest > 0) {
      subtract_product(B.middleCols(k0 + kb, rest), B.middleCols(k0, kb),
                       L.block(k0 + kb, k0, rest, kb), false);
    }
  }
}

// A = L L' in place (the lower triangle; A n x n). False if A is not positive definite.
bool cholesky_in_place(Ref A) {
  const Eigen::Index n = A.rows();
  for (Eigen::Index k0 = 0; k0 < n; k0 += kChunk) {
    const Eigen::Index kb = std::min(kChunk, n - k0);
    Ref D = A.block(k0, k0, kb, kb);
    const Eigen::LLT<Ref, Eigen::Lower> llt(D);  // in place
    if (llt.info() != Eigen::Success) return false;
    const Eigen::Index rest = n - k0 - kb;
    if (rest > 0) {
      Ref P = A.block(k0 + kb, k0, rest, kb);
      solve_right_transposed(D, P);
      subtract_product(A.block(k0 + kb, k0 + kb, rest, rest), P, P, true);
    }
  }
  return true;
}

// Eigen's own OpenMP split of a product, which it makes outside a parallel region, is off while
// this lives: that split packs into shared heap buffers (the fault above), and the top set's
// products run on the calling thread like the parts' (the same arithmetic for any team). 0
// restores Eigen's default (the OpenMP team size); nothing else in the project sets it. The
// setting is one global: it is touched only by a thread whose team could split (more than one
// thread), never by the calibration's side-by-side forward runs, which run on one thread each
// (inverse/forward_cache.cc) and so cannot split anyway.
struct SerialEigenProducts {
  const bool touch = omp_get_max_threads() > 1;
  SerialEigenProducts() {
    if (touch) Eigen::setNbThreads(1);
  }
  ~SerialEigenProducts() {
    if (touch) Eigen::setNbThreads(0);
  }
  SerialEigenProducts(const SerialEigenProducts&) = delete;
  SerialEigenProducts& operator=(const SerialEigenProducts&) = delete;
};

}  // namespace

bool SupernodalCholesky::fits(const cholmod_factor& L) const {
  return n_ > 0 && SupernodalStructure::readable(L) && st_.matches(L);
}

bool SupernodalCholesky::analyze(const cholmod_factor& L) {
  n_ = 0;
  if (!SupernodalStructure::readable(L)) return false;
  const int n = static_cast<int>(L.n);
  st_.assign(L);
  inverse_perm_.assign(static_cast<size_t>(n), 0);
  for (int i = 0; i < n; ++i) inverse_perm_[st_.perm[i]] = i;
  const int ns = st_.num_supernodes();
  const std::vector<int> of = st_.column_supernodes();

  // The updates, by descendant ascending; their rows in the target's block (both row lists are
  // sorted, the descendant's rows from p1 on a subset of the target's).
  updates_.clear();
  into_.assign(static_cast<size_t>(ns), {});
  from_.assign(static_cast<size_t>(ns), {});
  std::vector<double> work(static_cast<size_t>(ns), 0.0);
  for (int d = 0; d < ns; ++d) {
    const int nscol = st_.columns(d), nsrow = st_.rows(d);
    const int* rows = st_.row_indices(d);
    if (!std::is_sorted(rows, rows + nsrow)) return false;
    work[d] += nscol * static_cast<double>(nscol) * nscol / 3.0 +
               static_cast<double>(nscol) * nscol * (nsrow - nscol);
    for (int p = nscol; p < nsrow;) {
      Update u;
      u.d = d;
      u.j = of[rows[p]];
      u.p1 = p;
      u.p2 = p;
      while (u.p2 < nsrow && rows[u.p2] < st_.super[u.j + 1]) ++u.p2;
      const int* target = st_.row_indices(u.j);
      const int target_rows = st_.rows(u.j);
      u.rel.reserve(static_cast<size_t>(nsrow - p));
      int t = 0;
      for (int q = p; q < nsrow; ++q) {
        while (t < target_rows && target[t] < rows[q]) ++t;
        if (t == target_rows || target[t] != rows[q]) return false;  // not a supernodal structure
        u.rel.push_back(t);
      }
      work[d] += 2.0 * (nsrow - u.p1) * static_cast<double>(u.p2 - u.p1) * nscol;
      into_[u.j].push_back(static_cast<int>(updates_.size()));
      from_[d].push_back(static_cast<int>(updates_.size()));
      p = u.p2;
      updates_.push_back(std::move(u));
    }
  }
  cut_ = cut_tree(st_.parents(), work);

  top_offset_.assign(static_cast<size_t>(ns), 0);
  top_size_ = 0;
  for (int j : cut_.top) {
    top_offset_[j] = top_size_;
    top_size_ += st_.entries(j);
  }
  size_t largest_update = 1;
  for (const Update& u : updates_) {
    largest_update = std::max(largest_update, static_cast<size_t>(st_.rows(u.d) - u.p1) *
                                                  static_cast<size_t>(u.p2 - u.p1));
  }
  for (int p = 0; p < TreeCut::kParts; ++p) {
    buffer_[p].assign(top_size_, 0.0);
    workspace_[p].local.assign(static_cast<size_t>(n), 0);
    workspace_[p].C.resize(largest_update);
  }
  x_.assign(L.xsize, 0.0);
  n_ = n;
  return true;
}

bool SupernodalCholesky::assemble(const SparseMatrix& A, int j, double* block, Workspace* w) const {
  const int k1 = st_.super[j], nscol = st_.columns(j), nsrow = st_.rows(j);
  const int* rows = st_.row_indices(j);
  std::fill(block, block + st_.entries(j), 0.0);
  for (int t = 0; t < nsrow; ++t) w->local[rows[t]] = t;
  for (int c = 0; c < nscol; ++c) {
    const int k = k1 + c;
    double* column = block + static_cast<size_t>(c) * nsrow;
    for (SparseMatrix::InnerIterator it(A, st_.perm[k]); it; ++it) {
      const int i = inverse_perm_[it.row()];
      if (i < k) continue;
      // An entry outside L's structure (A's pattern not the analysed one): refuse.
      const int t = w->local[i];
      if (t >= nsrow || rows[t] != i) return false;
      column[t] += it.value();
    }
  }
  return true;
}

void SupernodalCholesky::apply(const Update& u, const double* x, double* target,
                               Workspace* w) const {
  const int nsrow_d = st_.rows(u.d), nscol_d = st_.columns(u.d);
  const int m1 = u.p2 - u.p1, m2 = nsrow_d - u.p1;
  const ConstBlock Ld(x + st_.px[u.d], nsrow_d, nscol_d, Eigen::OuterStride<>(nsrow_d));
  // C = -L_d[p1:, :] L_d[p1:p2, :]'
  Block C(w->C.data(), m2, m1, Eigen::OuterStride<>(m2));
  C.setZero();
  subtract_product(C, Ld.middleRows(u.p1, m2), Ld.middleRows(u.p1, m1), false);
  const int nsrow_j = st_.rows(u.j), k1 = st_.super[u.j];
  const int* rows = st_.row_indices(u.d) + u.p1;
  for (int cc = 0; cc < m1; ++cc) {
    double* column = target + static_cast<size_t>(rows[cc] - k1) * nsrow_j;
    for (int rr = cc; rr < m2; ++rr) column[u.rel[rr]] += C(rr, cc);
  }
}

bool SupernodalCholesky::factor_block(int j, double* x) const {
  const int nscol = st_.columns(j), nsrow = st_.rows(j), nb = nsrow - nscol;
  Block B(x + st_.px[j], nsrow, nscol, Eigen::OuterStride<>(nsrow));
  // Eigen's LLT refuses a pivot <= 0 only: a NaN one would pass.
  if (!cholesky_in_place(B.topRows(nscol)) || !B.topRows(nscol).diagonal().allFinite()) {
    return false;
  }
  // The strictly upper part of the diagonal block is not part of the factor: zero, as CHOLMOD's.
  B.topRows(nscol).triangularView<Eigen::StrictlyUpper>().setZero();
  if (nb > 0) solve_right_transposed(B.topRows(nscol), B.bottomRows(nb));
  return true;
}

void SupernodalCholesky::copy_block(int j, double* to) const {
  std::memcpy(to + st_.px[j], x_.data() + st_.px[j], st_.entries(j) * sizeof(double));
}

bool SupernodalCholesky::factorize(const SparseMatrix& A, cholmod_factor* L) {
  if (!fits(*L) || A.rows() != n_ || !A.isCompressed()) return false;
  const SerialEigenProducts serial;
  double* x = x_.data();
  double* to = static_cast<double*>(L->x);
  // A part that fails stops the other (which then ends with its work unfinished: the whole
  // factorisation is refused either way).
  std::atomic<bool> failed{false};
#pragma omp parallel for schedule(static, 1) if (n_ >= SupernodalStructure::kParallelFrom)
  for (int p = 0; p < TreeCut::kParts; ++p) {
    Workspace& w = workspace_[p];
    std::fill(buffer_[p].begin(), buffer_[p].end(), 0.0);
    for (int j : cut_.part[p]) {
      if (failed.load(std::memory_order_relaxed)) break;
      double* block = x + st_.px[j];
      bool ok = assemble(A, j, block, &w);
      if (ok) {
        for (int u : into_[j]) apply(updates_[u], x, block, &w);  // all from this part
        ok = factor_block(j, x);
      }
      if (!ok) {
        failed.store(true, std::memory_order_relaxed);
        break;
      }
      for (int u : from_[j]) {
        const Update& up = updates_[u];
        if (cut_.group[up.j] < 0) apply(up, x, buffer_[p].data() + top_offset_[up.j], &w);
      }
      copy_block(j, to);
    }
  }
  if (failed.load()) return false;
  Workspace& w = workspace_[0];
  for (int j : cut_.top) {
    double* block = x + st_.px[j];
    if (!assemble(A, j, block, &w)) return false;
    const size_t size = st_.entries(j);
    for (int p = 0; p < TreeCut::kParts; ++p) {
      const double* b = buffer_[p].data() + top_offset_[j];
      for (size_t i = 0; i < size; ++i) block[i] += b[i];
    }
    for (int u : into_[j])
      if (cut_.group[updates_[u].d] < 0) apply(updates_[u], x, block, &w);
    if (!factor_block(j, x)) return false;
    copy_block(j, to);
  }
  L->minor = L->n;
  return true;
}

}  // namespace vs
