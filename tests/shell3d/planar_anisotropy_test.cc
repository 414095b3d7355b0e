// Planar anisotropy in the 3D shell (material/planar_anisotropy.h, shell9.cc point_form): the
// element's stress in uniaxial tension at an angle to the convected rolling direction against the
// closed forms of Hill 1948 and the identification data of Yld2000-2d, the convection of RD with
// the sheet, and Hill 1948 with r0 = r45 = r90 = R against the normal-anisotropy law (element to
// round-off, a forming run to the solver's tolerance).
#include "material/planar_anisotropy.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include "element/quadrature.h"
#include "element/shell9.h"
#include "material/hill48.h"
#include "mesh/mesh_generators.h"
#include "model/forming_fields.h"
#include "model/shell_model.h"
#include "scene/load_scene.h"
#include "stepping/shell3d_driver.h"

namespace vs::shell3d {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// The ESAFORM 2021 AA6016-T4 data of the TUAT lab (data/measured/esaform2021-aa6016t4-cup).
AnisotropySpec hill48_tuat() {
  AnisotropySpec a;
  a.model = AnisotropyModel::kHill48R;
  a.r0 = 0.526;
  a.r45 = 0.253;
  a.r90 = 0.601;
  return a;
}

AnisotropySpec yld2000_tuat() {
  AnisotropySpec a = hill48_tuat();
  a.model = AnisotropyModel::kYld2000;
  a.sigma45_ratio = 0.908;
  a.sigma90_ratio = 0.983;
  a.sigma_b_ratio = 1.0;
  a.r_b = 1.0;
  a.exponent = 8.0;
  return a;
}

// One flat 9-node element of side 2 (thickness h) with material axes: the initial nodes rotated
// by beta about z, RD at phi from x in the initial sheet; the current nodes are F x_initial.
struct FlatElement {
  Shell9Geometry g;
  double h = 0.1;
};

FlatElement flat_element(double beta, double phi, const Eigen::Matrix2d& F) {
  static const ShellMesh mesh = rectangular_plate(2.0, 2.0, 1, 1, 0.1);
  static const ShellModel model(mesh);
  FlatElement el;
  el.g = model.element_geometry(0);
  const Eigen::Matrix2d Rb = rotation(beta);
  for (int a = 0; a < 9; ++a) {
    const Eigen::Vector2d X = Rb * el.g.x[a].head<2>();
    el.g.x_initial[a] = Vec3(X(0), X(1), 0.0);
    const Eigen::Vector2d x = F * X;
    el.g.x[a] = Vec3(x(0), x(1), 0.0);
  }
  el.g.has_material_axes = true;
  el.g.rd_initial = Vec3(std::cos(phi), std::sin(phi), 0.0);
  return el;
}

// Element dofs of the uniform in-plane rate D (global, symmetric): v = D x, no rotation rates.
Eigen::VectorXd uniform_rate(const Shell9Geometry& g, const Eigen::Matrix2d& D) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(g.ndof());
  for (int a = 0; a < 9; ++a) {
    const Eigen::Vector2d v = D * g.x[a].head<2>();
    q.segment<2>(g.offset(a)) = v;
  }
  return q;
}

// Global in-plane stress tensor at in-plane point p from the element's resultant N / h.
Eigen::Matrix2d global_stress(const Shell9Output& out, std::size_t p, double h) {
  const Shell9Resultant& r = out.resultant[p];
  Eigen::Matrix2d local;
  local << r.N(0), r.N(2), r.N(2), r.N(1);
  const Eigen::Matrix2d E = r.frame.topLeftCorner<2, 2>();
  return E * (local / h) * E.transpose();
}

// Uniaxial tension at theta from the current RD (psi = its global angle): the rate is the normal
// of the yield surface at u(theta) (material axes), turned to global axes; at unit flow stress
// the element's stress must be sigma_theta t t^T at every point (t the tension direction).
void expect_uniaxial(const PlanarAnisotropy& planar, const Shell9Material& mat,
                     const FlatElement& el, double psi, double theta, double* sigma_theta = nullptr,
                     double* r_theta = nullptr) {
  const PlaneVector u = uniaxial_stress_direction(theta);
  const YieldPoint y = planar.yield->evaluate(u);
  const PlaneVector dm = y.gradient;  // rate direction, material axes (engineering shear)
  Eigen::Matrix2d Dm;
  Dm << dm(0), 0.5 * dm(2), 0.5 * dm(2), dm(1);
  const Eigen::Matrix2d Rm = rotation(psi);
  const Eigen::Matrix2d D = Rm * Dm * Rm.transpose();
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  const int np = shell9_inplane_points(Shell9Rule::kMitc9) * 3;
  std::vector<double> sy(static_cast<std::size_t>(np), 1.0), hv(sy.size(), 0.0);
  const Shell9State st{sy.data(), hv.data()};
  Shell9Output out;
  shell9_evaluate(el.g, Shell9Rule::kMitc9, thick, mat, st, uniform_rate(el.g, D),
                  Shell9Stiffness::kNone, &out);
  const double expected = 1.0 / y.value;  // sigma_theta / sigma_0
  const Eigen::Vector2d t(std::cos(psi + theta), std::sin(psi + theta));
  const Eigen::Matrix2d S_expected = expected * t * t.transpose();
  for (std::size_t p = 0; p < out.resultant.size(); ++p) {
    const Eigen::Matrix2d S = global_stress(out, p, el.h);
    EXPECT_LT((S - S_expected).norm(), 1e-9) << "point " << p << " theta " << theta;
  }
  if (sigma_theta) *sigma_theta = expected;
  if (r_theta) *r_theta = lankford_ratio(dm, theta);
}

ViscousLaw rigid_plastic() { return ViscousLaw(RateSpec{}, 1e-9, 1.0); }

TEST(PlanarAnisotropy3d, UniaxialTensionAtAnAngleToRdGivesSigmaThetaAndRTheta) {
  const ViscousLaw law = rigid_plastic();
  const HillPlaneStressLaw hill(law);
  for (const AnisotropySpec& spec : {hill48_tuat(), yld2000_tuat()}) {
    const auto planar = make_planar_anisotropy(spec, "test");
    Shell9Material mat = Shell9Material::Viscous(hill, 1.0);
    mat.planar = planar.get();
    // Element axes and RD turned against each other; the current sheet a rigid rotation of the
    // initial one (RD turns with it).
    for (const auto& [beta, phi, spin] :
         {std::tuple{0.0, 0.0, 0.0}, std::tuple{0.3, 1.1, 0.0}, std::tuple{-0.7, 0.4, 0.9}}) {
      const FlatElement el = flat_element(beta, phi, rotation(spin));
      for (double theta : {0.0, kPi / 4, kPi / 2, kPi / 6, 1.2}) {
        double s = 0.0, r = 0.0;
        expect_uniaxial(*planar, mat, el, phi + spin, theta, &s, &r);
        if (spec.model == AnisotropyModel::kHill48R) {
          // Closed forms of Hill 1948 (hill48.h): with c = cos, s = sin of theta,
          //   1/sigma^2 = (G+H) c^4 - 2H c^2 s^2 + (F+H) s^4 + 2N c^2 s^2,
          //   r = (H + (2N - F - G - 4H) c^2 s^2) / (F s^2 + G c^2).
          const Hill48Coefficients k = hill48_from_r_values(spec.r0, spec.r45, spec.r90);
          const double c2 = std::pow(std::cos(theta), 2), s2 = std::pow(std::sin(theta), 2);
          const double inv2 =
              (k.G + k.H) * c2 * c2 - 2 * k.H * c2 * s2 + (k.F + k.H) * s2 * s2 + 2 * k.N * c2 * s2;
          EXPECT_NEAR(s, 1.0 / std::sqrt(inv2), 1e-12) << theta;
          EXPECT_NEAR(r, (k.H + (2 * k.N - k.F - k.G - 4 * k.H) * c2 * s2) / (k.F * s2 + k.G * c2),
                      1e-12)
              << theta;
        }
        // The data the yield function was identified from.
        if (theta == 0.0) {
          EXPECT_NEAR(r, spec.r0, 1e-8);
        }
        if (theta == kPi / 4) {
          EXPECT_NEAR(r, spec.r45, 1e-8);
        }
        if (theta == kPi / 2) {
          EXPECT_NEAR(r, spec.r90, 1e-8);
        }
        if (spec.model == AnisotropyModel::kYld2000) {
          if (theta == 0.0) {
            EXPECT_NEAR(s, 1.0, 1e-8);
          }
          if (theta == kPi / 4) {
            EXPECT_NEAR(s, spec.sigma45_ratio, 1e-8);
          }
          if (theta == kPi / 2) {
            EXPECT_NEAR(s, spec.sigma90_ratio, 1e-8);
          }
        }
      }
    }
  }
}

// RD is a material line: after the homogeneous deformation F (stretch and shear) it points along
// F RD0, in every flow point's local frame.
TEST(PlanarAnisotropy3d, RollingDirectionIsConvectedWithTheSheet) {
  Eigen::Matrix2d F;
  F << 1.3, 0.4, -0.1, 0.8;
  const double phi = 0.6;
  const FlatElement el = flat_element(0.25, phi, F);
  Shell9Operators ops;
  shell9_operators(el.g, Shell9Rule::kMitc9, thickness_rule(ThicknessKind::kSimpson, 3), &ops);
  const Eigen::Vector2d rd = F * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  const double expected = std::atan2(rd(1), rd(0));
  for (const Shell9Operators::FlowRow& fr : ops.flow) {
    const Mat3& frame = ops.frame[static_cast<std::size_t>(fr.point)];
    const double e1 = std::atan2(frame(1, 0), frame(0, 0));
    double a = std::atan2(fr.rd_sin, fr.rd_cos) + e1 - expected;
    a = std::remainder(a, 2 * kPi);
    EXPECT_NEAR(a, 0.0, 1e-12);
    EXPECT_NEAR(std::hypot(fr.rd_cos, fr.rd_sin), 1.0, 1e-14);
  }
  // Without material axes RD is e1.
  FlatElement plain = el;
  plain.g.has_material_axes = false;
  shell9_operators(plain.g, Shell9Rule::kMitc9, thickness_rule(ThicknessKind::kSimpson, 3), &ops);
  for (const Shell9Operators::FlowRow& fr : ops.flow) EXPECT_EQ(fr.rd_cos, 1.0);
}

// Hill 1948 with r0 = r45 = r90 = R is the normal-anisotropy law: force, tangent and potential of
// a curved, deformed element at an arbitrary rate agree to round-off, for any RD.
TEST(PlanarAnisotropy3d, EqualRValuesAreTheNormalAnisotropyLawToRoundOff) {
  static const ShellMesh mesh = sphere_patch(5.0, 0.3, 0.8, 0.1, 0.7, 1, 1, 0.2);
  static const ShellModel model(mesh);
  const double R = 1.7;
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.05;
  const ViscousLaw law(rate, 1e-3, R);
  const HillPlaneStressLaw hill(law);
  AnisotropySpec spec;
  spec.model = AnisotropyModel::kHill48R;
  spec.r0 = spec.r45 = spec.r90 = R;
  const auto planar = make_planar_anisotropy(spec, "test");
  Shell9Geometry g = model.element_geometry(0);
  g.x_initial = g.x;
  g.has_material_axes = true;
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  const int np = shell9_inplane_points(Shell9Rule::kMitc9) * 3;
  std::vector<double> sy(static_cast<std::size_t>(np), 180.0), hv(sy.size(), 2.0);
  const Shell9State st{sy.data(), hv.data()};
  Eigen::VectorXd q(g.ndof());
  for (int i = 0; i < q.size(); ++i) q(i) = 1e-2 * (std::sin(1.3 * i + 0.2) + 0.1 * (i % 3));
  Shell9Output a;
  shell9_evaluate(g, Shell9Rule::kMitc9, thick, Shell9Material::Viscous(hill, 10.0), st, q,
                  Shell9Stiffness::kTangent, &a);
  for (double phi : {0.0, 0.7, 2.0}) {
    g.rd_initial = Vec3(std::cos(phi), std::sin(phi), 0.0);
    Shell9Material mat = Shell9Material::Viscous(hill, 10.0);
    mat.planar = planar.get();
    Shell9Output b;
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, q, Shell9Stiffness::kTangent, &b);
    EXPECT_LT((a.force - b.force).norm(), 1e-13 * a.force.norm()) << phi;
    EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-13 * a.stiffness.norm()) << phi;
    EXPECT_NEAR(a.potential, b.potential, 1e-13 * std::abs(a.potential)) << phi;
  }
}

// The consistent tangent and the force are the derivatives of the force and the potential, for
// both planar laws on a curved element with RD oblique to the element axes.
TEST(PlanarAnisotropy3d, TangentAndForceAreDerivatives) {
  static const ShellMesh mesh = sphere_patch(5.0, 0.3, 0.8, 0.1, 0.7, 1, 1, 0.2);
  static const ShellModel model(mesh);
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.1;
  const ViscousLaw law(rate, 1e-3, 1.0);
  const HillPlaneStressLaw hill(law);
  Shell9Geometry g = model.element_geometry(0);
  g.x_initial = g.x;
  g.has_material_axes = true;
  g.rd_initial = Vec3(std::cos(0.4), std::sin(0.4), 0.0);
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  const int np = shell9_inplane_points(Shell9Rule::kMitc9) * 3;
  std::vector<double> sy(static_cast<std::size_t>(np), 200.0), hv(sy.size(), 3.0);
  const Shell9State st{sy.data(), hv.data()};
  Eigen::VectorXd q(g.ndof());
  for (int i = 0; i < q.size(); ++i) q(i) = 1e-2 * (std::sin(1.3 * i + 0.2) + 0.1 * (i % 3));
  for (const AnisotropySpec& spec : {hill48_tuat(), yld2000_tuat()}) {
    const auto planar = make_planar_anisotropy(spec, "test");
    Shell9Material mat = Shell9Material::Viscous(hill, 50.0);
    mat.planar = planar.get();
    Shell9Output out;
    shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, q, Shell9Stiffness::kTangent, &out);
    const double h = 1e-7;
    for (int j = 0; j < g.ndof(); j += 5) {
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      Shell9Output op, om;
      shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, qp, Shell9Stiffness::kNone, &op);
      shell9_evaluate(g, Shell9Rule::kMitc9, thick, mat, st, qm, Shell9Stiffness::kNone, &om);
      const Eigen::VectorXd fd = (op.force - om.force) / (2.0 * h);
      EXPECT_LT((fd - out.stiffness.col(j)).norm(), 1e-5 * out.stiffness.norm()) << j;
      EXPECT_NEAR((op.potential - om.potential) / (2.0 * h), out.force(j), 1e-6 * out.force.norm());
    }
    EXPECT_LT((out.stiffness - out.stiffness.transpose()).norm(), 1e-12 * out.stiffness.norm());
  }
}

// The primal-dual tangent (shell9.h) with Yld2000-2d: for any dual n it is given (here: on the
// unit ball sigma_bar(n) = 1), the point tangent D(n) = mu M + 3 w eh c sym(n (M d)^T) must stay
// positive semi-definite, or the assembled Newton matrix is indefinite and its step climbs the
// flow potential (the first step of the r45 0.292, r90 0.724 cup of experiments/10_earing looped
// on that). Adversarial case: equibiaxial stretching (m at the sharply curved equibiaxial point of
// the a = 8 locus) with n the pure-shear point of the unit ball, where n^T K(m) n = 5.3 (K the
// Hessian of sigma_bar^2 / 2 at m): unscaled, the point's D has eigenvalues -0.010 to 1 (relative)
// and the element's stiffness -1.1e-4 to 1.
// The consistent dual (n = m e / eh, inside the local ellipsoid) must be left as it is.
TEST(PlanarAnisotropy3d, Yld2000PrimalDualTangentStaysPositiveSemiDefinite) {
  AnisotropySpec spec = yld2000_tuat();  // UA yield-stress ratios, the failing r-values
  spec.r0 = 0.525;
  spec.r45 = 0.292;
  spec.r90 = 0.724;
  spec.sigma45_ratio = 0.867;
  spec.sigma90_ratio = 0.926;
  spec.sigma_b_ratio = 0.975;
  const auto planar = make_planar_anisotropy(spec, "test");
  const ViscousLaw law = rigid_plastic();
  const HillPlaneStressLaw hill(law);
  Shell9Material mat = Shell9Material::Viscous(hill, 50.0);
  mat.planar = planar.get();
  const FlatElement el = flat_element(0.0, 0.0, Eigen::Matrix2d::Identity());  // local = material
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  const auto np = static_cast<std::size_t>(shell9_inplane_points(Shell9Rule::kMitc9) * 3);
  std::vector<double> sy(np, 1.0), hv(np, 0.0);
  const Eigen::VectorXd q = uniform_rate(el.g, Eigen::Matrix2d::Identity());  // equibiaxial
  auto min_eigenvalue = [](const Eigen::MatrixXd& K) {
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    return ev(0) / ev(ev.size() - 1);
  };
  const PlaneVector shear(0.0, 0.0, 1.0);
  std::vector<Vec3> given(np, Vec3(shear / planar->yield->effective_stress(shear)));
  std::vector<Shell9FlowDirection> record(np);
  Shell9State st{sy.data(), hv.data()};
  st.dual_given = given.data();
  st.dual_record = record.data();
  Shell9Output out;
  shell9_evaluate(el.g, Shell9Rule::kMitc9, thick, mat, st, q, Shell9Stiffness::kTangent, &out);
  EXPECT_GT(min_eigenvalue(out.stiffness), -1e-12);
  for (const Shell9FlowDirection& r : record) {  // n scaled into the local ellipsoid
    EXPECT_LT(r.n.norm(), given[0].norm());
    EXPECT_GT(r.n.norm(), 0.0);
  }
  // n = the recorded m (the consistent tangent, on the ellipsoid's surface for e / eh = 1 in
  // double precision): untouched up to round-off, the tangent without duals.
  for (std::size_t k = 0; k < np; ++k) given[k] = record[k].m;
  shell9_evaluate(el.g, Shell9Rule::kMitc9, thick, mat, st, q, Shell9Stiffness::kTangent, &out);
  for (std::size_t k = 0; k < np; ++k)
    EXPECT_LT((record[k].n - given[k]).norm(), 1e-12 * given[k].norm()) << k;
  Shell9Output plain;
  const Shell9State no_duals{sy.data(), hv.data()};
  shell9_evaluate(el.g, Shell9Rule::kMitc9, thick, mat, no_duals, q, Shell9Stiffness::kTangent,
                  &plain);
  EXPECT_LT((out.stiffness - plain.stiffness).norm(), 1e-12 * plain.stiffness.norm());
  EXPECT_GT(min_eigenvalue(plain.stiffness), -1e-12);
}

// The calibration run that failed (experiments/10_earing, "One run failed"): the ESAFORM cup with
// Yld2000-2d at r45 0.292, r90 0.724 (UA yield-stress ratios, r_b 1), whose first step cycled for
// 100 iterations at |r|/|f| = 7.6e-2 with the unprojected duals. Now it converges with Newton
// steps only (measured: 25 iterations, 0 direct); a short draw (0.05 mm, about 3 s).
TEST(PlanarAnisotropy3d, Yld2000CalibrationCupFirstStepConverges) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) +
                       "/data/calibration/esaform_cup_3d_yld2000_quarter.toml");
  s.material.anisotropy.r45 = 0.292;
  s.material.anisotropy.r90 = 0.724;
  s.process.punch_travel_mm = 0.05;
  s.process.output_travels_mm = {0.05};
  const RunResult run = simulate_shell3d(s);
  ASSERT_TRUE(run.completed()) << run.message;
  ASSERT_FALSE(run.steps.empty());
  std::cout << "[ measured ] first step " << run.steps.front().iterations << " iterations\n";
  EXPECT_LE(run.steps.front().iterations, 40);
}

// The same in a forming run (ex4a, 2 divisions, 3 mm). The two laws differ by round-off, which
// can tip a decision of the solver (a Krylov or line-search stop, the iteration that meets the
// tolerance) one way in one run and the other in the other: the runs then agree to the nonlinear
// tolerance, not to round-off (at the default 1e-6 the force once differed by 1.7e-8 relative).
// Both run at a tolerance of 1e-10 (measured 6.7e-10 relative).
TEST(PlanarAnisotropy3d, EqualRValuesRunLikeNormalAnisotropy) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 2;
  s.numerics.tolerance = 1e-10;  // the runs agree to it (see above)
  s.process.punch_travel_mm = 3.0;
  s.process.output_travels_mm = {3.0};
  s.tools.at(0).friction = 0.2;
  s.material.r_value = 0.7;
  const RunResult normal = simulate_shell3d(s);
  s.material.anisotropy.model = AnisotropyModel::kHill48R;
  s.material.anisotropy.r0 = s.material.anisotropy.r45 = s.material.anisotropy.r90 = 0.7;
  s.material.r_value = 1.0;  // not used by the planar law
  const RunResult planar = simulate_shell3d(s);
  ASSERT_TRUE(normal.completed() && planar.completed()) << normal.message << planar.message;
  ASSERT_EQ(normal.steps.size(), planar.steps.size());
  const double f0 = normal.steps.back().punch_force_N, f1 = planar.steps.back().punch_force_N;
  std::cout << "[ measured ] force normal " << f0 << " N, planar " << f1 << " N, relative "
            << (f1 - f0) / f0 << "\n";
  EXPECT_LT(std::abs(f1 - f0), 1e-8 * f0);
  const ShellStage& a = normal.shell->stages.back();
  const ShellStage& b = planar.shell->stages.back();
  for (std::size_t i = 0; i < a.thickness_mm.size(); ++i)
    EXPECT_NEAR(a.thickness_mm[i], b.thickness_mm[i], 1e-9) << i;
}

// Turning RD from x to y mirrors the sheet about the diagonal: the thickness strain along x with
// RD = 0 is the one along y with RD = 90 deg. The two lines of one run differ (the anisotropy
// shows, where an isotropic sheet's differ by round-off; the mesh is symmetric about the
// diagonal): Hill 1948 with the ESAFORM r-values on ex4a (2 divisions, friction 0.2, 4 mm), at a
// nonlinear tolerance of 1e-10 (as EqualRValuesRunLikeNormalAnisotropy; measured 9e-13).
TEST(PlanarAnisotropy3d, RollingDirectionAlongYMirrorsRollingDirectionAlongX) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 2;
  s.numerics.tolerance = 1e-10;
  s.process.punch_travel_mm = 4.0;
  s.process.output_travels_mm = {4.0};
  s.tools.at(0).friction = 0.2;
  s.material.anisotropy = hill48_tuat();
  const RunResult rd_x = simulate_shell3d(s);
  s.material.anisotropy.rolling_direction_deg = 90.0;
  const RunResult rd_y = simulate_shell3d(s);
  ASSERT_TRUE(rd_x.completed() && rd_y.completed());
  const double h0 = s.blank.thickness_mm;
  const LineProfile ax = line_profile(rd_x.shell->mesh, rd_x.shell->stages.back(), "y0", h0);
  const LineProfile ay = line_profile(rd_x.shell->mesh, rd_x.shell->stages.back(), "x0", h0);
  const LineProfile by = line_profile(rd_y.shell->mesh, rd_y.shell->stages.back(), "x0", h0);
  ASSERT_EQ(ax.nodes.size(), by.nodes.size());
  double mirror = 0.0, lines = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < ax.nodes.size(); ++i) {
    largest = std::max(largest, std::abs(ax.eps_thickness[i]));
    mirror = std::max(mirror, std::abs(ax.eps_thickness[i] - by.eps_thickness[i]));
    lines = std::max(lines, std::abs(ax.eps_thickness[i] - ay.eps_thickness[i]));
  }
  std::cout << "[ measured ] |eps_t(x; RD x) - eps_t(y; RD y)| " << mirror
            << ", |eps_t(x) - eps_t(y)| of one run " << lines << " (largest |eps_t| " << largest
            << ")\n";
  EXPECT_LT(mirror, 1e-8);
  // r0 = 0.526 and r90 = 0.601 are close, and the difference is step-dependent: converged in the
  // travel step it is 0.42 % of the largest strain (grid 0.03125 / 0.0625 mm: 0.42 / 0.43 %, Heun
  // and implicit alike), 0.92-0.95 % at 0.125-0.25 mm, 0.45 % on the 0.5 mm grid of the defaults
  // (Nov 2026; a 1 % bound held only at some steps). An isotropic sheet's lines differ by
  // round-off (as `mirror`, ~1e-12), so 0.1 % still tells the anisotropy from none.
  EXPECT_GT(lines, 1e-3 * largest);
  EXPECT_NEAR(rd_x.steps.back().punch_force_N, rd_y.steps.back().punch_force_N,
              1e-8 * rd_x.steps.back().punch_force_N);
}

// Earing starts in the flange: the flange outline turns into lobes, and the material that stays
// out longest ends up highest in the wall (the ears). With Hill 1948 and the ESAFORM TUAT
// r-values (r0 + r90 - 2 r45 > 0: ears at 0 and 90 deg to RD) the flange draws in less along RD
// and TD than at 45 deg, so early in the draw the rim radius is largest at 0 and 90 deg (measured
// +0.34 / +0.26 mm on the 45 deg node at 8 mm); a normally anisotropic sheet (R-bar) draws in
// evenly up to the mesh (9e-4 mm). The bundled anisotropic 3D cup (10 kN holder) on 3
// divisions, to 8 mm.
TEST(PlanarAnisotropy3d, CupFlangeStaysOutLongestAlongRdAndTd) {
  auto rim_radii = [](const RunResult& r) {
    double r0 = 0.0, r45 = 0.0, r90 = 0.0, best45 = 1e9;
    for (int node : r.shell->mesh.set("edge")) {
      const Eigen::Vector3d& p0 = r.shell->mesh.nodes[node];
      const Eigen::Vector3d& x = r.shell->stages.back().x[node];
      const double rad = std::hypot(x.x(), x.y());
      const double angle = std::atan2(p0.y(), p0.x());
      if (std::abs(angle) < 1e-9) r0 = rad;
      if (std::abs(angle - kPi / 2) < 1e-9) r90 = rad;
      if (std::abs(angle - kPi / 4) < best45) {
        best45 = std::abs(angle - kPi / 4);
        r45 = rad;
      }
    }
    return std::array<double, 3>{r0, r45, r90};
  };
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/esaform_cup_3d_hill48_tuat.toml");
  s.blank.divisions = 3;
  s.process.punch_travel_mm = 8.0;
  s.process.output_travels_mm = {8.0};
  const RunResult aniso = simulate_shell3d(s);
  s.material.anisotropy.model = AnisotropyModel::kNormal;
  s.material.r_value = 0.41;
  const RunResult iso = simulate_shell3d(s);
  ASSERT_TRUE(aniso.completed() && iso.completed()) << aniso.message << iso.message;
  const auto a = rim_radii(aniso), i = rim_radii(iso);
  std::cout << "[ measured ] rim radius at 0/45/90 deg: Hill 1948 " << a[0] << " " << a[1] << " "
            << a[2] << " mm, normal anisotropy " << i[0] << " " << i[1] << " " << i[2]
            << " mm; run times " << aniso.timings.total_s << " s, " << iso.timings.total_s
            << " s\n";
  const double iso_spread = std::abs(i[1] - 0.5 * (i[0] + i[2]));
  EXPECT_GT(a[0] - a[1], 3.0 * iso_spread + 0.1);
  EXPECT_GT(a[2] - a[1], 3.0 * iso_spread + 0.1);
}

// Yld2000-2d with isotropic data and exponent 2 is von Mises (alpha = 1): its local dual solve
// must reproduce the closed-form law of R = 1 in a forming run, at a nonlinear tolerance of 1e-10
// (as EqualRValuesRunLikeNormalAnisotropy; measured 4.6e-12 relative).
TEST(PlanarAnisotropy3d, IsotropicYld2000WithExponentTwoRunsLikeVonMises) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 2;
  s.numerics.tolerance = 1e-10;
  s.process.punch_travel_mm = 3.0;
  s.process.output_travels_mm = {3.0};
  s.tools.at(0).friction = 0.2;
  const RunResult mises = simulate_shell3d(s);
  AnisotropySpec& a = s.material.anisotropy;
  a.model = AnisotropyModel::kYld2000;
  a.exponent = 2.0;  // every other datum 1: the isotropic point alpha = 1
  const RunResult yld = simulate_shell3d(s);
  ASSERT_TRUE(mises.completed() && yld.completed());
  ASSERT_EQ(mises.steps.size(), yld.steps.size());
  const double f0 = mises.steps.back().punch_force_N, f1 = yld.steps.back().punch_force_N;
  std::cout << "[ measured ] force von Mises " << f0 << " N, Yld2000 a = 2 " << f1
            << " N, relative " << (f1 - f0) / f0 << "\n";
  EXPECT_LT(std::abs(f1 - f0), 1e-9 * f0);
}

// Yld2000-2d warm-starts each flow point's local solve from its previous evaluation: still
// bitwise the same for one and two threads (each element owns its points' starts).
TEST(PlanarAnisotropy3d, Yld2000RunIsBitwiseIdenticalForOneAndTwoThreads) {
  Scene s = load_scene(std::string(VS_SOURCE_DIR) + "/data/scenes/ex4a_quarter_disc_sticking.toml");
  s.blank.divisions = 2;
  s.process.punch_travel_mm = 2.0;
  s.process.output_travels_mm = {2.0};
  s.tools.at(0).friction = 0.2;
  s.material.anisotropy = yld2000_tuat();
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const RunResult one = simulate_shell3d(s);
  omp_set_num_threads(2);
  const RunResult two = simulate_shell3d(s);
  omp_set_num_threads(threads);
  ASSERT_TRUE(one.completed() && two.completed());
  ASSERT_EQ(one.steps.size(), two.steps.size());
  for (std::size_t k = 0; k < one.steps.size(); ++k)
    EXPECT_EQ(one.steps[k].punch_force_N, two.steps[k].punch_force_N) << k;
  const ShellStage& a = one.shell->stages.back();
  const ShellStage& b = two.shell->stages.back();
  for (std::size_t i = 0; i < a.x.size(); ++i) EXPECT_EQ(a.x[i], b.x[i]) << i;
}

}  // namespace
}  // namespace vs::shell3d
