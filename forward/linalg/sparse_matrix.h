// The sparse matrix type of the 3D shell: compressed columns, full symmetric storage.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace vs {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// q = A p for a symmetric A stored in full (both triangles). Its compressed columns read as
// compressed rows are the same matrix, so the product runs row by row: one dot product a row,
// in parallel under OpenMP (Eigen's row-major product), each row summed in a fixed order, so the
// same bits for any team.
inline void multiply_symmetric(const SparseMatrix& A, const Eigen::VectorXd& p,
                               Eigen::VectorXd* q) {
  if (!A.isCompressed()) {
    q->noalias() = A * p;
    return;
  }
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> rows(
      A.rows(), A.cols(), A.nonZeros(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
  q->noalias() = rows * p;
}

}  // namespace vs
