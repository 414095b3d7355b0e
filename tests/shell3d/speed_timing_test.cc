// Timings of the 3D forming solver's building blocks on example 4a (quarter disc): element
// assembly passes per kind and the sparse factorisations. Disabled by default (timings are no
// tests); run with
//   build/tests/vs_shell3d_tests --gtest_also_run_disabled_tests --gtest_filter='*SpeedTiming*'
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <cstdio>
#include <ctime>
#include <string>

#include "linalg/sparse_spd_solver.h"
#include "model/forming_model.h"
#include "scene/load_scene.h"

namespace vs::shell3d {
namespace {

// Process CPU time per call (the machine is shared: wall time measures the load). With
// OMP_NUM_THREADS=1 it is the single-threaded cost.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class F>
double seconds_per_call(F&& f, int calls) {
  f();  // warm-up (workspaces, analysis)
  const double t0 = cpu_seconds();
  for (int i = 0; i < calls; ++i) f();
  return (cpu_seconds() - t0) / calls;
}

TEST(SpeedTiming, DISABLED_AssemblyAndFactorisation) {
  for (int n : {4, 8, 16}) {
    Scene s =
        load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
    s.blank.divisions = n;
    FormingModel model(s);
    FormingState st = model.initial_state();
    // A bent, stretched configuration with a stuck cap, so that the points are plastic.
    for (int i = 0; i < model.num_nodes(); ++i) {
      const Vec3& p = st.x[i];
      st.x[i].z() = 5.0 * std::exp(-(p.x() * p.x() + p.y() * p.y()) / 800.0);
      st.velocity[i] = Vec3(0.01 * p.x(), 0.012 * p.y(), st.x[i].z() / 5.0);
    }
    model.freeze_material(st, 0.5);
    model.prepare(st);
    const Eigen::VectorXd x = model.to_local(st.velocity, st.omega);
    FormingSystem sys;
    const int ne = model.num_elements();
    const int calls = n == 4 ? 40 : n == 8 ? 10 : 3;
    const double tk = seconds_per_call(
        [&] { model.evaluate(st, x, Shell9Stiffness::kTangent, 1.0, &sys); }, calls);
    const double tp = seconds_per_call([&] { model.potential(st, x); }, calls);
    SparseSpdSolver cholmod;
    cholmod.analyze(model.matrix());
    const double tc = seconds_per_call([&] { cholmod.factorize(model.matrix()); }, calls);
    Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> llt;
    llt.analyzePattern(model.matrix());
    const double tl = seconds_per_call([&] { llt.factorize(model.matrix()); }, calls);
    Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> csl;
    csl.analyzePattern(model.matrix());
    const double tcs = seconds_per_call([&] { csl.factorize(model.matrix()); }, calls);
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> csu;
    csu.analyzePattern(model.matrix());
    const double tcu = seconds_per_call([&] { csu.factorize(model.matrix()); }, calls);
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
    ldlt.analyzePattern(model.matrix());
    const double tld = seconds_per_call([&] { ldlt.factorize(model.matrix()); }, calls);
    std::printf("  CHOLMOD supernodal (upper) %.2f ms, Eigen SimplicialLDLT %.2f ms, nnz(K) %ld\n",
                1e3 * tcu, 1e3 * tld, static_cast<long>(model.matrix().nonZeros()));
    std::printf(
        "n = %d (%d elements, %d dofs), CPU time: tangent pass %.2f ms (%.1f us/element), "
        "potential pass "
        "%.2f ms (%.1f us/element); factorisation: CHOLMOD supernodal %.2f ms, CHOLMOD "
        "simplicial %.2f ms, Eigen SimplicialLLT %.2f ms\n",
        n, ne, model.num_dofs(), 1e3 * tk, 1e6 * tk / ne, 1e3 * tp, 1e6 * tp / ne, 1e3 * tc,
        1e3 * tcs, 1e3 * tl);
  }
}

}  // namespace
}  // namespace vs::shell3d
