#include "linalg/supernodal_structure.h"

#include <algorithm>

namespace vs {

namespace {

void copy_ints(const void* p, size_t n, std::vector<int>* to) {
  const int* a = static_cast<const int*>(p);
  to->assign(a, a + n);
}

bool equal_ints(const std::vector<int>& v, const void* p, size_t n) {
  return v.size() == n && std::equal(v.begin(), v.end(), static_cast<const int*>(p));
}

}  // namespace

bool SupernodalStructure::readable(const cholmod_factor& L) {
  return L.is_super && L.is_ll && L.itype == CHOLMOD_INT && L.xtype == CHOLMOD_REAL &&
         L.dtype == CHOLMOD_DOUBLE && L.x != nullptr;
}

void SupernodalStructure::assign(const cholmod_factor& L) {
  n = static_cast<int>(L.n);
  copy_ints(L.Perm, L.n, &perm);
  copy_ints(L.super, L.nsuper + 1, &super);
  copy_ints(L.pi, L.nsuper + 1, &pi);
  copy_ints(L.px, L.nsuper + 1, &px);
  copy_ints(L.s, L.ssize, &s);
}

bool SupernodalStructure::matches(const cholmod_factor& L) const {
  return n == static_cast<int>(L.n) && equal_ints(super, L.super, L.nsuper + 1) &&
         equal_ints(pi, L.pi, L.nsuper + 1) && equal_ints(px, L.px, L.nsuper + 1) &&
         equal_ints(s, L.s, L.ssize) && equal_ints(perm, L.Perm, L.n);
}

std::vector<int> SupernodalStructure::column_supernodes() const {
  std::vector<int> of(static_cast<size_t>(n));
  for (int j = 0; j < num_supernodes(); ++j)
    for (int k = super[j]; k < super[j + 1]; ++k) of[k] = j;
  return of;
}

std::vector<int> SupernodalStructure::parents() const {
  const std::vector<int> of = column_supernodes();
  std::vector<int> parent(static_cast<size_t>(num_supernodes()));
  for (int j = 0; j < num_supernodes(); ++j)
    parent[j] = rows(j) > columns(j) ? of[s[pi[j] + columns(j)]] : -1;
  return parent;
}

}  // namespace vs
