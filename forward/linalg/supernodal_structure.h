// The structure of a CHOLMOD supernodal LL' factor (cholmod_factor: Perm, super, pi, px, s), read
// once and shared by the two-thread factorisation (linalg/supernodal_cholesky.h) and the
// triangular solves (linalg/supernodal_factor.h). Supernode j holds the columns super[j] ..
// super[j+1]-1 and the rows s[pi[j]] .. s[pi[j+1]-1] (the first columns(j) of them its own
// columns, sorted), its values a dense rows(j) x columns(j) column-major block at x[px[j]]; the
// factor is of P A P' with (P b)_i = b[perm[i]].
#pragma once

#include <cholmod.h>

#include <cstddef>
#include <vector>

namespace vs {

struct SupernodalStructure {
  // Below this many unknowns the two-thread loops run on the calling thread (the same arithmetic).
  static constexpr int kParallelFrom = 2000;

  int n = 0;
  std::vector<int> perm, super, pi, px, s;

  // Whether L is a supernodal LL' factor with int indices and real double values allocated (after
  // a numeric factorisation; a symbolic one has none).
  static bool readable(const cholmod_factor& L);
  // Copies L's structure (L readable).
  void assign(const cholmod_factor& L);
  // Whether L (readable) has this structure, compared in place.
  bool matches(const cholmod_factor& L) const;

  int num_supernodes() const { return static_cast<int>(super.size()) - 1; }
  int columns(int j) const { return super[j + 1] - super[j]; }
  int rows(int j) const { return pi[j + 1] - pi[j]; }
  // Entries of supernode j's block (rows x columns).
  size_t entries(int j) const { return static_cast<size_t>(rows(j)) * columns(j); }
  const int* row_indices(int j) const { return s.data() + pi[j]; }
  // Parent of every supernode (the supernode holding its first row below the diagonal block;
  // -1 for a root). A parent always comes after its children.
  std::vector<int> parents() const;
  // The supernode of every column.
  std::vector<int> column_supernodes() const;
};

}  // namespace vs
