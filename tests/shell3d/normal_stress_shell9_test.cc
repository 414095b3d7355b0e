// The through-thickness normal stress term in the 9-node shell (shell9.h, Shell9State::
// face_pressure; material/normal_stress.h) against the closed-form section resultants at an
// equibiaxial membrane rate: N11 = N22 = h (sigma_eb - (p_l + p_u) / 2), N12 = 0,
// M11 = M22 = (p_l - p_u) h^2 / 12 (z along e3, the lower face at z = -h/2), the potential lower
// by h A (p_l + p_u) / 2 (d11 + d22), the stiffness unchanged, and the force still the gradient of
// the potential (a general velocity on a curved element).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "element/quadrature.h"
#include "element/shell9.h"
#include "mesh/mesh_generators.h"
#include "model/shell_model.h"

namespace vs::shell3d {
namespace {

TEST(Shell9NormalStress, SectionResultantsAtEquibiaxialRate) {
  const double sy = 250.0, h = 0.8, R = 1.5, pl = 14.0, pu = 4.0, rate = 0.3;
  const double lx = 2.0;
  const ShellMesh mesh = rectangular_plate(lx, lx, 1, 1, h);
  const ShellModel model(mesh);
  const Shell9Geometry g = model.element_geometry(0);
  const ViscousLaw scalar(RateSpec{}, 1e-12, R);
  const HillPlaneStressLaw hill(scalar);
  const Shell9Material mat = Shell9Material::Viscous(hill, 1.0);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(g.ndof());
  for (int a = 0; a < 9; ++a) {  // u = rate x, v = rate y: d11 = d22 = rate everywhere
    q(g.offset(a)) = rate * g.x[a].x();
    q(g.offset(a) + 1) = rate * g.x[a].y();
  }
  const double seb = sy * std::sqrt((1.0 + R) / 2.0);
  for (int nt : {3, 5}) {
    const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, nt);
    const std::vector<double> sigma(static_cast<std::size_t>(9 * nt), sy);
    const std::vector<FacePressure> pressure(9, FacePressure{pl, pu});
    Shell9State plain;
    plain.sigma_y = sigma.data();
    Shell9State pressed = plain;
    pressed.face_pressure = pressure.data();
    Shell9Output a, b, ak, bk;
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, plain, q, Shell9Stiffness::kNone, &a);
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, pressed, q, Shell9Stiffness::kNone, &b);
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, plain, q, Shell9Stiffness::kSecant, &ak);
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, pressed, q, Shell9Stiffness::kSecant, &bk);
    ASSERT_EQ(b.resultant.size(), 9u);
    for (const Shell9Resultant& r : b.resultant) {
      ASSERT_GT(r.frame(2, 2), 0.99);  // e3 = +z: the lower face is z = -h/2
      EXPECT_NEAR(r.N(0), h * (seb - 0.5 * (pl + pu)), 1e-9 * h * seb) << nt;
      EXPECT_NEAR(r.N(1), h * (seb - 0.5 * (pl + pu)), 1e-9 * h * seb) << nt;
      EXPECT_NEAR(r.N(2), 0.0, 1e-9 * h * seb);
      EXPECT_NEAR(r.M(0), (pl - pu) * h * h / 12.0, 1e-9 * h * seb) << nt;
      EXPECT_NEAR(r.M(1), (pl - pu) * h * h / 12.0, 1e-9 * h * seb) << nt;
    }
    const double area = lx * lx;
    EXPECT_NEAR(b.potential - a.potential, -h * area * 0.5 * (pl + pu) * 2.0 * rate,
                1e-9 * std::abs(a.potential));
    EXPECT_LT((bk.stiffness - ak.stiffness).norm(), 1e-12 * ak.stiffness.norm());
  }
}

TEST(Shell9NormalStress, ForceIsTheGradientOfThePotential) {
  const ShellMesh mesh = sphere_patch(5.0, 0.3, 0.8, 0.1, 0.7, 1, 1, 0.2);
  const ShellModel model(mesh);
  const Shell9Geometry g = model.element_geometry(0);
  const ViscousLaw scalar(RateSpec{}, 1e-6, 1.3);
  const HillPlaneStressLaw hill(scalar);
  const Shell9Material mat = Shell9Material::Viscous(hill, 40.0);
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 5);
  const std::vector<double> sigma(45, 200.0);
  std::vector<FacePressure> pressure;
  for (int p = 0; p < 9; ++p) pressure.push_back(FacePressure{10.0 + p, 3.0 - 0.2 * p});
  Shell9State st;
  st.sigma_y = sigma.data();
  st.face_pressure = pressure.data();
  Eigen::VectorXd q(g.ndof());
  for (int i = 0; i < q.size(); ++i) q(i) = std::sin(1.3 * i + 0.2) + 0.1 * std::cos(0.7 * i * i);
  Shell9Output out, op, om;
  shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, q, Shell9Stiffness::kNone, &out);
  for (int j = 0; j < q.size(); ++j) {
    const double eps = 1e-6;
    Eigen::VectorXd qp = q, qm = q;
    qp(j) += eps;
    qm(j) -= eps;
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, qp, Shell9Stiffness::kNone, &op);
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, qm, Shell9Stiffness::kNone, &om);
    EXPECT_NEAR((op.potential - om.potential) / (2.0 * eps), out.force(j), 1e-5 * out.force.norm())
        << j;
  }
}

}  // namespace
}  // namespace vs::shell3d
