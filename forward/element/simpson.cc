#include "element/simpson.h"

#include <cassert>

namespace vs {

ThicknessRule simpson_rule(int n) {
  assert(n >= 3 && n % 2 == 1);
  ThicknessRule rule;
  const double intervals = n - 1;
  for (int k = 0; k < n; ++k) {
    rule.zeta.push_back(k / intervals - 0.5);
    const double c = (k == 0 || k == n - 1) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    rule.weight.push_back(c / (3.0 * intervals));
  }
  return rule;
}

}  // namespace vs
