// A linear chain of 2-node axisymmetric elements with a constant viscosity (the elastic-shell
// analogy: velocities play displacements, mu plays G, nu = 0.5), for closed-form benchmarks.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <vector>

#include "element/axisym2.h"
#include "linalg/block_tridiag.h"

namespace vs::test {

struct Chain {
  std::vector<Eigen::Vector2d> x;  // nodes (r, z)
  double thickness = 1.0;
  double G = 1.0;
  int thickness_points = 5;
  Eigen::VectorXd load;                    // nodal loads (u, w, beta) per node, full 360 degrees
  std::vector<std::pair<int, int>> fixed;  // (node, dof)

  int nodes() const { return static_cast<int>(x.size()); }

  void init() { load = Eigen::VectorXd::Zero(3 * nodes()); }

  // Consistent nodal forces of a pressure p acting along each element's normal (-s, c) times
  // `sign`, integrated exactly over the frustum: F_a = 2 pi p l (2 r_a + r_b) / 6.
  // midpoint = true: one-point rule instead (load 2 pi r_m l p split equally between the nodes),
  // as the paper's element integrates everything at the midpoint.
  void add_pressure(double p, double sign = 1.0, bool midpoint = false) {
    for (int e = 0; e + 1 < nodes(); ++e) {
      const Eigen::Vector2d t = x[e + 1] - x[e];
      const double l = t.norm();
      const Eigen::Vector2d n = sign * Eigen::Vector2d(-t.y(), t.x()) / l;
      const double ra = x[e].x(), rb = x[e + 1].x();
      double fa = 2.0 * std::numbers::pi * p * l * (2.0 * ra + rb) / 6.0;
      double fb = 2.0 * std::numbers::pi * p * l * (ra + 2.0 * rb) / 6.0;
      if (midpoint) fa = fb = 0.5 * (fa + fb);
      load.segment<2>(3 * e) += fa * n;
      load.segment<2>(3 * (e + 1)) += fb * n;
    }
  }

  BlockTridiag stiffness() const {
    BlockTridiag K(nodes());
    const ThicknessRule rule = simpson_rule(thickness_points);
    const std::vector<double> sy(rule.zeta.size(), 0.0);
    const ViscousLaw law = ViscousLaw::Constant(G);
    Axisym2Output out;
    for (int e = 0; e + 1 < nodes(); ++e) {
      Axisym2Section sec{thickness, &sy, nullptr, G};
      Axisym2Geometry g{x[e].x(), x[e].y(), x[e + 1].x(), x[e + 1].y()};
      axisym2_evaluate(g, sec, rule, law, Vec6::Zero(), StiffnessKind::kSecant, &out);
      K.diag(e) += out.stiffness.block<3, 3>(0, 0);
      K.diag(e + 1) += out.stiffness.block<3, 3>(3, 3);
      K.lower(e) += out.stiffness.block<3, 3>(3, 0);
    }
    return K;
  }

  Eigen::VectorXd solve() const {
    BlockTridiag K = stiffness();
    Eigen::VectorXd f = load;
    for (auto [n, d] : fixed) {
      K.fix_dof(n, d);
      f(3 * n + d) = 0.0;
    }
    EXPECT_TRUE(K.factorize());
    return K.solve(f);
  }

  Eigen::MatrixXd dense() const {
    const BlockTridiag K = stiffness();
    const int n = 3 * nodes();
    Eigen::MatrixXd D(n, n);
    for (int j = 0; j < n; ++j) D.col(j) = K.multiply(Eigen::VectorXd::Unit(n, j));
    return D;
  }
};

// Flat plate meridian from r = r_in to r = a with n equal elements.
inline Chain plate(double r_in, double a, int n) {
  Chain c;
  for (int i = 0; i <= n; ++i) c.x.emplace_back(r_in + (a - r_in) * i / n, 0.0);
  c.init();
  return c;
}

}  // namespace vs::test
