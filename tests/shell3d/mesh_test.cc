// Structured mesh generators (forward/shell3d/mesh_generators.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "element/shell9.h"
#include "mesh/mesh_generators.h"
#include "mesh_area.h"
#include "model/shell_model.h"

namespace vs::shell3d {
namespace {

using test::total_area;

TEST(MeshGenerators, QuarterDiscAreaSetsAndOrientation) {
  const double r = 50.0;
  const ShellMesh disc = quarter_disc(r, 4, 3, 1.0);
  EXPECT_EQ(disc.num_elements(), 4 * 4 + 2 * 4 * 3);
  // 81 + 2 x 63 block nodes; seams of 9, 9 and 7 nodes; the corner (r/2, r/2) is on all three.
  EXPECT_EQ(disc.num_nodes(), 81 + 2 * 63 - 9 - 9 - 7 + 1);
  EXPECT_NEAR(total_area(disc), 0.25 * std::numbers::pi * r * r, 1e-4 * r * r);
  EXPECT_EQ(disc.set("x0").size(), disc.set("y0").size());
  EXPECT_EQ(disc.set("rim").size(), 2u * 2u * 4u + 1u);
  EXPECT_EQ(disc.set("centre").size(), 1u);
  ShellModel model(disc);
  for (int i = 0; i < disc.num_nodes(); ++i) EXPECT_GT(model.director(i).z(), 0.999999);
  for (int e = 0; e < disc.num_elements(); ++e)
    for (int a = 0; a < 9; ++a)
      EXPECT_GT(element_normal_at_node(model.element_geometry(e).x, a).z(), 0.999999);
  EXPECT_EQ(model.num_kinked(), 0);
}

TEST(MeshGenerators, CurvedPatchesHaveExactNormalsAndAreas) {
  const ShellMesh sph =
      sphere_patch(2.0, 0.0 + 0.2, 0.5 * std::numbers::pi, 0.0, 0.5 * std::numbers::pi, 6, 6, 0.1);
  const double exact = 0.25 * 2.0 * std::numbers::pi * 4.0 * std::cos(0.2);
  EXPECT_NEAR(total_area(sph), exact, 3e-5 * exact);  // isoparametric surface error
  for (int i = 0; i < sph.num_nodes(); ++i)
    EXPECT_NEAR(sph.exact_normal[i].dot(sph.nodes[i].normalized()), 1.0, 1e-14);
  const ShellMesh cyl = cylinder_patch(3.0, 0.0, 2.0, 0.0, 1.0, 3, 5, 0.1);
  EXPECT_NEAR(total_area(cyl), 3.0 * 1.0 * 2.0, 1e-5);
  EXPECT_EQ(ShellModel(cyl).num_kinked(), 0);
}

TEST(MeshGenerators, PlateSets) {
  const ShellMesh p = rectangular_plate(2.0, 1.0, 4, 2, 0.1);
  EXPECT_EQ(p.num_nodes(), 9 * 5);
  EXPECT_EQ(p.set("x0").size(), 5u);
  EXPECT_EQ(p.set("y1").size(), 9u);
  EXPECT_NEAR(total_area(p), 2.0, 1e-13);
}

}  // namespace
}  // namespace vs::shell3d
