#include "model/shell_assembler.h"

#include <algorithm>
#include <cassert>

namespace vs::shell3d {

ShellAssembler::ShellAssembler(const ShellModel& model) : model_(&model), n_(model.num_dofs()) {
  const int ne = model.num_elements();
  edofs_.resize(ne);
  std::vector<Eigen::Triplet<double, int>> trip;
  for (int e = 0; e < ne; ++e) {
    edofs_[e] = model.element_dofs(e);
    for (int a : edofs_[e])
      for (int b : edofs_[e]) trip.emplace_back(a, b, 0.0);
  }
  K_.resize(n_, n_);
  K_.setFromTriplets(trip.begin(), trip.end());
  K_.makeCompressed();
  scatter_.resize(ne);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  for (int e = 0; e < ne; ++e) {
    const auto& d = edofs_[e];
    auto& s = scatter_[e];
    s.resize(d.size() * d.size());
    for (std::size_t b = 0; b < d.size(); ++b) {
      const int* first = inner + outer[d[b]];
      const int* last = inner + outer[d[b] + 1];
      for (std::size_t a = 0; a < d.size(); ++a)
        s[b * d.size() + a] = static_cast<int>(std::lower_bound(first, last, d[a]) - inner);
    }
  }
  buffers_.resize(ne);
  // Column blocks of about equal numbers of values; a fixed count (not the thread count), so the
  // summation does not depend on the machine. 64 blocks keep 2-8 threads busy and cost 8 bytes per
  // element column.
  constexpr int kBlocks = 64;
  const Eigen::Index nnz = K_.nonZeros();
  block_begin_.assign(1, 0);
  for (int j = 0; j < n_; ++j) {
    const int c = static_cast<int>(block_begin_.size());  // the block j would end
    if (c < kBlocks && outer[j + 1] >= nnz * c / kBlocks) block_begin_.push_back(j + 1);
  }
  if (block_begin_.back() != n_) block_begin_.push_back(n_);
  const int nblocks = static_cast<int>(block_begin_.size()) - 1;
  std::vector<int> block_of(static_cast<std::size_t>(n_));
  for (int c = 0; c < nblocks; ++c)
    for (int j = block_begin_[c]; j < block_begin_[c + 1]; ++j) block_of[j] = c;
  block_columns_.assign(static_cast<std::size_t>(nblocks), {});
  for (int e = 0; e < ne; ++e) {
    for (std::size_t b = 0; b < edofs_[e].size(); ++b) {
      const int c = block_of[static_cast<std::size_t>(edofs_[e][b])];
      block_columns_[static_cast<std::size_t>(c)].push_back({e, static_cast<int>(b)});
    }
  }
}

Eigen::VectorXd ShellAssembler::gather(int e, const Eigen::VectorXd& q) const {
  const auto& d = edofs_[e];
  Eigen::VectorXd qe(static_cast<Eigen::Index>(d.size()));
  for (std::size_t a = 0; a < d.size(); ++a) qe(static_cast<Eigen::Index>(a)) = q(d[a]);
  return qe;
}

double ShellAssembler::assemble(const ElementKernel& kernel, const Eigen::VectorXd& q,
                                bool want_matrix, Eigen::VectorXd* force) {
  const int ne = static_cast<int>(edofs_.size());
#pragma omp parallel for schedule(dynamic, 4)
  for (int e = 0; e < ne; ++e) kernel(e, gather(e, q), &buffers_[e]);

  // Fixed-order reductions: the matrix by column blocks in parallel, each value's terms in
  // element order (see the header); the forces and the potential in element order.
  if (want_matrix) {
    double* val = K_.valuePtr();
    const int* outer = K_.outerIndexPtr();
    const int nblocks = static_cast<int>(block_columns_.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (int c = 0; c < nblocks; ++c) {
      std::fill(val + outer[block_begin_[c]], val + outer[block_begin_[c + 1]], 0.0);
      for (const ElementColumn& ec : block_columns_[static_cast<std::size_t>(c)]) {
        const std::size_t m = edofs_[ec.element].size();
        const std::size_t first = static_cast<std::size_t>(ec.column) * m;
        // Column-major, like the scatter map.
        const double* k = buffers_[ec.element].stiffness.data() + first;
        const int* s = scatter_[ec.element].data() + first;
        for (std::size_t i = 0; i < m; ++i) val[s[i]] += k[i];
      }
    }
  }
  force->setZero(n_);
  double potential = 0.0;
  for (int e = 0; e < ne; ++e) {
    const ElementContribution& c = buffers_[e];
    const auto& d = edofs_[e];
    for (std::size_t a = 0; a < d.size(); ++a) (*force)(d[a]) += c.force(static_cast<int>(a));
    potential += c.potential;
  }
  return potential;
}

void ShellAssembler::apply_constraints(const std::vector<char>& fixed,
                                       const std::vector<double>& value, Eigen::VectorXd* rhs) {
  std::vector<int> columns;  // the fixed dofs, ascending
  for (int j = 0; j < n_; ++j)
    if (fixed[j]) columns.push_back(j);
  const int nf = static_cast<int>(columns.size());
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  double* val = K_.valuePtr();
  // The known columns to the right-hand side, by one thread (the rows of different columns
  // coincide); a zero value moves nothing.
  for (int j : columns) {
    if (value[j] == 0.0) continue;
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (!fixed[inner[k]]) (*rhs)(inner[k]) -= val[k] * value[j];
  }
  // The fixed columns: every value but the diagonal is zeroed; each column writes only its own
  // values and rhs(j).
#pragma omp parallel for schedule(static)
  for (int c = 0; c < nf; ++c) {
    const int j = columns[static_cast<std::size_t>(c)];
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      if (inner[k] != j) {
        val[k] = 0.0;
      } else {
        if (val[k] == 0.0) val[k] = 1.0;
        (*rhs)(j) = val[k] * value[j];
      }
    }
  }
  // The fixed rows: the pattern is symmetric, so row j holds values exactly in the columns i of
  // column j's rows; those of free columns are found by bisection (the rows are sorted). Each
  // value (j, i) has one (i, j): no two iterations write the same value.
#pragma omp parallel for schedule(static)
  for (int c = 0; c < nf; ++c) {
    const int j = columns[static_cast<std::size_t>(c)];
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      if (fixed[i]) continue;
      const int* at = std::lower_bound(inner + outer[i], inner + outer[i + 1], j);
      assert(at != inner + outer[i + 1] && *at == j);
      val[at - inner] = 0.0;
    }
  }
}

}  // namespace vs::shell3d
