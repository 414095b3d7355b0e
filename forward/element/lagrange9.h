// Biquadratic Lagrange shape functions of the 9-node element on [-1, 1]^2.
// Node order: corners counter-clockwise (0: (-1,-1), 1: (1,-1), 2: (1,1), 3: (-1,1)), then
// midsides (4: (0,-1), 5: (1,0), 6: (0,1), 7: (-1,0)), then the centre (8: (0,0)).
#pragma once

#include <Eigen/Core>
#include <array>

namespace vs::shell3d {

using Vec9 = Eigen::Matrix<double, 9, 1>;

// Natural coordinates of node a.
std::array<double, 2> lagrange9_node(int a);

struct Shape9 {
  Vec9 N, dr, ds;  // N_a(r, s) and its derivatives
};

Shape9 lagrange9(double r, double s);

// 1D quadratic Lagrange basis on nodes -1, 0, 1 and its derivative.
std::array<double, 3> quad1d(double x);
std::array<double, 3> quad1d_deriv(double x);

}  // namespace vs::shell3d
