#include "element/lagrange9.h"

namespace vs::shell3d {

namespace {
// 1D index (0: -1, 1: 0, 2: +1) of each node in r and s.
constexpr std::array<int, 9> kIr = {0, 2, 2, 0, 1, 2, 1, 0, 1};
constexpr std::array<int, 9> kIs = {0, 0, 2, 2, 0, 1, 2, 1, 1};
}  // namespace

std::array<double, 2> lagrange9_node(int a) {
  return {static_cast<double>(kIr[a] - 1), static_cast<double>(kIs[a] - 1)};
}

std::array<double, 3> quad1d(double x) {
  return {0.5 * x * (x - 1.0), 1.0 - x * x, 0.5 * x * (x + 1.0)};
}

std::array<double, 3> quad1d_deriv(double x) { return {x - 0.5, -2.0 * x, x + 0.5}; }

Shape9 lagrange9(double r, double s) {
  const auto lr = quad1d(r), ls = quad1d(s);
  const auto dr = quad1d_deriv(r), ds = quad1d_deriv(s);
  Shape9 sh;
  for (int a = 0; a < 9; ++a) {
    sh.N(a) = lr[kIr[a]] * ls[kIs[a]];
    sh.dr(a) = dr[kIr[a]] * ls[kIs[a]];
    sh.ds(a) = lr[kIr[a]] * ds[kIs[a]];
  }
  return sh;
}

}  // namespace vs::shell3d
