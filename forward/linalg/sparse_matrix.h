// The sparse matrix type of the 3D shell: compressed columns, full symmetric storage.
#pragma once

#include <Eigen/SparseCore>

namespace vs {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace vs
