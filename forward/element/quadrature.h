// Quadrature rules of the 9-node shell: Gauss-Legendre on [-1, 1] for the element surface, and
// through-thickness rules (Gauss or composite Simpson) as fractions of the thickness.
#pragma once

#include <vector>

#include "element/simpson.h"

namespace vs::shell3d {

struct Rule1D {
  std::vector<double> x;  // abscissae in [-1, 1]
  std::vector<double> w;  // weights, summing to 2
};

// n = 1..5 points.
Rule1D gauss_legendre(int n);

enum class ThicknessKind { kGauss, kSimpson };

// zeta in [-1/2, 1/2], weights summing to 1 (the convention of vs::ThicknessRule).
// kGauss: n >= 1; kSimpson: n odd >= 3.
ThicknessRule thickness_rule(ThicknessKind kind, int n);

}  // namespace vs::shell3d
