#include "model/gap_holder3.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "element/lagrange9.h"
#include "element/quadrature.h"
#include "model/ironing.h"

namespace vs::shell3d {

namespace {

// Penalty factor on the element's reference viscosity (AxisymModel::area_rate_penalty): keeps the
// constraint to ~1e-3 of the flow rate.
constexpr double kPenalty = 1e3;

}  // namespace

Eigen::Matrix<double, 9, 3> surface_divergence(const std::array<Vec3, 9>& x, double r, double s,
                                               double* area_jacobian) {
  const Shape9 sh = lagrange9(r, s);
  Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
  for (int a = 0; a < 9; ++a) {
    gr += sh.dr(a) * x[static_cast<std::size_t>(a)];
    gs += sh.ds(a) * x[static_cast<std::size_t>(a)];
  }
  const Vec3 m = gr.cross(gs);
  const double J = m.norm();
  if (area_jacobian) *area_jacobian = J;
  const Vec3 n = m / J;
  const Vec3 along_r = gs.cross(n) / J, along_s = n.cross(gr) / J;
  Eigen::Matrix<double, 9, 3> b;
  for (int a = 0; a < 9; ++a) b.row(a) = (sh.dr(a) * along_r + sh.ds(a) * along_s).transpose();
  return b;
}

std::array<double, 9> element_area_shares(const std::array<Vec3, 9>& x) {
  std::array<double, 9> area{};
  const Rule1D q = gauss_legendre(3);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const Shape9 sh = lagrange9(q.x[i], q.x[j]);
      Vec3 gr = Vec3::Zero(), gs = Vec3::Zero();
      for (int a = 0; a < 9; ++a) {
        gr += sh.dr(a) * x[static_cast<std::size_t>(a)];
        gs += sh.ds(a) * x[static_cast<std::size_t>(a)];
      }
      const double dA = gr.cross(gs).norm() * q.w[i] * q.w[j];
      for (int a = 0; a < 9; ++a) area[static_cast<std::size_t>(a)] += sh.N(a) * dA;
    }
  return area;
}

void GapHolder3::prepare(const GapHolderInput& in) {
  assert(in.mesh && in.x && in.thickness && in.in_gap && in.frame && in.viscosity);
  mesh_ = in.mesh;
  const int ne = in.mesh->num_elements();
  constraints_.assign(static_cast<std::size_t>(ne), {});
  gap_nodes_.assign(static_cast<std::size_t>(ne), {});
  constrained_elements_ = 0;
  const bool ironing = in.node_gap != nullptr;
  if (!(in.dt_s > 0.0) || !(ironing || in.gap_mm > 0.0)) return;
  for (int e = 0; e < ne; ++e) {
    const std::size_t ue = static_cast<std::size_t>(e);
    const auto& conn = in.mesh->elements[ue];
    bool any = false;
    for (int a = 0; a < 9; ++a) {
      const char g = (*in.in_gap)[static_cast<std::size_t>(conn[static_cast<std::size_t>(a)])];
      gap_nodes_[ue][static_cast<std::size_t>(a)] = g;
      any = any || g != 0;
    }
    if (!any) continue;
    double gap = in.gap_mm;
    if (ironing) {
      gap = std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < 9; ++a) {
        if (gap_nodes_[ue][a] != 0) {
          gap = std::min(gap, (*in.node_gap)[static_cast<std::size_t>(conn[a])]);
        }
      }
    }
    if (!(gap > 0.0) || !std::isfinite(gap)) {
      gap_nodes_[ue] = {};
      continue;
    }
    ++constrained_elements_;
    std::array<Vec3, 9> xe;
    for (std::size_t a = 0; a < 9; ++a) xe[a] = (*in.x)[static_cast<std::size_t>(conn[a])];
    const std::array<double, 9> area = element_area_shares(xe);
    const double k = kPenalty * (*in.viscosity)[ue];
    for (int a = 0; a < 9; ++a) {
      const std::size_t ua = static_cast<std::size_t>(a);
      // A share <= 0 (a badly distorted element) has no volume to constrain.
      if (!(area[ua] > 0.0)) continue;
      const std::size_t node = static_cast<std::size_t>(conn[ua]);
      const double h = (*in.thickness)[node];
      const std::array<double, 2> rs = lagrange9_node(a);
      const Eigen::Matrix<double, 9, 3> bg = surface_divergence(xe, rs[0], rs[1]);
      Constraint c;
      c.local = a;
      c.rate_bound = (ironing ? ironing_log_target(h, gap, in.max_log_ratio, in.correction, 0.0)
                              : std::min(0.0, std::log(h / gap))) /
                     in.dt_s;
      c.penalty = k;
      c.area = area[ua];
      c.stiffness = k * h * area[ua];
      // Local unknowns: v_b = Q_b (q_t - C_b q_r), so b_b . v_b = (Q_b^T b_b) . q_t -
      // (C_b^T Q_b^T b_b) . q_r.
      for (std::size_t b = 0; b < 9; ++b) {
        const std::size_t node_b = static_cast<std::size_t>(conn[b]);
        const Mat3& Q = (*in.frame)[node_b];
        const Vec3 bt = Q.transpose() * bg.row(static_cast<Eigen::Index>(b)).transpose();
        c.b.segment<3>(5 * static_cast<Eigen::Index>(b)) = bt;
        c.b.segment<2>(5 * static_cast<Eigen::Index>(b) + 3) =
            in.face ? Eigen::Vector2d(-(*in.face)[node_b].transpose() * bt)
                    : Eigen::Vector2d::Zero();
      }
      constraints_[ue].push_back(c);
    }
  }
}

void GapHolder3::add(int e, const Eigen::VectorXd& qe, bool want_matrix,
                     ElementContribution* out) const {
  const std::vector<Constraint>& list = constraints_[static_cast<std::size_t>(e)];
  if (list.empty()) return;
  assert(qe.size() == 45);
  const bool matrix = want_matrix && out->stiffness.rows() == qe.size();
  for (const Constraint& c : list) {
    const double violation = c.rate_bound - c.b.dot(qe);
    if (violation <= 0.0) continue;
    // Phi = k V violation^2 / 2; dPhi/dq = -k V violation b; d2Phi/dq2 = k V b b^T.
    out->potential += 0.5 * c.stiffness * violation * violation;
    out->force -= c.stiffness * violation * c.b;
    if (!matrix) continue;
    out->stiffness.noalias() += c.stiffness * c.b * c.b.transpose();
  }
}

void GapHolder3::add_element_forces(int e, const Eigen::VectorXd& qe,
                                    std::vector<double>* f) const {
  const std::size_t ue = static_cast<std::size_t>(e);
  const auto& conn = mesh_->elements[ue];
  const std::array<char, 9>& gap = gap_nodes_[ue];
  assert(qe.size() == 45);
  // Areas of the element's nodes in the gap, to share the force of the constrained nodes outside.
  double gap_area = 0.0;
  std::array<double, 9> share{};
  for (const Constraint& c : constraints_[ue]) {
    if (gap[static_cast<std::size_t>(c.local)]) {
      share[static_cast<std::size_t>(c.local)] = c.area;
      gap_area += c.area;
    }
  }
  for (const Constraint& c : constraints_[ue]) {
    const double violation = c.rate_bound - c.b.dot(qe);
    if (violation <= 0.0) continue;
    const double force = c.penalty * violation * c.area;  // pressure times area share
    if (gap[static_cast<std::size_t>(c.local)]) {
      (*f)[static_cast<std::size_t>(conn[static_cast<std::size_t>(c.local)])] += force;
    } else if (gap_area > 0.0) {
      for (std::size_t a = 0; a < 9; ++a) {
        if (share[a] > 0.0) (*f)[static_cast<std::size_t>(conn[a])] += force * share[a] / gap_area;
      }
    }
  }
}

}  // namespace vs::shell3d
