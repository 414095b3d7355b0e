// Assembly of element matrices and vectors into a sparse matrix with a fixed pattern.
//
// The pattern (full symmetric storage, compressed columns) is built once from the element dof
// lists, together with a scatter map from every element matrix entry to its slot in the value
// array; later assemblies only write values, so the sparse Cholesky's symbolic analysis is done
// once (numerics.md 4.2). Element evaluation runs in parallel (OpenMP) into per-element buffers.
// The matrix buffers are then summed in parallel over fixed blocks of global columns: a block adds
// the element columns that fall in it, element by element, so every value receives its terms in
// element order and the assembled values are bitwise identical whatever the number of threads
// (and to a summation by one thread). Forces and potential are summed by one thread.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "linalg/sparse_matrix.h"
#include "model/shell_model.h"

namespace vs::shell3d {

using vs::SparseMatrix;

struct ElementContribution {
  Eigen::VectorXd force;      // element dofs
  Eigen::MatrixXd stiffness;  // element dofs (may be left empty when no matrix is wanted)
  double potential = 0.0;
};

// Evaluates element e at its element velocities q_e.
using ElementKernel =
    std::function<void(int e, const Eigen::VectorXd& q_e, ElementContribution* out)>;

class ShellAssembler {
 public:
  explicit ShellAssembler(const ShellModel& model);

  int num_dofs() const { return n_; }
  const SparseMatrix& matrix() const { return K_; }
  SparseMatrix& matrix() { return K_; }

  // Gathers element velocities from the global vector.
  Eigen::VectorXd gather(int e, const Eigen::VectorXd& q) const;

  // K (if want_matrix) and f = sum of element contributions at global velocities q;
  // returns the summed potential.
  double assemble(const ElementKernel& kernel, const Eigen::VectorXd& q, bool want_matrix,
                  Eigen::VectorXd* force);

  // Imposes q_j = g_j on the fixed dofs of K q = rhs without changing the pattern: the known
  // columns move to the right-hand side, rows and columns are zeroed and the diagonal keeps its
  // value (or 1 if it was zero) with rhs_j = diag * g_j. Symmetry and definiteness are kept.
  void apply_constraints(const std::vector<char>& fixed, const std::vector<double>& value,
                         Eigen::VectorXd* rhs);

 private:
  const ShellModel* model_;
  int n_ = 0;
  std::vector<std::vector<int>> edofs_;
  std::vector<std::vector<int>> scatter_;  // per element, column-major (a, b) -> value index
  // Column blocks of K for the parallel summation: block c holds the global columns
  // [block_begin_[c], block_begin_[c + 1]) and, in element order, the element columns that land
  // there (element, local column b).
  struct ElementColumn {
    int element = 0, column = 0;
  };
  std::vector<int> block_begin_;
  std::vector<std::vector<ElementColumn>> block_columns_;
  SparseMatrix K_;
  std::vector<ElementContribution> buffers_;
};

}  // namespace vs::shell3d
