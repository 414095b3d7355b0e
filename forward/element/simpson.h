// Composite Simpson rule through the thickness (paper section 4.3: 3 points where membrane
// action dominates, 5 or more where plastic bending matters; numerics.md section 3.4).
#pragma once

#include <vector>

namespace vs {

struct ThicknessRule {
  std::vector<double> zeta;    // positions as fractions of the thickness, in [-1/2, 1/2]
  std::vector<double> weight;  // weights, summing to 1
};

// n odd, >= 3.
ThicknessRule simpson_rule(int n);

}  // namespace vs
