#include "element/mitc9.h"

#include <cmath>

namespace vs::shell3d {

namespace {

const double kA = 1.0 / std::sqrt(3.0);
const double kB = std::sqrt(0.6);

// Linear Lagrange basis through -a, a; quadratic through -b, 0, b.
std::array<double, 2> lin(double x) { return {0.5 * (1.0 - x / kA), 0.5 * (1.0 + x / kA)}; }
std::array<double, 3> quad(double x) {
  const double b2 = kB * kB;
  return {0.5 * x * (x - kB) / b2, 1.0 - x * x / b2, 0.5 * x * (x + kB) / b2};
}

// Tying point k of the "r" family: r index k / 3 (0: -a, 1: +a), s index k % 3 (-b, 0, b).
double r_coord(int k) { return (k / 3 == 0) ? -kA : kA; }
double s_coord(int k) { return (k % 3 - 1) * kB; }

Mat5X B_at(const Shell9Geometry& g, double r, double s, double t) {
  const Shape9 sh = lagrange9(r, s);
  const PointBasis pb = point_basis(g, sh, t);
  return covariant_B(g, sh, pb, t);
}

}  // namespace

Mitc9TyingB mitc9_tying(const Shell9Geometry& g, double t) {
  Mitc9TyingB ty;
  for (int k = 0; k < 6; ++k) {
    ty.r_points[k] = B_at(g, r_coord(k), s_coord(k), t);
    ty.s_points[k] = B_at(g, s_coord(k), r_coord(k), t);  // r and s exchanged
  }
  for (int k = 0; k < 4; ++k) {
    const double r = (k % 2 == 0) ? -kA : kA, s = (k / 2 == 0) ? -kA : kA;
    ty.rs_points[k] = B_at(g, r, s, t);
  }
  return ty;
}

Mat5X mitc9_assumed_B(const Mitc9TyingB& ty, double r, double s) {
  const int n = static_cast<int>(ty.r_points[0].cols());
  Mat5X B = Mat5X::Zero(5, n);
  const auto lr = lin(r), ls = lin(s);
  const auto qr = quad(r), qs = quad(s);
  for (int k = 0; k < 6; ++k) {
    const double wr = lr[k / 3] * qs[k % 3];  // e_rr, 2e_rt family
    const double ws = ls[k / 3] * qr[k % 3];  // e_ss, 2e_st family
    B.row(0) += wr * ty.r_points[k].row(0);
    B.row(3) += wr * ty.r_points[k].row(3);
    B.row(1) += ws * ty.s_points[k].row(1);
    B.row(4) += ws * ty.s_points[k].row(4);
  }
  for (int k = 0; k < 4; ++k) {
    B.row(2) += (lr[k % 2] * ls[k / 2]) * ty.rs_points[k].row(2);
  }
  return B;
}

}  // namespace vs::shell3d
