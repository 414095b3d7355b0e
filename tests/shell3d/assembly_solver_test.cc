// Fixed-pattern assembly (deterministic across thread counts), CHOLMOD vs SimplicialLDLT,
// fallback on an indefinite matrix, symbolic analysis reuse, kinked (6-dof) nodes.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <string>

#include "benchmark_setups.h"

namespace vs::shell3d {
namespace {

TEST(ShellAssembler, BitwiseIdenticalForAnyThreadCount) {
  const ShellMesh mesh = sphere_patch(10.0, 0.3, 1.5, 0.0, 1.5, 6, 6, 0.1);
  ShellModel model(mesh);
  LinearShellProblem p(model, Shell9Material::Elastic(1e5, 0.3),
                       bench::options(Shell9Rule::kMitc9));
  Eigen::VectorXd q(model.num_dofs());
  for (Eigen::Index i = 0; i < q.size(); ++i) q(i) = std::sin(0.37 * static_cast<double>(i));
  const int saved = omp_get_max_threads();
  std::vector<std::vector<double>> values;
  std::vector<Eigen::VectorXd> forces;
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    Eigen::VectorXd f;
    p.assembler().assemble(p.kernel(Shell9Stiffness::kSecant), q, true, &f);
    const SparseMatrix& K = p.assembler().matrix();
    values.emplace_back(K.valuePtr(), K.valuePtr() + K.nonZeros());
    forces.push_back(f);
  }
  omp_set_num_threads(saved);
  for (std::size_t k = 1; k < values.size(); ++k) {
    EXPECT_EQ(0,
              std::memcmp(values[0].data(), values[k].data(), values[0].size() * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(forces[0].data(), forces[k].data(),
                             static_cast<std::size_t>(forces[0].size()) * sizeof(double)));
  }
  // Linear element: f = K q.
  EXPECT_LT((p.assembler().matrix() * q - forces[0]).norm(), 1e-10 * forces[0].norm());
  // The parallel summation by column blocks gives each value its element terms in element order:
  // the same bits as adding the element matrices one after the other.
  SparseMatrix reference = p.assembler().matrix();
  reference.coeffs().setZero();
  const ElementKernel kernel = p.kernel(Shell9Stiffness::kSecant);
  for (int e = 0; e < model.num_elements(); ++e) {
    ElementContribution c;
    kernel(e, p.assembler().gather(e, q), &c);
    const std::vector<int> d = model.element_dofs(e);
    for (std::size_t b = 0; b < d.size(); ++b)
      for (std::size_t a = 0; a < d.size(); ++a)
        reference.coeffRef(d[a], d[b]) +=
            c.stiffness(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
  }
  ASSERT_EQ(reference.nonZeros(), static_cast<Eigen::Index>(values[0].size()));
  EXPECT_EQ(0,
            std::memcmp(values[0].data(), reference.valuePtr(), values[0].size() * sizeof(double)));
}

TEST(ShellAssembler, ConstraintsDecoupleTheFixedUnknowns) {
  // apply_constraints against the dense definition: a known column times its value moves to the
  // right-hand side of the free rows; the fixed rows and columns are zero but for the diagonal,
  // with rhs_j = K_jj g_j; every free-free value is untouched. Also on 2 threads: the same bits.
  const ShellMesh mesh = sphere_patch(10.0, 0.3, 1.5, 0.0, 1.5, 4, 4, 0.1);
  ShellModel model(mesh);
  LinearShellProblem p(model, Shell9Material::Elastic(1e5, 0.3),
                       bench::options(Shell9Rule::kMitc9));
  const int n = model.num_dofs();
  Eigen::VectorXd f;
  p.assembler().assemble(p.kernel(Shell9Stiffness::kSecant), Eigen::VectorXd::Zero(n), true, &f);
  const Eigen::MatrixXd K(p.assembler().matrix());
  std::vector<char> fixed(static_cast<std::size_t>(n), 0);
  std::vector<double> value(static_cast<std::size_t>(n), 0.0);
  for (int j = 0; j < n; j += 7) {
    fixed[static_cast<std::size_t>(j)] = 1;
    value[static_cast<std::size_t>(j)] = (j % 3 == 0) ? 0.0 : std::cos(0.3 * j);
  }
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::sin(0.11 * i + 0.5);
  Eigen::MatrixXd K_ref = K;
  Eigen::VectorXd b_ref = b;
  for (int j = 0; j < n; ++j) {
    if (!fixed[static_cast<std::size_t>(j)]) continue;
    for (int i = 0; i < n; ++i)
      if (!fixed[static_cast<std::size_t>(i)])
        b_ref(i) -= K(i, j) * value[static_cast<std::size_t>(j)];
  }
  for (int j = 0; j < n; ++j) {
    if (!fixed[static_cast<std::size_t>(j)]) continue;
    const double d = K(j, j) == 0.0 ? 1.0 : K(j, j);
    K_ref.row(j).setZero();
    K_ref.col(j).setZero();
    K_ref(j, j) = d;
    b_ref(j) = d * value[static_cast<std::size_t>(j)];
  }
  const int saved = omp_get_max_threads();
  std::vector<double> first;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    p.assembler().assemble(p.kernel(Shell9Stiffness::kSecant), Eigen::VectorXd::Zero(n), true, &f);
    Eigen::VectorXd rhs = b;
    p.assembler().apply_constraints(fixed, value, &rhs);
    const SparseMatrix& A = p.assembler().matrix();
    EXPECT_EQ((Eigen::MatrixXd(A) - K_ref).cwiseAbs().maxCoeff(), 0.0) << threads;
    EXPECT_LT((rhs - b_ref).norm(), 1e-14 * b_ref.norm()) << threads;
    std::vector<double> v(A.valuePtr(), A.valuePtr() + A.nonZeros());
    if (first.empty()) first = v;
    EXPECT_TRUE(v == first) << threads;
  }
  omp_set_num_threads(saved);
}

TEST(SparseSpdSolver, CholmodAndLdltAgreeAndReuseTheAnalysis) {
  const ShellMesh mesh = cylinder_patch(300.0, 0.0, 300.0, 0.0, 1.5707963267948966, 6, 6, 3.0);
  Eigen::VectorXd solutions[2];
  for (int s = 0; s < 2; ++s) {
    ShellModel model(mesh);
    for (int i : mesh.set("y1")) model.clamp(i);
    auto o = bench::options(Shell9Rule::kMitc9);
    o.solver = s == 0 ? SparseSolverKind::kCholmodSupernodal : SparseSolverKind::kSimplicialLDLT;
    LinearShellProblem p(model, Shell9Material::Elastic(3e6, 0.3), o);
    p.add_point_load(mesh.nearest_node(Vec3(0, 0, 300)), Vec3(0, 0, -1));
    solutions[s] = p.solve();
    const Eigen::VectorXd again = p.solve();  // numeric refactorisation only
    EXPECT_EQ(p.solver().analyses(), 1);
    EXPECT_EQ(p.solver().active(), o.solver);
    // CHOLMOD's refactorisation is the two-thread one of linalg/supernodal_cholesky.h (sums in
    // another order than CHOLMOD's first): round-off times the condition number, measured 1.3e-12
    // (CHOLMOD twice: 0).
    EXPECT_LT((again - solutions[s]).norm(), 1e-10 * solutions[s].norm());
  }
  EXPECT_LT((solutions[0] - solutions[1]).norm(), 1e-8 * solutions[0].norm());
}

TEST(SparseSpdSolver, FallsBackToLdltWhenCholmodFails) {
  SparseMatrix A(3, 3);
  std::vector<Eigen::Triplet<double>> t = {
      {0, 0, 2.0}, {1, 1, -1.0}, {2, 2, 3.0}, {0, 2, 0.5}, {2, 0, 0.5}};
  A.setFromTriplets(t.begin(), t.end());
  SparseSpdSolver s(SparseSolverKind::kCholmodSupernodal);
  s.analyze(A);
  EXPECT_EQ(s.fallbacks(), 0);
  // The refusal is counted, not printed (CHOLMOD's warning once filled a run's log).
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  const bool factorised = s.factorize(A);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  ASSERT_TRUE(factorised);
  EXPECT_EQ(out + err, "");
  EXPECT_EQ(s.fallbacks(), 1);
  EXPECT_EQ(s.active(), SparseSolverKind::kSimplicialLDLT);
  const Eigen::VectorXd b = Eigen::Vector3d(1.0, 2.0, 3.0);
  EXPECT_LT((A * s.solve(b) - b).norm(), 1e-12);
  // A positive definite matrix afterwards: CHOLMOD again, the count unchanged.
  A.coeffRef(1, 1) = 1.0;
  ASSERT_TRUE(s.factorize(A));
  EXPECT_EQ(s.active(), SparseSolverKind::kCholmodSupernodal);
  EXPECT_EQ(s.fallbacks(), 1);
}

// Folded plate: two unit squares meeting at 90 degrees along x = 1 (a kink line), clamped at
// x = 0, loaded at the free corner. The fold nodes carry 6 dofs. Known limitation (README): the
// paper's drilling treatment penalises the absolute rate about each element's normal, and at a
// fold that rate is the neighbour's bending rotation, so the answer moves between a hinge
// (k_drill -> 0: -6.2628) and a clamped fold rotation (k_drill -> large: -4.70) instead of
// being tied to the membrane rotation.
double folded_plate_tip(double drill_scale, int* kinked) {
  static const ShellMesh mesh = [] {
    ShellMesh a = rectangular_plate(1.0, 1.0, 4, 4, 0.02);
    ShellMesh b = structured_block(
        4, 4, [](double u, double v) { return Eigen::Vector3d(1.0, v, u); }, {}, 0.02);
    a.exact_normal.clear();
    ShellMesh m = merge_meshes({a, b}, 1e-9);
    add_node_set(&m, "clamped", [](const Eigen::Vector3d& x) { return x.x() < 1e-12; });
    return m;
  }();
  ShellModel model(mesh);
  *kinked = model.num_kinked();
  for (int i : mesh.set("clamped")) model.clamp(i);
  Shell9Material mat = Shell9Material::Elastic(1e5, 0.3);
  mat.drill_scale = drill_scale;
  LinearShellProblem p(model, mat, bench::options(Shell9Rule::kMitc9));
  const int tip = mesh.nearest_node(Vec3(1.0, 1.0, 1.0));
  p.add_point_load(tip, Vec3(0.0, 0.0, -1.0));
  return p.translation(p.solve(), tip).z();
}

TEST(KinkedNodes, FoldLineHasSixDofs) {
  int kinked = 0;
  const double w_hinge = folded_plate_tip(1e-8, &kinked);
  EXPECT_EQ(kinked, 9);  // the 9 nodes on the fold line
  EXPECT_NEAR(w_hinge, -6.2628, 1e-3);
  EXPECT_NEAR(folded_plate_tip(1e-3, &kinked), -5.8209, 1e-3);  // regression (default scale)
  EXPECT_NEAR(folded_plate_tip(1.0, &kinked), -4.7039, 1e-3);
}

// On a smooth surface 6 dofs everywhere (each element with its own normal) reproduce the 5-dof
// answer, independently of the drilling stiffness (numerics.md 4.2: vary it by 10x).
double scordelis_lo_dofs(double drill_scale, bool six) {
  const double R = 25.0;
  const ShellMesh mesh = cylinder_patch(R, 0.0, 25.0, 0.0, 40.0 * bench::kDeg, 4, 4, 0.25);
  ShellModelOptions mo;
  mo.all_six_dof = six;
  ShellModel model(mesh, mo);
  for (int i : mesh.set("y1")) {
    model.fix_translation(i, 0);
    model.fix_translation(i, 2);
  }
  for (int i : mesh.set("y0")) model.symmetry(i, Vec3::UnitY());
  for (int i : mesh.set("theta0")) model.symmetry(i, Vec3::UnitX());
  Shell9Material mat = Shell9Material::Elastic(4.32e8, 0.0);
  mat.drill_scale = drill_scale;
  LinearShellProblem p(model, mat, bench::options(Shell9Rule::kMitc9));
  p.add_surface_load(Vec3(0.0, 0.0, -90.0));
  const Eigen::VectorXd q = p.solve();
  const Vec3 x(R * std::sin(40.0 * bench::kDeg), 0.0, R * std::cos(40.0 * bench::kDeg));
  return -p.translation(q, mesh.nearest_node(x)).z();
}

TEST(KinkedNodes, SixDofsOnSmoothSurfaceMatchFiveDofs) {
  const double w5 = scordelis_lo_dofs(1e-3, false);
  for (double scale : {1e-4, 1e-3, 1e-2})
    EXPECT_NEAR(scordelis_lo_dofs(scale, true) / w5, 1.0, 1e-5);
}

}  // namespace
}  // namespace vs::shell3d
