// The 9-node shell element (forward/shell3d/shell9.h): zero-energy modes per rule, the
// constant-viscosity mode as the nu = 1/2 elastic shell, consistent tangent of the viscous mode.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "benchmark_setups.h"
#include "element/shell9.h"

namespace vs::shell3d {
namespace {

// Number of (relatively) zero eigenvalues of the free, unconstrained stiffness.
int zero_modes(const ShellMesh& mesh, Shell9Rule rule) {
  ShellModel model(mesh);
  LinearShellProblem p(model, Shell9Material::Elastic(1.0, 0.3), bench::options(rule));
  Eigen::VectorXd f;
  p.assembler().assemble(p.kernel(Shell9Stiffness::kSecant),
                         Eigen::VectorXd::Zero(model.num_dofs()), true, &f);
  const Eigen::MatrixXd K(p.assembler().matrix());
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
  int n = 0;
  for (Eigen::Index i = 0; i < ev.size(); ++i) n += std::abs(ev(i)) < 1e-9 * ev.maxCoeff();
  return n;
}

TEST(Shell9ZeroModes, SingleFlatElement) {
  const ShellMesh one = rectangular_plate(1.0, 1.0, 1, 1, 0.1);
  EXPECT_EQ(zero_modes(one, Shell9Rule::kSelective), 7);  // 6 rigid + 1 spurious w-mode
  EXPECT_EQ(zero_modes(one, Shell9Rule::kFull), 6);
  EXPECT_EQ(zero_modes(one, Shell9Rule::kReduced), 13);  // 7 spurious
  EXPECT_EQ(zero_modes(one, Shell9Rule::kMitc9), 6);
}

TEST(Shell9ZeroModes, SingleCurvedElement) {
  const ShellMesh one = cylinder_patch(1.0, 0.0, 1.0, 0.0, 1.0, 1, 1, 0.05);
  EXPECT_EQ(zero_modes(one, Shell9Rule::kSelective), 6);
  EXPECT_EQ(zero_modes(one, Shell9Rule::kMitc9), 6);
}

TEST(Shell9ZeroModes, AssembledFlatMeshes) {
  for (int n : {2, 4}) {
    const ShellMesh mesh = rectangular_plate(1.0, 1.0, n, n, 0.1);
    EXPECT_EQ(zero_modes(mesh, Shell9Rule::kSelective), 7) << n;  // the global checkerboard
    EXPECT_EQ(zero_modes(mesh, Shell9Rule::kMitc9), 6) << n;
  }
}

Shell9Geometry curved_geometry() {
  static const ShellMesh mesh = sphere_patch(5.0, 0.3, 0.8, 0.1, 0.7, 1, 1, 0.2);
  static const ShellModel model(mesh);
  return model.element_geometry(0);
}

Eigen::VectorXd test_velocity(int n) {
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = std::sin(1.3 * i + 0.2) + 0.1 * std::cos(0.7 * i * i);
  return q;
}

TEST(Shell9Element, ConstantViscosityIsTheIncompressibleElasticShell) {
  const Shell9Geometry g = curved_geometry();
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 5);
  const double mu = 7.0;
  const ViscousLaw constant = ViscousLaw::Constant(mu);
  const HillPlaneStressLaw hill(constant);
  for (auto rule : {Shell9Rule::kSelective, Shell9Rule::kMitc9}) {
    Shell9Output a, b;
    const Eigen::VectorXd q = test_velocity(g.ndof());
    shell9_evaluate(g, rule, thick, Shell9Material::Elastic(3.0 * mu, 0.5), {}, q,
                    Shell9Stiffness::kSecant, &a);
    shell9_evaluate(g, rule, thick, Shell9Material::Viscous(hill, mu), {}, q,
                    Shell9Stiffness::kSecant, &b);
    EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-12 * a.stiffness.norm());
    EXPECT_LT((a.force - a.stiffness * q).norm(), 1e-12 * a.force.norm());
    // Linear: the potential is half the power.
    EXPECT_NEAR(a.potential, 0.5 * q.dot(a.force), 1e-12 * std::abs(a.potential));
  }
}

TEST(Shell9Element, ViscousTangentAndForceAreDerivatives) {
  const Shell9Geometry g = curved_geometry();
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.1;
  const ViscousLaw law(rate, 1e-3, 1.6);
  const HillPlaneStressLaw hill(law);
  const Shell9Material mat = Shell9Material::Viscous(hill, 50.0);
  for (auto rule : {Shell9Rule::kSelective, Shell9Rule::kMitc9}) {
    const int np = shell9_inplane_points(rule) * 3;
    std::vector<double> sy(static_cast<std::size_t>(np), 200.0), hv(sy.size(), 3.0);
    const Shell9State st{sy.data(), hv.data()};
    const Eigen::VectorXd q = 1e-2 * test_velocity(g.ndof());
    Shell9Output out;
    shell9_evaluate(g, rule, thick, mat, st, q, Shell9Stiffness::kTangent, &out);
    const double h = 1e-7;
    for (int j = 0; j < g.ndof(); j += 7) {
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      Shell9Output op, om;
      shell9_evaluate(g, rule, thick, mat, st, qp, Shell9Stiffness::kNone, &op);
      shell9_evaluate(g, rule, thick, mat, st, qm, Shell9Stiffness::kNone, &om);
      const Eigen::VectorXd fd = (op.force - om.force) / (2.0 * h);
      EXPECT_LT((fd - out.stiffness.col(j)).norm(), 1e-5 * out.stiffness.norm()) << j;
      EXPECT_NEAR((op.potential - om.potential) / (2.0 * h), out.force(j), 1e-6 * out.force.norm());
    }
    EXPECT_LT((out.stiffness - out.stiffness.transpose()).norm(), 1e-12 * out.stiffness.norm());
  }
}

// A viscous MITC9 element (3 Simpson points) with its operators and point state, for the
// operator tests (the laws point to each other: not copied).
struct ViscousElement {
  Shell9Geometry g = curved_geometry();
  ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  ViscousLaw law{RateSpec{}, 1e-3, 1.6};
  HillPlaneStressLaw hill{law};
  Shell9Material mat = Shell9Material::Viscous(hill, 50.0);
  Shell9Operators ops;
  std::vector<double> sy, hv;
  ViscousElement() {
    shell9_operators(g, Shell9Rule::kMitc9, thick, &ops);
    sy.assign(ops.flow.size(), 200.0);
    hv.assign(ops.flow.size(), 3.0);
  }
  ViscousElement(const ViscousElement&) = delete;
  ViscousElement& operator=(const ViscousElement&) = delete;
  Shell9State state() const { return Shell9State{sy.data(), hv.data()}; }
};

TEST(Shell9Element, SubstitutedVelocityIsTheTransformedElement) {
  // shell9_substitute_velocity: with u = u' - C r at two nodes (q = T q'), the element in the
  // unknowns (u', r) has force T^T f(T q'), matrix T^T K T and the same power potential. Checks
  // the in-plane operators and the shear Gram matrix (its rows and columns) together.
  const ViscousElement el;
  const Shell9Geometry& g = el.g;
  const Shell9Operators& ops = el.ops;
  Shell9Operators sub = ops;
  const int n = g.ndof();
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(n, n);
  int substituted = 0;
  for (int a : {1, 4, 6}) {
    if (g.n_rot[static_cast<std::size_t>(a)] != 2) continue;
    Eigen::Matrix<double, 3, 2> C;
    C << 0.3, -0.1, 0.05 * a, 0.2, -0.4, 0.1 * a;
    shell9_substitute_velocity(g.offset(a), g.offset(a) + 3, C, &sub);
    T.block<3, 2>(g.offset(a), g.offset(a) + 3) = -C;
    ++substituted;
  }
  ASSERT_GE(substituted, 2);
  const Shell9State st = el.state();
  const Eigen::VectorXd qs = 1e-2 * test_velocity(n), q = T * qs;
  Shell9Output a, b;
  shell9_evaluate(ops, el.mat, st, q, Shell9Stiffness::kTangent, &a);
  shell9_evaluate(sub, el.mat, st, qs, Shell9Stiffness::kTangent, &b);
  const Eigen::VectorXd f = T.transpose() * a.force;
  const Eigen::MatrixXd K = T.transpose() * a.stiffness * T;
  EXPECT_LT((b.force - f).norm(), 1e-12 * f.norm());
  EXPECT_LT((b.stiffness - K).norm(), 1e-12 * K.norm());
  EXPECT_NEAR(b.potential, a.potential, 1e-12 * std::abs(a.potential));
  // The shear Gram matrix alone.
  EXPECT_LT((sub.shear_gram - T.transpose() * ops.shear_gram * T).norm(),
            1e-12 * ops.shear_gram.norm());
}

TEST(Shell9Element, PrefetchingTheNextOperatorsChangesNothing) {
  // shell9_evaluate's `next` only asks the memory system for the next element's L and S: forces,
  // matrix, potential and point rates are the same bits with and without it, for either kind.
  const ViscousElement el;
  const Shell9Operators& ops = el.ops;
  const Shell9Material& mat = el.mat;
  Shell9Operators next;
  shell9_operators(el.g, Shell9Rule::kMitc9, el.thick, &next);
  const Shell9State st = el.state();
  const Eigen::VectorXd q = 1e-2 * test_velocity(el.g.ndof());
  for (auto kind : {Shell9Stiffness::kNone, Shell9Stiffness::kTangent}) {
    Shell9Output plain, ahead;
    shell9_evaluate(ops, mat, st, q, kind, &plain);
    shell9_evaluate(ops, mat, st, q, kind, &ahead, 1.0, &next);
    EXPECT_TRUE(plain.force == ahead.force);
    EXPECT_TRUE(plain.stiffness == ahead.stiffness);
    EXPECT_EQ(plain.potential, ahead.potential);
    EXPECT_EQ(plain.point_rate, ahead.point_rate);
  }
}

}  // namespace
}  // namespace vs::shell3d
