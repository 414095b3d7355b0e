#include "element/quadrature.h"

#include <cmath>
#include <stdexcept>

namespace vs::shell3d {

Rule1D gauss_legendre(int n) {
  Rule1D r;
  switch (n) {
    case 1:
      r.x = {0.0};
      r.w = {2.0};
      break;
    case 2: {
      const double a = 1.0 / std::sqrt(3.0);
      r.x = {-a, a};
      r.w = {1.0, 1.0};
      break;
    }
    case 3: {
      const double a = std::sqrt(0.6);
      r.x = {-a, 0.0, a};
      r.w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
      break;
    }
    case 4: {
      const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
      const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
      const double wa = (18.0 + std::sqrt(30.0)) / 36.0;
      const double wb = (18.0 - std::sqrt(30.0)) / 36.0;
      r.x = {-b, -a, a, b};
      r.w = {wb, wa, wa, wb};
      break;
    }
    case 5: {
      const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
      const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
      const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
      const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
      r.x = {-b, -a, 0.0, a, b};
      r.w = {wb, wa, 128.0 / 225.0, wa, wb};
      break;
    }
    default:
      throw std::invalid_argument("gauss_legendre: n must be 1..5");
  }
  return r;
}

ThicknessRule thickness_rule(ThicknessKind kind, int n) {
  if (kind == ThicknessKind::kSimpson) {
    if (n < 3 || n % 2 == 0) throw std::invalid_argument("Simpson thickness rule: n odd >= 3");
    return simpson_rule(n);
  }
  const Rule1D g = gauss_legendre(n);
  ThicknessRule t;
  for (std::size_t k = 0; k < g.x.size(); ++k) {
    t.zeta.push_back(0.5 * g.x[k]);
    t.weight.push_back(0.5 * g.w[k]);
  }
  return t;
}

}  // namespace vs::shell3d
