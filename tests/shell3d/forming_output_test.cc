// Outputs of the 3D forming run: the VTU / PVD writer (plain arrays) and the derived fields.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/mesh_generators.h"
#include "model/forming_fields.h"
#include "output/vtu_writer.h"

namespace vs::shell3d {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(VtuWriter, OneBiquadraticCellWithPointAndCellData) {
  VtuGrid g;
  for (int k = 0; k < 9; ++k) g.points.insert(g.points.end(), {double(k), 0.0, 0.0});
  for (int k = 0; k < 9; ++k) g.connectivity.push_back(k);
  g.offsets = {9};
  g.types = {kVtkBiquadraticQuad};
  const std::string vtu = render_vtu(g, {VtuField{"thickness_mm", 1, std::vector<double>(9, 0.85)}},
                                     {VtuField{"eps_major", 1, {0.25}}});
  EXPECT_NE(vtu.find("NumberOfPoints=\"9\" NumberOfCells=\"1\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"thickness_mm\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"eps_major\""), std::string::npos);
  EXPECT_EQ(count(vtu, "0.85"), 9);
  EXPECT_NE(vtu.find(" 28\n"), std::string::npos);
  EXPECT_THROW(render_vtu(g, {VtuField{"bad", 1, {1.0}}}, {}), std::invalid_argument);
  const std::string pvd = render_pvd({{0.0, "stage_0.vtu"}, {10.0, "stage_1.vtu"}});
  EXPECT_EQ(count(pvd, "<DataSet"), 2);
  EXPECT_NE(pvd.find("timestep=\"10\""), std::string::npos);
}

// A uniform in-plane stretch of a flat plate: major/minor strains are the logarithmic stretches,
// the membrane thickness strain their negative sum.
TEST(FormingFields, PrincipalStrainsOfAHomogeneousStretch) {
  const ShellMesh m = rectangular_plate(10.0, 10.0, 2, 2, 1.0);
  ShellStage st;
  st.thickness_mm.assign(m.num_nodes(), 1.0);
  st.contact_tool.assign(m.num_nodes(), -1);
  st.eps_effective.assign(m.num_elements(), 0.0);
  // Stretch 1.2 along the diagonal direction (1, 1)/sqrt(2), 0.9 across: principal axes rotated.
  const double a = 1.2, b = 0.9, c = std::sqrt(0.5);
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Eigen::Matrix2d R;
  R << c, -c, c, c;
  F.topLeftCorner<2, 2>() = R * Eigen::Vector2d(a, b).asDiagonal() * R.transpose();
  for (const auto& x : m.nodes) st.x.push_back(F * x);
  const ElementStrains e = element_strains(m, st);
  for (int k = 0; k < m.num_elements(); ++k) {
    EXPECT_NEAR(e.major[k], std::log(a), 1e-12);
    EXPECT_NEAR(e.minor[k], std::log(b), 1e-12);
    EXPECT_NEAR(e.thickness[k], -std::log(a * b), 1e-12);
  }
  EXPECT_NEAR(interpolate({0.0, 1.0, 3.0}, {0.0, 2.0, 6.0}, 2.0), 4.0, 1e-15);
  EXPECT_EQ(interpolate({0.0, 1.0}, {5.0, 6.0}, -1.0), 5.0);
}

}  // namespace
}  // namespace vs::shell3d
