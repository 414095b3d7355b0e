// Full (unsymmetric) blanks of the 3D solver: the full_disc / full_square generators, the model's
// constraints without symmetry planes, and full against quarter runs of one scene. With
// blank.symmetry = "full" forming_mesh mirrors the quarter mesh onto all four quadrants, so both
// runs discretise the same sheet and must agree to the nonlinear solver's tolerance. The task
// asked for punch force within 0.5 % and thickness strain along y = 0 within 0.002; measured
// (printed by the tests, listed in forward/shell3d/README.md): at most 4.1e-9 relative in force
// and 2.2e-9 in thickness strain (Coulomb; sticking and the clamped square agree to 1e-14), so
// the tests hold both to 1e-5, which still leaves the solver's convergence tolerance room and
// catches any real difference between the two models.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>

#include "element/shell9.h"
#include "mesh/forming_mesh.h"
#include "mesh/mesh_generators.h"
#include "mesh_area.h"
#include "model/forming_fields.h"
#include "model/forming_model.h"
#include "model/shell_model.h"
#include "output/run_writer.h"
#include "output/shell_stage_vtu.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

using test::total_area;

double min_node_distance(const ShellMesh& mesh) {
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < mesh.num_nodes(); ++i)
    for (int j = i + 1; j < mesh.num_nodes(); ++j)
      d = std::min(d, (mesh.nodes[i] - mesh.nodes[j]).norm());
  return d;
}

// Every element's surface normal at each of its nodes is +z and the model finds no kinks.
void expect_flat_and_upward(const ShellMesh& mesh) {
  ShellModel model(mesh);
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int a = 0; a < 9; ++a)
      EXPECT_GT(element_normal_at_node(model.element_geometry(e).x, a).z(), 0.999999)
          << "element " << e << " node " << a;
  EXPECT_EQ(model.num_kinked(), 0);
}

// The lines through the centre hold exactly the nodes on them.
void expect_line_sets(const ShellMesh& mesh, double size) {
  const double tol = 1e-9 * size;
  int on_x0 = 0, on_y0 = 0, on_diagonal = 0;
  for (const auto& p : mesh.nodes) {
    on_x0 += std::abs(p.x()) < tol ? 1 : 0;
    on_y0 += std::abs(p.y()) < tol ? 1 : 0;
    on_diagonal += std::abs(p.x() - p.y()) < tol ? 1 : 0;
  }
  EXPECT_EQ(static_cast<int>(mesh.set("x0").size()), on_x0);
  EXPECT_EQ(static_cast<int>(mesh.set("y0").size()), on_y0);
  EXPECT_EQ(static_cast<int>(mesh.set("diagonal").size()), on_diagonal);
  ASSERT_EQ(mesh.set("centre").size(), 1u);
  EXPECT_LT(mesh.nodes[mesh.set("centre")[0]].norm(), tol);
}

TEST(FullBlankMesh, DiscCountsAreaSetsAndOrientation) {
  const double r = 50.0;
  const int n = 4, m = 2;
  const ShellMesh disc = full_disc(r, n, m, 1.0);
  EXPECT_EQ(disc.num_elements(), n * n + 4 * n * m);
  // (2n+1)^2 central nodes; each curved block adds 2m (2n+1) nodes off the square, less the 2m
  // of the radial seam it shares with its neighbour.
  EXPECT_EQ(disc.num_nodes(), (2 * n + 1) * (2 * n + 1) + 4 * (2 * m * (2 * n + 1) - 2 * m));
  EXPECT_GT(min_node_distance(disc), 0.1 * r / (2 * n));  // no duplicates left by the merge
  // Isoparametric rim: the same relative accuracy as the quarter disc test (mesh_test.cc).
  EXPECT_NEAR(total_area(disc), std::numbers::pi * r * r, 4e-4 * r * r);
  EXPECT_EQ(static_cast<int>(disc.set("edge").size()), 4 * 2 * n);
  for (int i : disc.set("edge")) EXPECT_NEAR(disc.nodes[i].norm(), r, 1e-9 * r);
  EXPECT_EQ(static_cast<int>(disc.set("y0").size()), 2 * n + 1 + 4 * m);
  expect_line_sets(disc, r);
  expect_flat_and_upward(disc);
}

TEST(FullBlankMesh, DiscIsTheQuarterDiscMirrored) {
  const double r = 40.0, tol = 1e-9 * r;
  const int k = 3;
  const ShellMesh full = full_disc(r, 2 * k, k, 1.0);
  const ShellMesh quarter = quarter_disc(r, k, k, 1.0);
  EXPECT_EQ(full.num_elements(), 4 * quarter.num_elements());
  int in_quadrant = 0;
  for (const auto& p : full.nodes) {
    if (p.x() < -tol || p.y() < -tol) continue;
    ++in_quadrant;
    EXPECT_LT((quarter.nodes[quarter.nearest_node(p)] - p).norm(), tol);
  }
  EXPECT_EQ(in_quadrant, quarter.num_nodes());
}

TEST(FullBlankMesh, SquareCountsAreaSetsAndOrientation) {
  const double a = 30.0;
  const int n = 6;
  const ShellMesh sq = full_square(a, n, 1.0);
  EXPECT_EQ(sq.num_elements(), n * n);
  EXPECT_EQ(sq.num_nodes(), (2 * n + 1) * (2 * n + 1));
  EXPECT_GT(min_node_distance(sq), 0.1 * a / n);
  EXPECT_NEAR(total_area(sq), 4.0 * a * a, 1e-12 * a * a);
  EXPECT_EQ(static_cast<int>(sq.set("edge").size()), 4 * 2 * n);
  expect_line_sets(sq, a);
  expect_flat_and_upward(sq);
}

Scene example_4a() {
  return load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
}

TEST(FullBlankMesh, FormingMeshSplitsTheProfileLines) {
  Scene s = example_4a();
  s.blank.divisions = 2;
  s.blank.symmetry = BlankSymmetry::kFull;
  const ShellMesh mesh = forming_mesh(s);
  const double tol = 1e-9 * s.blank.radius_mm;
  for (const char* line : {"y0", "x0", "diagonal"}) {
    const std::string neg = std::string(line) + "_neg";
    EXPECT_EQ(mesh.set(line).size(), mesh.set(neg).size()) << line;
    for (int i : mesh.set(line)) EXPECT_GT(mesh.nodes[i].x() + mesh.nodes[i].y(), -tol);
    for (int i : mesh.set(neg)) EXPECT_LT(mesh.nodes[i].x() + mesh.nodes[i].y(), tol);
  }
  EXPECT_EQ(static_cast<int>(mesh.set("y0").size()), 2 * 2 + 1 + 2 * 2);  // centre + square + ring
}

// Without symmetry planes only the free edge needs constraints against rigid motion: the
// centre's in-plane velocity and one circumferential velocity on y = 0.
TEST(FullBlankModel, ConstraintsWithoutSymmetryPlanes) {
  Scene s = example_4a();
  s.blank.divisions = 2;
  s.blank.symmetry = BlankSymmetry::kFull;
  for (EdgeCondition edge : {EdgeCondition::kPinned, EdgeCondition::kFree}) {
    s.blank.edge = edge;
    FormingModel model(s);
    EXPECT_EQ(model.symmetry_factor(), 1.0);
    FormingState st = model.initial_state();
    model.freeze_material(st, 0.1);
    model.prepare(st);
    const ShellModel& m = model.shell_model();
    const auto& fixed = model.prescribed_mask();
    const int centre = model.mesh().set("centre")[0];
    const int on_y0 = model.mesh().nearest_node(Eigen::Vector3d(20.0, 0.0, 0.0));
    const int rim_x = model.mesh().nearest_node(Eigen::Vector3d(s.blank.radius_mm, 0.0, 0.0));
    EXPECT_TRUE(model.on_axis(centre));
    EXPECT_LT((model.frame(centre) - Mat3::Identity()).norm(), 1e-15);
    for (int k = 0; k < 5; ++k) EXPECT_FALSE(fixed[m.dof(on_y0, k)]) << "dof " << k;
    for (int k : {2, 3, 4}) EXPECT_FALSE(fixed[m.dof(centre, k)]) << "dof " << k;
    const bool free = edge == EdgeCondition::kFree;
    EXPECT_EQ(fixed[m.dof(centre, 0)] != 0, free);
    EXPECT_EQ(fixed[m.dof(centre, 1)] != 0, free);
    EXPECT_TRUE(fixed[m.dof(rim_x, 0)]);  // pinned: the edge; free: the spin reference
    EXPECT_EQ(fixed[m.dof(rim_x, 2)] != 0, !free);
    int fixed_dofs = 0;
    for (char f : fixed) fixed_dofs += f;
    const int edge_nodes = static_cast<int>(model.mesh().set("edge").size());
    EXPECT_EQ(fixed_dofs, free ? 3 : 3 * edge_nodes);
  }
}

RunResult run(const Scene& s) {
  const RunResult r = simulate_shell3d(s);
  EXPECT_TRUE(r.completed()) << r.message;
  return r;
}

double force_at(const RunResult& r, double travel) {
  for (const StepRecord& rec : r.steps)
    if (std::abs(rec.punch_travel_mm - travel) < 1e-9) return rec.punch_force_N;
  ADD_FAILURE() << "no step at travel " << travel;
  return std::nan("");
}

// Largest |eps_thickness| difference between the full run's profile `full_line` and the quarter
// run's `quarter_line` (the same initial positions up to the mirror).
double profile_difference(const Scene& scene, const RunResult& quarter,
                          const std::string& quarter_line, const RunResult& full,
                          const std::string& full_line, std::size_t stage) {
  const double h0 = scene.blank.thickness_mm;
  const LineProfile q =
      line_profile(quarter.shell->mesh, quarter.shell->stages.at(stage), quarter_line, h0);
  const LineProfile f = line_profile(full.shell->mesh, full.shell->stages.at(stage), full_line, h0);
  EXPECT_EQ(q.nodes.size(), f.nodes.size()) << full_line;
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(q.nodes.size(), f.nodes.size()); ++i) {
    EXPECT_NEAR(q.r0_mm[i], f.r0_mm[i], 1e-9 * scene.blank.radius_mm);
    d = std::max(d, std::abs(q.eps_thickness[i] - f.eps_thickness[i]));
  }
  return d;
}

constexpr double kForceTolerance = 1e-5;   // relative
constexpr double kStrainTolerance = 1e-5;  // absolute, thickness strain

// Runs `quarter_scene` and its full twin and checks force and thickness strain at every output.
void expect_full_matches_quarter(const Scene& quarter_scene) {
  Scene full_scene = quarter_scene;
  full_scene.blank.symmetry = BlankSymmetry::kFull;
  const RunResult quarter = run(quarter_scene);
  const RunResult full = run(full_scene);
  ASSERT_TRUE(quarter.completed() && full.completed());
  EXPECT_EQ(full.shell->mesh.num_elements(), 4 * quarter.shell->mesh.num_elements());
  ASSERT_EQ(quarter.shell->stages.size(), full.shell->stages.size());
  for (std::size_t k = 0; k < quarter_scene.process.output_travels_mm.size(); ++k) {
    const double travel = quarter_scene.process.output_travels_mm[k];
    const double fq = force_at(quarter, travel), ff = force_at(full, travel);
    const double force_dev = (ff - fq) / fq;
    EXPECT_LT(std::abs(force_dev), kForceTolerance)
        << "travel " << travel << ": full " << ff << " N, quarter " << fq << " N";
    const double dy0 = profile_difference(quarter_scene, quarter, "y0", full, "y0", k);
    EXPECT_LT(dy0, kStrainTolerance) << "travel " << travel;
    // The other lines of the full blank, against the quarter's (its symmetry planes).
    double dother = 0.0;
    for (const auto& [q, f] :
         {std::pair{"y0", "y0_neg"}, std::pair{"x0", "x0"}, std::pair{"x0", "x0_neg"},
          std::pair{"diagonal", "diagonal"}, std::pair{"diagonal", "diagonal_neg"}})
      dother = std::max(dother, profile_difference(quarter_scene, quarter, q, full, f, k));
    EXPECT_LT(dother, kStrainTolerance) << "travel " << travel;
    std::cout << "[ measured ] travel " << travel << " mm: force full " << ff << " N, quarter "
              << fq << " N, relative difference " << force_dev << "; max |d eps_thickness| y0 "
              << dy0 << ", other lines " << dother << "\n";
  }
  std::cout << "[ measured ] run time quarter " << quarter.timings.total_s << " s, full "
            << full.timings.total_s << " s\n";
}

// Example 4a on a coarse mesh and a short travel (the scene's 0.5 mm grid, as forming_test.cc).
Scene disc_scene(double friction) {
  Scene s = example_4a();
  s.blank.divisions = 3;
  s.process.punch_travel_mm = 4.0;
  s.process.output_travels_mm = {2.0, 4.0};
  s.tools.at(0).friction = friction;
  s.numerics.max_travel_increment_per_length = 1e9;
  return s;
}

TEST(FullBlankForming, DiscStickingMatchesQuarter) {
  expect_full_matches_quarter(disc_scene(std::numeric_limits<double>::infinity()));
}

TEST(FullBlankForming, DiscCoulombMatchesQuarter) { expect_full_matches_quarter(disc_scene(0.2)); }

// An orthotropic sheet (Hill 1948, the ESAFORM AA6016-T4 r-values, RD along x) keeps the mirror
// symmetry about x = 0 and y = 0 that the quarter model assumes (scene_checks: RD along x or y).
TEST(FullBlankForming, OrthotropicDiscMatchesQuarter) {
  Scene s = disc_scene(0.2);
  s.material.anisotropy.model = AnisotropyModel::kHill48R;
  s.material.anisotropy.r0 = 0.526;
  s.material.anisotropy.r45 = 0.253;
  s.material.anisotropy.r90 = 0.601;
  expect_full_matches_quarter(s);
}

TEST(FullBlankForming, ClampedSquareMatchesQuarter) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4b_square_clamped.toml");
  s.blank.divisions = 3;
  s.process.punch_travel_mm = 4.0;
  s.process.output_travels_mm = {2.0, 4.0};
  s.numerics.max_travel_increment_per_length = 1e9;
  s.numerics.max_travel_increment_mm = 0.5;  // the grid of docs/shell3d.md's table (scene: 0.25)
  expect_full_matches_quarter(s);
}

// A free edge drawn over a die (example 2's punch and die, no blank holder): the full model's
// only constraints are the centre's in-plane velocity and one circumferential velocity
// (FormingModel::fix_rigid_modes); it must still follow the quarter model.
TEST(FullBlankForming, FreeEdgeOverTheDieMatchesQuarter) {
  Scene s = example_4a();
  s.blank.radius_mm = 80.0;
  s.blank.edge = EdgeCondition::kFree;
  s.blank.divisions = 2;
  s.tools.at(0).friction = 0.04;
  ToolSpec die;
  die.name = "die";
  die.kind = ToolKind::kDie;
  die.radius_mm = 52.83;
  die.profile_radius_mm = 6.35;
  die.friction = 0.04;
  s.tools.push_back(die);
  s.process.punch_travel_mm = 2.0;
  s.process.output_travels_mm = {1.0, 2.0};
  s.numerics.max_travel_increment_per_length = 1e9;
  expect_full_matches_quarter(s);
}

// The run folder of a full blank: profiles along both halves of every line, the whole mesh in
// the VTU files, forces without a symmetry factor.
TEST(FullBlankForming, OutputsCoverTheWholeBlank) {
  Scene s = example_4a();
  s.blank.symmetry = BlankSymmetry::kFull;
  s.blank.divisions = 1;
  s.process.punch_travel_mm = 1.0;
  s.process.output_travels_mm = {1.0};
  s.numerics.max_travel_increment_per_length = 1e9;
  const RunResult r = run(s);
  ASSERT_TRUE(r.completed());
  std::vector<std::string> lines;
  for (const Profile& p : r.profiles)
    if (p.punch_travel_mm == r.profiles.back().punch_travel_mm) lines.push_back(p.line);
  EXPECT_EQ(lines,
            (std::vector<std::string>{"x", "y", "diagonal", "x_neg", "y_neg", "diagonal_neg", "x",
                                      "y", "diagonal", "x_neg", "y_neg", "diagonal_neg"}));
  const std::string vtu = stage_vtu(r.shell->mesh, r.shell->stages.back(), s.blank.thickness_mm);
  EXPECT_NE(vtu.find("NumberOfCells=\"12\""), std::string::npos);
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "vs_full_blank_outputs";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_run_folder(s, r, dir.string());
  for (const char* f : {"load_travel.csv", "strains_travel_001.00mm_x.csv",
                        "strains_travel_001.00mm_diagonal_neg.csv", "fld_points.csv", "stage_0.vtu",
                        "stages.pvd", "run.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  EXPECT_GT(r.steps.back().punch_force_N, 0.0);
}

}  // namespace
}  // namespace vs::shell3d
