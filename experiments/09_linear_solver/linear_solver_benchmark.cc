// The sparse linear solver of the 3D model, per mesh size: symbolic analysis and numeric
// factorisation times, factor size and flops for CHOLMOD supernodal with its default ordering
// choice, with METIS and with AMD forced, CHOLMOD simplicial, and Eigen's SimplicialLDLT (AMD).
// The matrix is the 3D forming model's own (ex4a quarter disc, friction 0.2), assembled in the
// first configuration with the punch in contact at the pole, secant flow stiffness at a
// velocity field that moves the sheet with the punch (every entry of the final pattern present).
//
//   build/experiments/linear_solver_benchmark [--quick] [--out DIR]
// Writes results/linear_solver.csv and results/summary.md.
#include <omp.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "common/harness.h"
#include "common/table.h"
#include "linalg/dynamic_teams.h"
#include "linalg/sparse_spd_solver.h"
#include "linalg/supernodal_factor.h"
#include "model/forming_model.h"

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Row {
  std::string name;
  double analyse_s = 0.0, factor_s = 0.0, solve_s = 0.0;
  double factor_nnz = 0.0, flops = 0.0, residual = 0.0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class Solver>
Row time_solver(const std::string& name, Solver& solver, const vs::SparseMatrix& A,
                const Eigen::VectorXd& b, int repeats) {
  Row r;
  r.name = name;
  auto t0 = Clock::now();
  solver.analyzePattern(A);
  r.analyse_s = since(t0);
  std::vector<double> f, s;
  Eigen::VectorXd x;
  for (int k = 0; k < repeats; ++k) {
    t0 = Clock::now();
    solver.factorize(A);
    f.push_back(since(t0));
    t0 = Clock::now();
    x = solver.solve(b);
    s.push_back(since(t0));
  }
  r.factor_s = median(f);
  r.solve_s = median(s);
  r.residual = (A.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
  return r;
}

// CHOLMOD's calls run inside vs::DynamicTeams, as in the product (linalg/dynamic_teams.h), unless
// uncapped (CHOLMOD's own fixed 4-thread regions).
template <class Cholmod>
Row time_cholmod(const std::string& name, int ordering, bool supernodal, const vs::SparseMatrix& A,
                 const Eigen::VectorXd& b, int repeats, bool uncapped = false) {
  std::optional<vs::DynamicTeams> teams;
  if (!uncapped) teams.emplace();
  Cholmod solver;
  cholmod_common& c = solver.cholmod();
  c.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  if (ordering >= 0) {
    c.nmethods = 1;
    c.method[0].ordering = ordering;
    c.postorder = 1;
  }
  Row r = time_solver(name, solver, A, b, repeats);
  r.flops = c.fl;
  r.factor_nnz = c.lnz;
  return r;
}

// The product's factorisation in the interface time_solver uses: SparseSpdSolver, whose analysis
// is CHOLMOD's and whose first factorisation (which allocates the factor) is CHOLMOD's too; the
// timed ones are those of linalg/supernodal_cholesky.h.
struct ProductSolver {
  vs::SparseSpdSolver solver{vs::SparseSolverKind::kCholmodSupernodal};
  void analyzePattern(const vs::SparseMatrix& A) {
    solver.analyze(A);
    solver.factorize(A);
  }
  void factorize(const vs::SparseMatrix& A) { solver.factorize(A); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return solver.solve(b); }
};

// `threads` sets the OpenMP team (1: the two parts one after the other).
Row time_product(const std::string& name, const vs::SparseMatrix& A, const Eigen::VectorXd& b,
                 int repeats, int threads) {
  const int was = omp_get_max_threads();
  omp_set_num_threads(threads);
  ProductSolver product;
  Row r = time_solver(name, product, A, b, repeats);
  omp_set_num_threads(was);
  const cholmod_factor* L = product.solver.held_cholmod_factor();
  r.factor_nnz = L ? static_cast<double>(L->xsize) : 0.0;  // stored entries (CHOLMOD: nonzeros)
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string src = VS_SOURCE_DIR;
  const vsx::StudyArgs args =
      vsx::parse_args(argc, argv, src + "/experiments/09_linear_solver/results");
  std::filesystem::create_directories(args.out_dir);
  const std::vector<int> divisions =
      args.quick ? std::vector<int>{4, 8} : std::vector<int>{4, 8, 16, 32};
  std::ofstream csv(args.out_dir + "/linear_solver.csv");
  csv << "divisions,dofs,matrix_nnz,solver,analyse_s,factorise_s,solve_s,factor_nnz,flops,"
         "relative_residual\n";
  std::string md =
      "| n | dofs | solver | analyse s | factorise s | solve s | factor nnz | flops |\n"
      "|---|---|---|---|---|---|---|---|\n";
  std::string md_solves =
      "\n| n | dofs | CHOLMOD solve ms | supernodes, double ms | supernodes, single ms | single, "
      "one thread ms | tree cut: top / largest part % | single vs CHOLMOD (rel.) | matrix "
      "product ms |\n|---|---|---|---|---|---|---|---|---|\n";
  for (int n : divisions) {
    vsx::Overrides ov = {{"blank.divisions", std::to_string(n)}, {"tool.punch.friction", "0.2"}};
    for (const auto& [k, v] : args.sets) ov.push_back({k, v});
    const vs::Scene scene = vsx::make_scene(vsx::scene_path(src, "ex4a_quarter_disc_sticking"), ov);
    vs::shell3d::FormingModel model(scene);
    vs::shell3d::FormingState s = model.initial_state();
    model.place_tools(s);
    // Move every node with the punch (upwards), so that the flow law sees a strain rate field
    // of the dome kind and the secant is a realistic SPD matrix.
    for (int i = 0; i < model.num_nodes(); ++i) {
      const double r = std::hypot(s.x[i].x(), s.x[i].y());
      s.velocity[i] = vs::shell3d::Vec3(0.0, 0.0, std::max(0.0, 1.0 - r / scene.blank.radius_mm));
    }
    model.freeze_material(s, 0.1);
    model.prepare(s);
    const Eigen::VectorXd x = model.to_local(s.velocity, s.omega);
    vs::shell3d::FormingSystem sys;
    model.evaluate(s, x, vs::shell3d::Shell9Stiffness::kSecant, 0.0, &sys);
    const vs::SparseMatrix& A = model.matrix();
    Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
    const int repeats = n >= 32 ? 3 : 5;
    std::vector<Row> rows;
    using Super = Eigen::CholmodSupernodalLLT<vs::SparseMatrix, Eigen::Upper>;  // as the product
    using Simp = Eigen::CholmodSimplicialLLT<vs::SparseMatrix, Eigen::Lower>;
    rows.push_back(
        time_cholmod<Super>("cholmod supernodal (default ordering)", -1, true, A, b, repeats));
    rows.push_back(time_product("two-thread numeric factorisation (product)", A, b, repeats, 2));
    rows.push_back(time_product("the same on one thread", A, b, repeats, 1));
    rows.push_back(time_cholmod<Super>("cholmod supernodal, its 4-thread regions uncapped", -1,
                                       true, A, b, repeats, true));
    rows.push_back(
        time_cholmod<Super>("cholmod supernodal, METIS", CHOLMOD_METIS, true, A, b, repeats));
    rows.push_back(
        time_cholmod<Super>("cholmod supernodal, AMD", CHOLMOD_AMD, true, A, b, repeats));
    rows.push_back(
        time_cholmod<Simp>("cholmod simplicial, AMD", CHOLMOD_AMD, false, A, b, repeats));
    if (n <= 16) {
      Eigen::SimplicialLDLT<vs::SparseMatrix, Eigen::Lower> ldlt;
      rows.push_back(time_solver("eigen SimplicialLDLT (AMD)", ldlt, A, b, repeats));
    }
    // The solves the Krylov steps make with a held factor: CHOLMOD's own, the same factor's
    // supernodes traversed in double and in single precision (linalg/supernodal_factor.h),
    // and a product with the matrix (one per CG iteration), all as the product makes them.
    {
      vs::SparseSpdSolver super(vs::SparseSolverKind::kCholmodSupernodal);
      super.analyze(A);
      super.factorize(A);
      vs::SupernodalFactor<float> f32;
      vs::SupernodalFactor<double> f64;
      f32.assign(*super.held_cholmod_factor());
      f64.assign(*super.held_cholmod_factor());
      const Eigen::VectorXd x_ref = super.solve(b);
      Eigen::VectorXd z;
      auto time_it = [&](auto&& apply) {
        std::vector<double> t;
        for (int k = 0; k < 3 * repeats; ++k) {
          const auto t0 = Clock::now();
          apply();
          t.push_back(since(t0));
        }
        return median(t);
      };
      const double t_cholmod = time_it([&] { z = super.solve(b); });
      const double t64 = time_it([&] { f64.solve(b, &z); });
      const double d64 = (z - x_ref).norm() / x_ref.norm();
      const double t32 = time_it([&] { f32.solve(b, &z); });
      const double d32 = (z - x_ref).norm() / x_ref.norm();
      // The single-precision solve on one thread (the tree's parts one after the other).
      const int threads = omp_get_max_threads();
      omp_set_num_threads(1);
      const double t32_1 = time_it([&] { f32.solve(b, &z); });
      omp_set_num_threads(threads);
      const double tmv = time_it([&] { vs::multiply_symmetric(A, b, &z); });
      fmt::print(
          "n {:2d} dofs {:6d}: solve with the factor: CHOLMOD {:.2f} ms, supernodes in double "
          "{:.2f} ms (rel. diff {:.1e}), in single {:.2f} ms on {} threads, {:.2f} ms on one "
          "(rel. diff {:.1e}; tree cut: top set {:.1f} %, largest of {} parts {:.1f} % of the "
          "entries); matrix product {:.2f} ms\n",
          n, A.rows(), 1e3 * t_cholmod, 1e3 * t64, d64, 1e3 * t32, threads, 1e3 * t32_1, d32,
          100 * f32.top_fraction(), f32.kParts, 100 * f32.largest_part_fraction(), 1e3 * tmv);
      md_solves += fmt::format(
          "| {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.1f} / {:.1f} | {:.1e} | {:.2f} |\n",
          n, A.rows(), 1e3 * t_cholmod, 1e3 * t64, 1e3 * t32, 1e3 * t32_1, 100 * f32.top_fraction(),
          100 * f32.largest_part_fraction(), d32, 1e3 * tmv);
    }
    const long nnz = static_cast<long>(A.nonZeros());
    for (const Row& r : rows) {
      fmt::print(
          "n {:2d} dofs {:6d}: {:40s} analyse {:.4f} s factorise {:.4f} s solve {:.4f} s factor "
          "nnz {:.3g} flops {:.3g} residual {:.1e}\n",
          n, A.rows(), r.name, r.analyse_s, r.factor_s, r.solve_s, r.factor_nnz, r.flops,
          r.residual);
      csv << fmt::format("{},{},{},{},{:.5g},{:.5g},{:.5g},{:.6g},{:.6g},{:.3g}\n", n, A.rows(),
                         nnz, r.name, r.analyse_s, r.factor_s, r.solve_s, r.factor_nnz, r.flops,
                         r.residual);
      md +=
          fmt::format("| {} | {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.3g} | {:.3g} |\n", n,
                      A.rows(), r.name, r.analyse_s, r.factor_s, r.solve_s, r.factor_nnz, r.flops);
    }
  }
  std::ofstream(args.out_dir + "/summary.md") << md << md_solves;
  return 0;
}
