// Regularised Coulomb friction, the one law of both geometries (numerics.md 3.5).
//
// The friction force on a slip velocity v (signed in the axisymmetric meridian, the magnitude
// |s| of the slip vector in 3D) is
//     f(v) = L 2/pi atan(v / v0),        L = the Coulomb limit (mu N, plus holder shares),
// a smooth, monotone stand-in for L sign(v) whose transition width v0 is
// numerics.friction_regularisation times the punch speed. It derives from the convex potential
//     P(v) = L 2/pi (v atan(v/v0) - v0/2 ln(1 + (v/v0)^2)),      P' = f,
// so friction joins the flow potential that the Newton line search minimises. Its secant
// stiffness f/v (the direct iteration's; L 2/(pi v0) at v -> 0) and tangent stiffness
// f' = L 2/(pi v0 (1 + (v/v0)^2)) are returned with it. In 3D the force acts along the slip,
// f(|s|) s/|s|, with the matrix ks I + theta (kt - ks) e e^T (e = s/|s|).
#pragma once

#include <cmath>
#include <numbers>

namespace vs {

struct CoulombTerms {
  double force = 0.0;      // f(v)
  double secant = 0.0;     // f(v) / v
  double tangent = 0.0;    // df/dv
  double potential = 0.0;  // P(v)
};

inline CoulombTerms regularised_coulomb(double limit, double v, double v0) {
  constexpr double kTwoOverPi = 2.0 / std::numbers::pi;
  CoulombTerms t;
  const double a = v / v0;
  const double at = std::atan(a);
  t.force = limit * kTwoOverPi * at;
  t.secant = std::abs(a) < 1e-8 ? limit * kTwoOverPi / v0 : t.force / v;
  t.tangent = limit * kTwoOverPi / (v0 * (1.0 + a * a));
  t.potential = limit * kTwoOverPi * (v * at - 0.5 * v0 * std::log1p(a * a));
  return t;
}

}  // namespace vs
