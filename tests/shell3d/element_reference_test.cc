// The fast 9-node shell kernel (shell9.cc: covariant operator as a quadratic polynomial in the
// thickness coordinate, MITC9 tying once per element, stacked rank-R stiffness product, nodal
// velocity frames inside the operator) against the straightforward evaluation it replaced: every
// thickness point rebuilds the tying operators from point_basis() / covariant_B(), and the matrix
// is summed point by point. Both must agree to round-off for every rule, with 5- and 6-dof nodes,
// and with nodal velocity frames (which must equal rotating the global result, K_loc = T^T K T).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

#include "benchmark_setups.h"
#include "element/mitc9.h"
#include "element/quadrature.h"
#include "element/shell9.h"

namespace vs::shell3d {
namespace {

struct Reference {
  Eigen::VectorXd force;
  Eigen::MatrixXd K;
  double potential = 0.0;
  std::vector<double> rate;
};

// The element before the speed work (shell9.cc of Nov 2026), without drilling and resultants.
Reference reference_evaluate(const Shell9Geometry& g, Shell9Rule rule, const ThicknessRule& thick,
                             const Shell9Material& mat, const Shell9State& st,
                             const Eigen::VectorXd& q, double tw) {
  const int n = g.ndof();
  Reference out;
  out.force = Eigen::VectorXd::Zero(n);
  out.K = Eigen::MatrixXd::Zero(n, n);
  const Rule1D mr = gauss_legendre(rule == Shell9Rule::kReduced ? 2 : 3);
  const bool separate = rule == Shell9Rule::kSelective;
  const int nt = static_cast<int>(thick.zeta.size());
  const Rule1D sr = gauss_legendre(separate ? 2 : static_cast<int>(mr.x.size()));
  const double Gs = mat.shear_correction * mat.shear_reference();
  out.rate.assign(mr.x.size() * mr.x.size() * nt, 0.0);
  auto local_B = [&](double r, double s, double t, const Mitc9TyingB* tying, PointBasis* pb) {
    const Shape9 sh = lagrange9(r, s);
    *pb = point_basis(g, sh, t);
    const Mat5X Bcov = tying ? mitc9_assumed_B(*tying, r, s) : covariant_B(g, sh, *pb, t);
    return Mat5X(local_transform(pb->C) * Bcov);
  };
  auto shear = [&](const Eigen::MatrixXd& Bs, double dV) {
    const Eigen::Vector2d gam = Bs * q;
    out.force += (Gs * dV) * (Bs.transpose() * gam);
    out.K += (Gs * dV) * Bs.transpose() * Bs;
    out.potential += 0.5 * Gs * gam.squaredNorm() * dV;
  };
  for (int k = 0; k < nt; ++k) {
    const double t = 2.0 * thick.zeta[k], wt = 2.0 * thick.weight[k];
    std::optional<Mitc9TyingB> tying;
    if (rule == Shell9Rule::kMitc9) tying = mitc9_tying(g, t);
    int ip = 0;
    for (std::size_t j = 0; j < mr.x.size(); ++j) {
      for (std::size_t i = 0; i < mr.x.size(); ++i, ++ip) {
        PointBasis pb;
        const Mat5X Bl = local_B(mr.x[i], mr.x[j], t, tying ? &*tying : nullptr, &pb);
        const double dV = pb.detJ * mr.w[i] * mr.w[j] * wt;
        const Eigen::MatrixXd Bm = Bl.topRows<3>();
        const Vec3 d = Bm * q;
        const int flow = ip * nt + k;
        const InPlanePoint p = mat.law->evaluate(st.sigma_y[flow], st.hardening_viscosity[flow], d);
        const Vec3 Ad = mat.law->A() * d;
        const Mat3 D = p.mu * mat.law->A() + tw * p.tangent_coef * Ad * Ad.transpose();
        out.rate[flow] = p.rate;
        out.force += dV * (Bm.transpose() * p.stress);
        out.K += dV * Bm.transpose() * D * Bm;
        out.potential += p.potential * dV;
        if (!separate) shear(Bl.bottomRows<2>(), dV);
      }
    }
    if (separate) {
      for (std::size_t j = 0; j < sr.x.size(); ++j)
        for (std::size_t i = 0; i < sr.x.size(); ++i) {
          PointBasis pb;
          const Mat5X Bl = local_B(sr.x[i], sr.x[j], t, nullptr, &pb);
          shear(Bl.bottomRows<2>(), pb.detJ * sr.w[i] * sr.w[j] * wt);
        }
    }
  }
  return out;
}

// A doubly curved element with varying thickness and tilted directors.
Shell9Geometry test_geometry(bool six_dof_node) {
  const ShellMesh mesh = sphere_patch(5.0, 0.3, 0.8, 0.1, 0.7, 1, 1, 0.2);
  ShellModel model(mesh);
  Shell9Geometry g = model.element_geometry(0);
  for (int a = 0; a < 9; ++a) {
    g.thickness[a] *= 1.0 + 0.1 * std::sin(1.7 * a);
    g.director[a] =
        (g.director[a] + Vec3(0.03 * std::cos(a), 0.02 * std::sin(2.0 * a), 0.0)).normalized();
  }
  if (six_dof_node) {
    g.n_rot[4] = 3;
    g.rot_map[4] = rot_map_6dof(g.director[4]);
  }
  return g;
}

Eigen::VectorXd test_velocity(int n) {
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = 1e-2 * (std::sin(1.3 * i + 0.2) + 0.1 * std::cos(0.7 * i * i));
  return q;
}

TEST(Shell9FastKernel, MatchesThePointByPointEvaluation) {
  const ThicknessRule thick = thickness_rule(ThicknessKind::kSimpson, 3);
  RateSpec rate;
  rate.law = RateLaw::kPower;
  rate.m = 0.1;
  const ViscousLaw law(rate, 1e-3, 1.6);
  const HillPlaneStressLaw hill(law);
  const Shell9Material mat = Shell9Material::Viscous(hill, 50.0);
  std::vector<double> sy(9 * 3), hv(sy.size());
  for (std::size_t k = 0; k < sy.size(); ++k) {
    sy[k] = 200.0 + 3.0 * static_cast<double>(k);
    hv[k] = 1.0 + 0.1 * static_cast<double>(k);
  }
  const Shell9State st{sy.data(), hv.data()};
  for (bool six : {false, true}) {
    Shell9Geometry g = test_geometry(six);
    for (auto rule :
         {Shell9Rule::kMitc9, Shell9Rule::kSelective, Shell9Rule::kFull, Shell9Rule::kReduced}) {
      const Eigen::VectorXd q = test_velocity(g.ndof());
      Shell9Material m = mat;
      m.drill_scale = 0.0;  // the reference has no drilling term
      const Reference ref = reference_evaluate(g, rule, thick, m, st, q, 0.7);
      Shell9Output out;
      shell9_evaluate(g, rule, thick, m, st, q, Shell9Stiffness::kTangent, &out, 0.7);
      EXPECT_LT((out.force - ref.force).norm(), 1e-12 * ref.force.norm());
      EXPECT_LT((out.stiffness - ref.K).norm(), 1e-12 * ref.K.norm());
      EXPECT_NEAR(out.potential, ref.potential, 1e-12 * std::abs(ref.potential));
      ASSERT_EQ(out.point_rate.size(), ref.rate.size());
      for (std::size_t k = 0; k < ref.rate.size(); ++k)
        EXPECT_NEAR(out.point_rate[k], ref.rate[k], 1e-12 * ref.rate[k]);
      // Potential-only evaluation: same force and potential.
      Shell9Output o2;
      shell9_evaluate(g, rule, thick, m, st, q, Shell9Stiffness::kNone, &o2);
      EXPECT_LT((o2.force - ref.force).norm(), 1e-12 * ref.force.norm());
      EXPECT_NEAR(o2.potential, ref.potential, 1e-12 * std::abs(ref.potential));

      // Nodal velocity frames: the same as rotating the global quantities.
      Shell9Geometry gl = g;
      gl.has_vel_frame = true;
      Eigen::MatrixXd T = Eigen::MatrixXd::Identity(g.ndof(), g.ndof());
      for (int a = 0; a < 9; ++a) {
        gl.vel_frame[a] = Eigen::AngleAxisd(0.3 + 0.5 * a, Vec3(1.0, 0.2 * a, 0.5).normalized())
                              .toRotationMatrix();
        T.block<3, 3>(g.offset(a), g.offset(a)) = gl.vel_frame[a];
      }
      const Eigen::VectorXd ql = T.transpose() * q;  // q = T ql
      Shell9Output loc;
      shell9_evaluate(gl, rule, thick, m, st, ql, Shell9Stiffness::kTangent, &loc, 0.7);
      EXPECT_LT((loc.force - T.transpose() * ref.force).norm(), 1e-12 * ref.force.norm());
      EXPECT_LT((loc.stiffness - T.transpose() * ref.K * T).norm(), 1e-12 * ref.K.norm());
      EXPECT_NEAR(loc.potential, ref.potential, 1e-12 * std::abs(ref.potential));
    }
  }
}

}  // namespace
}  // namespace vs::shell3d
