// The numeric supernodal Cholesky factorisation P A P' = L L' on two threads, written into the
// storage of a CHOLMOD supernodal factor (linalg/supernodal_structure.h), so that CHOLMOD's
// solves and everything that reads its factor work on the result. CHOLMOD 3's own factorisation
// runs on one thread (its BLAS is kept on the calling thread, linalg/blas_library.h) while the
// second core waits: on the ex4a quarter disc at n = 16, 60 factorisations of 33 ms, 2 s of a
// 14 s run to 10 mm (experiments/09_linear_solver).
//
// Left-looking, supernode by supernode (as CHOLMOD's t_cholmod_super_numeric): supernode j's
// block (nsrow x nscol, column-major) is cleared, A's lower entries of its columns are scattered
// into it, every descendant d whose rows below its diagonal block meet j's columns subtracts
//   C = L_d[rows of d from k1 on, :] L_d[rows of d in k1..k2-1, :]'
// at the rows and columns they map to in j, and then the diagonal block is factorised (LLT)
// and the rows below it solved against its transpose.
//
// Two threads: the elimination tree is cut (linalg/tree_cut.h) with the work of a supernode =
// its own flops + the flops of the updates it sends. A part's supernodes are factorised by one
// thread, ascending; every update they send into the top set goes into that part's buffer (the
// layout of the top set's blocks). Then, on one thread, each top supernode ascending: A's
// entries, plus part 0's buffer, plus part 1's, minus the updates of its top descendants
// ascending, and its dense factorisation. Every sum has a fixed order, so the factor has the
// same bits for any number of threads (not CHOLMOD's bits: its sums are ordered otherwise).
#pragma once

#include <cholmod.h>

#include <Eigen/Core>
#include <array>
#include <vector>

#include "linalg/aligned_buffer.h"
#include "linalg/sparse_matrix.h"
#include "linalg/supernodal_structure.h"
#include "linalg/tree_cut.h"

namespace vs {

class SupernodalCholesky {
 public:
  // Takes the structure of a supernodal LL' factor (int indices, real double values allocated,
  // i.e. after one CHOLMOD factorisation) and builds the schedule; false (and holds nothing) for
  // any other kind of factor.
  bool analyze(const cholmod_factor& L);
  bool analyzed() const { return n_ > 0; }
  // Whether L has the structure analyze() took (the same pattern and ordering; any object).
  bool fits(const cholmod_factor& L) const;
  // Overwrites L.x with the factor of P A P', A symmetric in full storage (both triangles are
  // read: an entry (i, k) of P A P' with i >= k from column perm[k]). False if a diagonal block is
  // not positive definite (or not finite), or if A has an entry outside L's structure; L.x is then
  // partly overwritten and the caller factorises again by other means.
  bool factorize(const SparseMatrix& A, cholmod_factor* L);

  const TreeCut& cut() const { return cut_; }

 private:
  // An update of supernode j by its descendant d: d's rows from index p1 (the first at or after
  // j's first column) to the end, those before p2 in j's columns; rel: their rows in j's block.
  struct Update {
    int d = 0, j = 0, p1 = 0, p2 = 0;
    std::vector<int> rel;
  };
  struct Workspace {
    std::vector<int> local;  // row -> its index in the block being assembled
    AlignedBuffer<double> C;
  };
  bool assemble(const SparseMatrix& A, int j, double* block, Workspace* w) const;
  void apply(const Update& u, const double* x, double* target, Workspace* w) const;
  bool factor_block(int j, double* x) const;
  void copy_block(int j, double* to) const;

  int n_ = 0;
  SupernodalStructure st_;
  std::vector<int> inverse_perm_;
  // The factor is computed here, 64-byte aligned (linalg/aligned_buffer.h: its bits then do not
  // depend on where CHOLMOD's array lies), in CHOLMOD's layout, and each block copied to L.x.
  AlignedBuffer<double> x_;
  TreeCut cut_;
  std::vector<Update> updates_;
  std::vector<std::vector<int>> into_, from_;  // per supernode: updates into / from it, ascending
  std::vector<size_t> top_offset_;             // per supernode of the top set: its buffer offset
  size_t top_size_ = 0;
  mutable std::array<std::vector<double>, TreeCut::kParts> buffer_;
  mutable std::array<Workspace, TreeCut::kParts> workspace_;
};

}  // namespace vs
