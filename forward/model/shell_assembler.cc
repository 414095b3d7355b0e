#include "model/shell_assembler.h"

#include <algorithm>

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

  // Fixed-order reduction.
  force->setZero(n_);
  double potential = 0.0;
  if (want_matrix) std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
  double* val = K_.valuePtr();
  for (int e = 0; e < ne; ++e) {
    const ElementContribution& c = buffers_[e];
    const auto& d = edofs_[e];
    for (std::size_t a = 0; a < d.size(); ++a) (*force)(d[a]) += c.force(static_cast<int>(a));
    potential += c.potential;
    if (want_matrix) {
      const double* k = c.stiffness.data();  // column-major, like the scatter map
      const auto& s = scatter_[e];
      for (std::size_t i = 0; i < s.size(); ++i) val[s[i]] += k[i];
    }
  }
  return potential;
}

void ShellAssembler::apply_constraints(const std::vector<char>& fixed,
                                       const std::vector<double>& value, Eigen::VectorXd* rhs) {
  for (int j = 0; j < n_; ++j) {
    for (SparseMatrix::InnerIterator it(K_, j); it; ++it) {
      const auto i = static_cast<int>(it.row());
      if (fixed[j] && !fixed[i]) (*rhs)(i) -= it.value() * value[j];
    }
  }
  for (int j = 0; j < n_; ++j) {
    for (SparseMatrix::InnerIterator it(K_, j); it; ++it) {
      const auto i = static_cast<int>(it.row());
      if (i == j && fixed[j]) {
        if (it.value() == 0.0) it.valueRef() = 1.0;
        (*rhs)(j) = it.value() * value[j];
      } else if (fixed[i] || fixed[j]) {
        it.valueRef() = 0.0;
      }
    }
  }
}

}  // namespace vs::shell3d
