#include "model/axisym_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact/coulomb.h"
#include "core/error.h"
#include "model/ironing.h"

namespace vs {

namespace {

constexpr double kTwoOverPi = 2.0 / std::numbers::pi;

// Node radii of a meridian from the pole to `radius` with `n` elements whose lengths grow
// geometrically so that last/first = grading.
std::vector<double> graded_radii(double radius, int n, double grading) {
  const double q = n > 1 ? std::pow(grading, 1.0 / (n - 1)) : 1.0;
  std::vector<double> len(n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    len[i] = std::pow(q, i);
    sum += len[i];
  }
  std::vector<double> r(n + 1, 0.0);
  for (int i = 0; i < n; ++i) r[i + 1] = r[i] + radius * len[i] / sum;
  r[n] = radius;
  return r;
}

}  // namespace

AxisymModel::AxisymModel(const Scene& scene)
    : scene_(scene),
      rule_(simpson_rule(scene.numerics.thickness_points)),
      hardening_(scene.material.hardening, scene.material.elastic),
      law_(scene.material.rate,
           scene.numerics.strain_rate_cutoff * scene.process.punch_speed_mm_per_s /
               scene.blank.radius_mm,
           scene.material.r_value),
      tools_(make_tools(scene)) {
  if (scene.geometry != Geometry::kAxisymmetric) {
    throw InputError(scene.source + ": the axisymmetric solver only runs axisymmetric scenes");
  }
  nominal_rate_ = scene.process.punch_speed_mm_per_s / scene.blank.radius_mm;
  friction_velocity_ = scene.numerics.friction_regularisation * scene.process.punch_speed_mm_per_s;
  r0_ = graded_radii(scene.blank.radius_mm, scene.blank.elements, scene.blank.grading);
  const double h0 = scene.blank.thickness_mm;
  for (int e = 0; e + 1 < num_nodes(); ++e) {
    l0_.push_back(r0_[e + 1] - r0_[e]);
    volume_.push_back(std::numbers::pi * (r0_[e + 1] * r0_[e + 1] - r0_[e] * r0_[e]) * h0);
  }
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    if (tools_[i].is_punch()) punch_ = static_cast<int>(i);
    if (tools_[i].kind() == ToolKind::kDie) die_ = static_cast<int>(i);
    if (tools_[i].kind() == ToolKind::kBlankHolder) holder_ = static_cast<int>(i);
  }
  for (const ToolSpec& t : scene.tools) {
    if (t.kind == ToolKind::kBlankHolder) {
      has_holder_ = true;
      holder_force_ = t.force_N;
      holder_gap_ = t.gap_mm;
      holder_friction_ = t.friction;
    }
  }
  if (punch_ < 0) throw InputError(scene.source + ": the scene has no punch");
  if (has_holder_ && die_ < 0) throw InputError(scene.source + ": a blank holder needs a die");
  if (has_holder_ && std::isinf(holder_friction_)) {
    throw InputError(scene.source + ": blank holder friction cannot be sticking (inf)");
  }
}

AxisymState AxisymModel::initial_state() const {
  AxisymState s;
  s.x.resize(num_nodes());
  for (int i = 0; i < num_nodes(); ++i) s.x[i] = Eigen::Vector2d(r0_[i], 0.0);
  s.thickness.assign(num_elements(), scene_.blank.thickness_mm);
  s.eps_bar.assign(static_cast<std::size_t>(num_elements()) * rule_.zeta.size(), 0.0);
  s.tool_offset.assign(tools_.size(), Eigen::Vector2d::Zero());
  s.contact.resize(num_nodes());
  s.v = Eigen::VectorXd::Zero(num_dofs());
  return s;
}

void AxisymModel::place_tools(const AxisymState& s) {
  for (std::size_t t = 0; t < tools_.size(); ++t) tools_[t].set_offset(s.tool_offset[t]);
  if (scene_.numerics.normal_stress == NormalStress::kContact) freeze_face_pressures(s);
}

void AxisymModel::freeze_face_pressures(const AxisymState& s) {
  const int ne = num_elements(), nn = num_nodes();
  std::vector<double> area(nn, 0.0);  // nodal areas, full 360 degrees [mm^2]
  std::vector<Eigen::Vector2d> normal(ne);
  for (int e = 0; e < ne; ++e) {
    const Axisym2Geometry g = geometry(s, e);
    const double l = g.length();
    const double half = std::numbers::pi * g.mid_radius() * l;
    area[e] += half;
    area[e + 1] += half;
    normal[e] = Eigen::Vector2d(-(g.zb - g.za) / l, (g.rb - g.ra) / l);
  }
  face_pressure_.assign(ne, FacePressure{});
  for (int i = 0; i < nn; ++i) {
    const NodeContact& c = s.contact[i];
    if (c.tool < 0 || area[i] <= 0.0) continue;
    const double p_tool = std::max(c.normal_force_N, 0.0) / area[i];
    const double p_other = std::max(c.holder_force_N + c.squeeze_force_N, 0.0) / area[i];
    for (int e : {i - 1, i}) {
      if (e < 0 || e >= ne) continue;
      const double dir = c.normal.dot(normal[e]);
      add_face_pressure(dir, 0.5 * p_tool, &face_pressure_[e]);
      add_face_pressure(-dir, 0.5 * p_other, &face_pressure_[e]);
    }
  }
}

void AxisymModel::freeze_material(const std::vector<double>& eps_bar, double dt_predicted) {
  // Backward Euler in the hardening: the solve sees sigma_y(eps_bar + dt eps_dot), linearised.
  // Rate-independent flow makes the hardening an algebraic constraint (two elements carrying the
  // same load flow in whatever proportion keeps their flow stresses equal), i.e. an infinitely
  // stiff mode. For a yield-stress difference d between two such elements the solve gives a
  // rate difference -d / (theta H dt) and the step changes d by H dt times that: d -> (1 - 1/theta)
  // d. The midpoint weight theta = 1/2 (used before Nov 2026) flips the sign of d every step
  // without damping it: the strain rates alternated step to step by up to 30 % and the load curve
  // and strains jittered above 0.05 element lengths per step (experiments/06_step_stability); theta
  // = 1 removes the difference in one step (with the Heun predictor hardening from the start of the
  // step too, Driver::take_step).
  constexpr double kTheta = 1.0;
  step_dt_ = dt_predicted;
  const std::size_t np = rule_.zeta.size();
  sigma_y_.assign(num_elements(), std::vector<double>(np));
  hardening_viscosity_.assign(num_elements(), std::vector<double>(np));
  shear_viscosity_.assign(num_elements(), 0.0);
  for (int e = 0; e < num_elements(); ++e) {
    for (std::size_t k = 0; k < np; ++k) {
      double H = 0.0;
      sigma_y_[e][k] = hardening_.flow_stress_and_slope(eps_bar[e * np + k], &H);
      hardening_viscosity_[e][k] = kTheta * H * dt_predicted;
    }
    // Transverse shear penalty: the viscosity of the section's mid point at the nominal rate
    // (numerics.md section 3.4: keep transverse shear out of the flow rule), from the hardening
    // curve (the elastic start's flow stress is 0 in the undeformed sheet).
    const double sy = hardening_.curve_stress(eps_bar[e * np + np / 2]);
    shear_viscosity_[e] = law_.is_constant()
                              ? law_.constant_mu()
                              : law_.effective_stress(sy, nominal_rate_) / (3.0 * nominal_rate_);
  }
}

Axisym2Geometry AxisymModel::geometry(const AxisymState& s, int e) const {
  return {s.x[e].x(), s.x[e].y(), s.x[e + 1].x(), s.x[e + 1].y()};
}

double AxisymModel::node_thickness(const AxisymState& s, int node) const {
  if (node == 0) return s.thickness.front();
  if (node == num_nodes() - 1) return s.thickness.back();
  return 0.5 * (s.thickness[node - 1] + s.thickness[node]);
}

double AxisymModel::face_arm(const AxisymState& s, int node) const {
  if (scene_.numerics.friction_surface != FrictionSurface::kFace) return 0.0;
  const NodeContact& c = s.contact[node];
  if (c.tool < 0 || (node == 0 && r0_.front() == 0.0)) return 0.0;
  // Pressed on both faces (flange under a holder, ironing): the mid-surface stays.
  if (c.on_die_face && (has_holder_ || fixed_gap_holder())) return 0.0;
  if (c.on_holder_face || c.squeeze_tool >= 0) return 0.0;
  // The node's normal: the mean of its elements' normals n = (-s, c).
  Eigen::Vector2d n = Eigen::Vector2d::Zero();
  for (int e : {node - 1, node}) {
    if (e < 0 || e >= num_elements()) continue;
    const Eigen::Vector2d t = s.x[e + 1] - s.x[e];
    n += Eigen::Vector2d(-t.y(), t.x()).normalized();
  }
  return 0.5 * node_thickness(s, node) * std::abs(n.normalized().dot(c.normal));
}

Eigen::Matrix3d AxisymModel::frame(const AxisymState& s, int node) const {
  Eigen::Matrix3d Q = Eigen::Matrix3d::Identity();
  const NodeContact& c = s.contact[node];
  if (c.tool < 0) return Q;
  const Eigen::Vector2d n = c.normal;
  const Eigen::Vector2d t(n.y(), -n.x());
  Q(0, 0) = t.x();
  Q(1, 0) = t.y();
  Q(0, 1) = n.x();
  Q(1, 1) = n.y();
  // Face velocity (friction_surface = face): the tangential unknown is the touching face's
  // v_t + k beta, so (u, w) = t (v_t,face - k beta) + n v_n.
  const double k = face_arm(s, node);
  Q(0, 2) = -k * t.x();
  Q(1, 2) = -k * t.y();
  return Q;
}

Eigen::VectorXd AxisymModel::to_local(const AxisymState& s, const Eigen::VectorXd& v) const {
  Eigen::VectorXd out = v;
  for (int i = 0; i < num_nodes(); ++i) {
    if (s.contact[i].tool < 0) continue;
    // Q^-1: the rotation's transpose, then the face term (frame()).
    const Eigen::Matrix3d Q = frame(s, i);
    const Eigen::Matrix2d R = Q.topLeftCorner<2, 2>();
    out.segment<2>(3 * i) = R.transpose() * v.segment<2>(3 * i);
    out(3 * i) += face_arm(s, i) * v(3 * i + 2);
  }
  return out;
}

Eigen::VectorXd AxisymModel::to_global(const AxisymState& s, const Eigen::VectorXd& v) const {
  Eigen::VectorXd out = v;
  rotate_to_global(s, &out);
  return out;
}

void AxisymModel::rotate_to_global(const AxisymState& s, Eigen::VectorXd* v) const {
  for (int i = 0; i < num_nodes(); ++i) {
    if (s.contact[i].tool < 0) continue;
    const Eigen::Vector3d local = v->segment<3>(3 * i);
    v->segment<3>(3 * i) = frame(s, i) * local;
  }
}

void AxisymModel::prescribed(const AxisymState& s, std::vector<char>* mask,
                             Eigen::VectorXd* values) const {
  mask->assign(num_dofs(), 0);
  *values = Eigen::VectorXd::Zero(num_dofs());
  auto fix = [&](int node, int dof, double value) {
    (*mask)[3 * node + dof] = 1;
    (*values)(3 * node + dof) = value;
  };
  for (int i = 0; i < num_nodes(); ++i) {
    const NodeContact& c = s.contact[i];
    if (c.tool >= 0) {
      const RigidTool& tool = tools_[c.tool];
      const Eigen::Vector2d t(c.normal.y(), -c.normal.x());
      fix(i, 1, tool.velocity().dot(c.normal));
      if (tool.sticking() && !c.slip_edge) fix(i, 0, tool.velocity().dot(t));
    }
  }
  // Axis of symmetry: no radial motion, no rotation (the contact normal there is vertical, so the
  // local tangential dof is the radial one).
  if (r0_.front() == 0.0) {
    fix(0, 0, 0.0);
    fix(0, 2, 0.0);
  }
  const int rim = num_nodes() - 1;
  switch (scene_.blank.edge) {
    case EdgeCondition::kClamped:
      fix(rim, 2, 0.0);
      [[fallthrough]];
    case EdgeCondition::kPinned:
      fix(rim, 0, 0.0);
      fix(rim, 1, 0.0);
      break;
    case EdgeCondition::kFree:
      break;
  }
}

void AxisymModel::update_holder(AxisymState* s) const {
  if (fixed_gap_holder()) {
    for (int i = 0; i < num_nodes(); ++i) {
      NodeContact& c = s->contact[i];
      if (!in_gap(c)) c.holder_force_N = 0.0;
    }
    return;
  }
  for (auto& c : s->contact) c.holder_force_N = 0.0;
  if (!has_holder_) return;
  double total_area = 0.0;
  std::vector<double> area(num_nodes(), 0.0);
  for (int i = 0; i < num_nodes(); ++i) {
    if (s->contact[i].tool != die_ || !s->contact[i].on_die_face) continue;
    double half = 0.0;
    if (i > 0) half += 0.5 * (s->x[i] - s->x[i - 1]).norm();
    if (i + 1 < num_nodes()) half += 0.5 * (s->x[i + 1] - s->x[i]).norm();
    area[i] = 2.0 * std::numbers::pi * s->x[i].x() * half;
    total_area += area[i];
  }
  if (total_area <= 0.0) return;
  for (int i = 0; i < num_nodes(); ++i) {
    s->contact[i].holder_force_N = holder_force_ * area[i] / total_area;
  }
}

void AxisymModel::update_sandwiched(AxisymState* s) const {
  for (int i = 0; i < num_nodes(); ++i) {
    NodeContact& c = s->contact[i];
    c.sandwiched =
        fixed_gap_holder() && in_gap(c) && node_thickness(*s, i) >= (1.0 - 1e-3) * holder_gap_;
  }
}

void AxisymModel::update_squeezed(AxisymState* s) const {
  // A node touching tool A is squeezed when its other surface comes within 1 % of the thickness
  // of a second tool B (neither a fixed-gap holder). The clearance through the node is the
  // distance from its mid-surface to A (h / 2) plus that to B.
  for (int i = 0; i < num_nodes(); ++i) {
    NodeContact& c = s->contact[i];
    const int before = c.squeeze_tool;
    c.squeeze_tool = -1;
    c.clearance_mm = 0.0;
    if (c.tool < 0 || sandwiched(c) || tools_[c.tool].kind() == ToolKind::kBlankHolder) {
      c.squeeze_force_N = 0.0;
      continue;
    }
    const double h = node_thickness(*s, i);
    for (std::size_t t = 0; t < tools_.size(); ++t) {
      const RigidTool& other = tools_[t];
      if (static_cast<int>(t) == c.tool || other.kind() == ToolKind::kBlankHolder) continue;
      if (other.gap(s->x[i], h) > 0.01 * h) continue;
      c.squeeze_tool = static_cast<int>(t);
      c.clearance_mm = 0.5 * h + other.closest(s->x[i]).distance;
      break;
    }
    if (c.squeeze_tool != before) c.squeeze_force_N = 0.0;
  }
}

std::vector<double> AxisymModel::squeeze_forces(const AxisymState& s,
                                                const AxisymSystem& sys) const {
  return nodal_pressure_forces(s, sys.squeeze_pressure,
                               [](const NodeContact& c) { return c.squeeze_tool >= 0; });
}

std::vector<double> AxisymModel::holder_forces_from_gap(const AxisymState& s,
                                                        const AxisymSystem& sys) const {
  return nodal_pressure_forces(s, sys.gap_pressure, [](const NodeContact& c) { return in_gap(c); });
}

std::vector<double> AxisymModel::nodal_pressure_forces(
    const AxisymState& s, const std::vector<double>& pressure,
    const std::function<bool(const NodeContact&)>& pressed) const {
  std::vector<double> f(num_nodes(), 0.0);
  if (pressure.empty()) return f;
  for (int e = 0; e < num_elements(); ++e) {
    const double p = pressure[e];
    if (p <= 0.0) continue;
    const Axisym2Geometry g = geometry(s, e);
    const double force = p * 2.0 * std::numbers::pi * g.mid_radius() * g.length();
    // Shared by the element's pressed nodes (one pressed node at the edge takes it all).
    const bool a = pressed(s.contact[e]), b = pressed(s.contact[e + 1]);
    f[e] += a ? (b ? 0.5 : 1.0) * force : 0.0;
    f[e + 1] += b ? (a ? 0.5 : 1.0) * force : 0.0;
  }
  return f;
}

namespace {

// The regularised Coulomb law (contact/coulomb.h) into the out-parameters of the assembly.
void regularised_coulomb(double limit, double vt_rel, double v0, double* force,
                         double* stiff_secant, double* stiff_tangent, double* potential) {
  const CoulombTerms t = vs::regularised_coulomb(limit, vt_rel, v0);
  *force = t.force;
  *stiff_secant = t.secant;
  *stiff_tangent = t.tangent;
  *potential = t.potential;
}

}  // namespace

void AxisymModel::friction_terms(const AxisymState& s, int node, double vt_rel, double normal_N,
                                 double* force, double* stiff_secant, double* stiff_tangent,
                                 double* potential) const {
  const NodeContact& c = s.contact[node];
  const RigidTool& tool = tools_[c.tool];
  // Coulomb limit: tool coefficient times the normal reaction, plus the holder's share.
  double limit = tool.friction() * std::max(normal_N, 0.0);
  if (c.on_die_face) limit += holder_friction_ * c.holder_force_N;
  if (c.on_holder_face) limit += tools_[die_].friction() * c.holder_force_N;
  // Squeezed: the second tool's pressure presses the node against this tool too.
  if (c.squeeze_tool >= 0) limit += tool.friction() * c.squeeze_force_N;
  // A flange node sandwiched in a fixed gap is never released: a tensile reaction on the face
  // it touches is the opposite face pushing, with that face's friction.
  if (sandwiched(c)) {
    const double other = c.on_die_face ? holder_friction_ : tools_[die_].friction();
    limit += other * std::max(-c.normal_force_N, 0.0);
  }
  regularised_coulomb(limit, vt_rel, friction_velocity_, force, stiff_secant, stiff_tangent,
                      potential);
}

bool AxisymModel::squeeze_friction_terms(const AxisymState& s, int node, double vt_local,
                                         double* force, double* stiff_secant, double* stiff_tangent,
                                         double* potential) const {
  const NodeContact& c = s.contact[node];
  if (c.squeeze_tool < 0 || !(c.squeeze_force_N > 0.0)) return false;
  const RigidTool& other = tools_[c.squeeze_tool];
  if (other.sticking()) return false;
  const Eigen::Vector2d t(c.normal.y(), -c.normal.x());
  regularised_coulomb(other.friction() * c.squeeze_force_N, vt_local - other.velocity().dot(t),
                      friction_velocity_, force, stiff_secant, stiff_tangent, potential);
  return true;
}

void AxisymModel::evaluate(const AxisymState& s, const Eigen::VectorXd& v_local, StiffnessKind kind,
                           AxisymSystem* out, double tangent_weight) const {
  evaluate_elements(s, v_local, kind, out, nullptr, tangent_weight);
  assemble(s, v_local, kind, out, tangent_weight);
}

void AxisymModel::evaluate_elements(const AxisymState& s, const Eigen::VectorXd& v_local,
                                    StiffnessKind kind, AxisymSystem* out,
                                    const std::vector<double>* flow_directions,
                                    double weight) const {
  const int nn = num_nodes();
  Eigen::VectorXd& v = out->v_global;
  v = v_local;
  rotate_to_global(s, &v);
  const bool want_k = kind != StiffnessKind::kNone;
  const bool tangent = kind == StiffnessKind::kTangent;
  const bool split = tangent && weight < 0.0;
  if (want_k) {
    if (out->K_elements.blocks() != nn) out->K_elements.resize(nn);
    out->K_elements.set_zero();
  }
  if (split) {
    if (out->K_tangent_part.blocks() != nn) out->K_tangent_part.resize(nn);
    out->K_tangent_part.set_zero();
  }
  out->element_force.setZero(num_dofs());
  out->element_potential = 0.0;
  out->element_kind = kind;
  out->element_weight = tangent && !split ? weight : -1.0;

  Axisym2Output& eo = out->element;
  if (out->keep_element_states) {
    out->point_rates.resize(num_elements());
    out->resultants.resize(num_elements());
  }
  auto add_blocks = [](const Mat6& k, int e, BlockTridiag* K) {
    K->diag(e) += k.block<3, 3>(0, 0);
    K->diag(e + 1) += k.block<3, 3>(3, 3);
    K->lower(e) += k.block<3, 3>(3, 0);
  };
  const std::size_t np = rule_.zeta.size();
  const bool dual = tangent && flow_directions && !flow_directions->empty();
  if (tangent) {
    out->directions.resize(2 * np * num_elements());
    out->cutoff_rates.resize(np * num_elements());
    assert(!dual || flow_directions->size() == out->directions.size());
  }
  for (int e = 0; e < num_elements(); ++e) {
    // numerics.transverse_shear_scale: on the shear penalty only (not on the fixed-gap holder's
    // penalty, which borrows the same viscosity as its scale).
    Axisym2Section sec{s.thickness[e], &sigma_y_[e], &hardening_viscosity_[e],
                       scene_.numerics.transverse_shear_scale * shear_viscosity_[e]};
    if (dual) sec.flow_direction = flow_directions->data() + 2 * np * e;
    if (!face_pressure_.empty()) sec.face_pressure = face_pressure_[e];
    const Vec6 d = v.segment<6>(3 * e);
    // Split: weight 0, eo.stiffness is the secant matrix and eo.tangent_part the rest.
    axisym2_evaluate(geometry(s, e), sec, rule_, law_, d, kind, &eo, split ? 0.0 : weight, split);
    out->element_force.segment<6>(3 * e) += eo.force;
    out->element_potential += eo.potential;
    if (out->keep_element_states) {
      out->point_rates[e] = eo.point_rate;
      out->resultants[e] = eo.stress_resultant;
    }
    if (want_k) add_blocks(eo.stiffness, e, &out->K_elements);
    if (split) add_blocks(eo.tangent_part, e, &out->K_tangent_part);
    if (tangent) {
      std::copy(eo.point_direction.begin(), eo.point_direction.end(),
                out->directions.begin() + 2 * np * e);
      std::copy(eo.point_cutoff_rate.begin(), eo.point_cutoff_rate.end(),
                out->cutoff_rates.begin() + np * e);
    }
  }
  if (fixed_gap_holder()) add_gap_holder(s, v, want_k, out);
  add_squeeze(s, v, want_k, out);
  if (coupling_) add_geometry_coupling(s, v, want_k, out);
}

void AxisymModel::add_geometry_coupling(const AxisymState& s, const Eigen::VectorXd& v, bool want_k,
                                        AxisymSystem* out) const {
  const GeometryCoupling& c = *coupling_;
  assert(static_cast<int>(c.resultants.size()) == num_elements());
  for (int e = 0; e < num_elements(); ++e) {
    const Mat6 k = c.scale_s *
                   axisym2_stress_stiffness(geometry(s, e), c.resultants[e](0), c.resultants[e](1));
    const Vec6 dv = v.segment<6>(3 * e) - c.v_ref.segment<6>(3 * e);
    const Vec6 f = k * dv;
    out->element_force.segment<6>(3 * e) += f;
    out->element_potential += 0.5 * dv.dot(f);
    if (want_k) {
      out->K_elements.diag(e) += k.block<3, 3>(0, 0);
      out->K_elements.diag(e + 1) += k.block<3, 3>(3, 3);
      out->K_elements.lower(e) += k.block<3, 3>(3, 0);
    }
  }
}

double AxisymModel::potential(const AxisymState& s, const Eigen::VectorXd& v_local,
                              const AxisymSystem& sums) const {
  // As assemble(): element potential, minus the work of the holder forces (f_ext . v), plus the
  // friction potential of the sliding contact nodes.
  double p = sums.element_potential;
  for (int i = 0; i < num_nodes(); ++i) p -= holder_load(s.contact[i]) * sums.v_global(3 * i + 1);
  for (int i = 0; i < num_nodes(); ++i) {
    const NodeContact& c = s.contact[i];
    if (c.tool < 0 || tools_[c.tool].sticking()) continue;
    const Eigen::Vector2d t(c.normal.y(), -c.normal.x());
    const double vt_rel = v_local(3 * i) - tools_[c.tool].velocity().dot(t);
    double f, ks, kt, phi;
    friction_terms(s, i, vt_rel, c.normal_force_N, &f, &ks, &kt, &phi);
    p += phi;
  }
  for (int i = 0; i < num_nodes(); ++i) {
    double f, ks, kt, phi;
    if (squeeze_friction_terms(s, i, v_local(3 * i), &f, &ks, &kt, &phi)) p += phi;
  }
  return p;
}

void AxisymModel::point_rate_increments(const AxisymState& s, const Eigen::VectorXd& dv_local,
                                        std::vector<double>* dd) const {
  const Eigen::VectorXd dv = to_global(s, dv_local);
  const std::size_t np = rule_.zeta.size();
  dd->resize(2 * np * num_elements());
  for (int e = 0; e < num_elements(); ++e) {
    const Vec5 de = axisym2_strain_rates(geometry(s, e), dv.segment<6>(3 * e));
    for (std::size_t k = 0; k < np; ++k) {
      const double z = rule_.zeta[k] * s.thickness[e];
      (*dd)[2 * (np * e + k)] = de(0) + z * de(2);
      (*dd)[2 * (np * e + k) + 1] = de(1) + z * de(3);
    }
  }
}

void AxisymModel::assemble(const AxisymState& s, const Eigen::VectorXd& v_local, StiffnessKind kind,
                           AxisymSystem* out, double tangent_weight) const {
  const int nn = num_nodes();
  const Eigen::VectorXd& v = out->v_global;
  const bool want_k = kind != StiffnessKind::kNone;
  // Blend the split tangent part in, or use sums made at this weight (or the secant's).
  const bool split = out->element_kind == StiffnessKind::kTangent && out->element_weight < 0.0;
  const bool blend = kind == StiffnessKind::kTangent && split;
  assert(!want_k ||
         (kind == StiffnessKind::kSecant ? out->element_kind == kind || split
                                         : split || out->element_weight == tangent_weight));
  if (want_k) {
    if (out->K.blocks() != nn) out->K.resize(nn);
    out->K.set_symmetric();
    out->K.clear_fixed();
    for (int i = 0; i < nn; ++i) {
      out->K.diag(i) = out->K_elements.diag(i);
      if (blend) out->K.diag(i) += tangent_weight * out->K_tangent_part.diag(i);
      if (i + 1 == nn) continue;
      out->K.lower(i) = out->K_elements.lower(i);
      if (blend) out->K.lower(i) += tangent_weight * out->K_tangent_part.lower(i);
    }
  }
  out->external_force.setZero(num_dofs());
  out->potential = out->element_potential;
  for (int i = 0; i < nn; ++i) {
    out->external_force(3 * i + 1) += holder_load(s.contact[i]);
    // f_ext . v node by node, in the order of potential() (the same rounding).
    out->potential -= holder_load(s.contact[i]) * v(3 * i + 1);
  }

  // Residual and stiffness in the nodal frames.
  Eigen::VectorXd& r = out->residual;
  r = out->element_force - out->external_force;
  for (int i = 0; i < nn; ++i) {
    if (s.contact[i].tool < 0) continue;
    const Eigen::Matrix3d Q = frame(s, i);
    const Eigen::Vector3d ri = r.segment<3>(3 * i);
    r.segment<3>(3 * i) = Q.transpose() * ri;
    if (want_k) {
      const Eigen::Matrix3d Kii = out->K.diag(i);
      out->K.diag(i) = Q.transpose() * Kii * Q;
      if (i > 0) {
        const Eigen::Matrix3d C = out->K.lower(i - 1);
        out->K.lower(i - 1) = Q.transpose() * C;
      }
      if (i + 1 < nn) {
        const Eigen::Matrix3d C = out->K.lower(i);
        out->K.lower(i) = C * Q;
      }
    }
  }
  // Regularised Coulomb friction on sliding contact nodes.
  for (int i = 0; i < nn; ++i) {
    const NodeContact& c = s.contact[i];
    if (c.tool < 0 || tools_[c.tool].sticking()) continue;
    const Eigen::Vector2d t(c.normal.y(), -c.normal.x());
    const double vt_rel = v_local(3 * i) - tools_[c.tool].velocity().dot(t);
    // Consistent friction: the limit follows the current normal reaction N(v) (the local normal
    // component of the residual before friction), and Newton's matrix gets its derivative,
    // d f / d v = mu psi(v_t) d N / d v with psi = f / limit: the normal row of node i, times
    // mu psi, added to its tangential row (non-symmetric). The potential stays the lagged one (the
    // step problem sets the lag to N at every evaluated iterate, so the line-search merit is the
    // friction potential with N frozen at the iterate, whose gradient there is this residual).
    const bool consistent = consistent_friction(c);
    const double N_now = r(3 * i + 1);
    double f, ks, kt, phi;
    friction_terms(s, i, vt_rel, consistent ? N_now : c.normal_force_N, &f, &ks, &kt, &phi);
    r(3 * i) += f;
    out->potential += phi;
    if (want_k) {
      out->K.diag(i)(0, 0) +=
          kind == StiffnessKind::kTangent ? ks + tangent_weight * (kt - ks) : ks;
    }
    if (want_k && consistent && kind == StiffnessKind::kTangent && N_now > 0.0) {
      const double mu = tools_[c.tool].friction();
      const double c_n = tangent_weight * mu * kTwoOverPi * std::atan(vt_rel / friction_velocity_);
      out->K.unsymmetric();
      Eigen::Matrix3d& D = out->K.diag(i);
      D.row(0) += c_n * D.row(1);
      if (i > 0) out->K.lower(i - 1).row(0) += c_n * out->K.lower(i - 1).row(1);
      if (i + 1 < nn) out->K.upper(i).row(0) += c_n * out->K.upper(i).row(1);
    }
  }
  // Squeezed nodes: friction of the second tool, from its lagged pressure force, on the slip
  // relative to that tool along the node's tangent (a sticking second tool is taken as
  // frictionless: a node stuck to both could not move at all). Kept per node for the punch force.
  out->squeeze_friction.assign(nn, 0.0);
  for (int i = 0; i < nn; ++i) {
    double f, ks, kt, phi;
    if (!squeeze_friction_terms(s, i, v_local(3 * i), &f, &ks, &kt, &phi)) continue;
    r(3 * i) += f;
    out->potential += phi;
    out->squeeze_friction[i] = f;
    if (want_k) {
      out->K.diag(i)(0, 0) +=
          kind == StiffnessKind::kTangent ? ks + tangent_weight * (kt - ks) : ks;
    }
  }
  prescribed(s, &out->fixed, &out->fixed_values);
  for (int k = 0; k < num_dofs(); ++k) {
    if (!out->fixed[k]) continue;
    r(k) = 0.0;
    if (want_k) out->K.fix_dof(k / 3, k % 3);
  }
}

void AxisymModel::add_gap_holder(const AxisymState& s, const Eigen::VectorXd& v, bool want_k,
                                 AxisymSystem* out) const {
  // Fixed-gap blank holder on a flange element (both nodes on the die face). The plane-stress
  // shell cannot carry a through-thickness stress, but a holder pressure p acts on the flow like
  // a hydrostatic shift: both in-plane stresses change by -p, i.e. p does virtual power
  // -p (d_s + d_t) per unit volume. The holder stops the thickness h (dh/dt = -(d_s + d_t) h) at
  // the gap g: over the step dt, h_next = h exp(-(d_s + d_t) dt) <= g needs
  //   d_s + d_t >= c = min(ln(h / g), 0) / dt.
  // A penalty on the violation, potential k V (c - d_s - d_t)_+^2 / 2 with k = 1e3 times the
  // element's reference viscosity, gives p = k (c - d_s - d_t)_+ (MPa) and keeps the constraint
  // to ~1e-3 of the flow rate. V is the element volume.
  out->gap_pressure.assign(num_elements(), 0.0);
  if (!(step_dt_ > 0.0)) return;
  for (int e = 0; e < num_elements(); ++e) {
    // Elements with at least one node in the gap: the element that straddles the holder's inner
    // edge stays constrained until it has left completely (left free, it is squeezed between a
    // node held by friction on both faces and a node running over the die shoulder, and folds:
    // measured at gaps 1.1-1.15 mm).
    if (!in_gap(s.contact[e]) && !in_gap(s.contact[e + 1])) continue;
    // No correction of an overshoot left by an earlier step (the penalty lets the thickness pass
    // the gap by ~1e-3 of a step's strain): demanding it back within one step makes the required
    // pressure grow without bound as cut-backs shrink dt.
    out->gap_pressure[e] = area_rate_penalty(
        s, v, e, std::min(0.0, std::log(s.thickness[e] / holder_gap_)), want_k, out);
  }
}

double AxisymModel::area_rate_penalty(const AxisymState& s, const Eigen::VectorXd& v, int e,
                                      double log_ratio, bool want_k, AxisymSystem* out) const {
  // d_s + d_t >= c = log_ratio / dt by the penalty k V (c - d_s - d_t)_+^2 / 2, k = 1e3 times the
  // element's reference viscosity: pressure p = k (c - d_s - d_t)_+ [MPa].
  constexpr double kPenalty = 1e3;
  const Axisym2Geometry g = geometry(s, e);
  const Mat56 B = axisym2_B(g);
  const Vec6 bv = (B.row(0) + B.row(1)).transpose();
  const double violation = log_ratio / step_dt_ - bv.dot(v.segment<6>(3 * e));
  if (violation <= 0.0) return 0.0;
  const double k = kPenalty * shear_viscosity_[e];
  const double volume = 2.0 * std::numbers::pi * g.mid_radius() * g.length() * s.thickness[e];
  const double p = k * violation;
  out->element_force.segment<6>(3 * e) -= p * volume * bv;
  out->element_potential += 0.5 * k * volume * violation * violation;
  if (want_k) {
    // Linear in v: the same matrix in the secant and the tangent (part of K_elements).
    const Mat6 kb = k * volume * bv * bv.transpose();
    out->K_elements.diag(e) += kb.block<3, 3>(0, 0);
    out->K_elements.diag(e + 1) += kb.block<3, 3>(3, 3);
    out->K_elements.lower(e) += kb.block<3, 3>(3, 0);
  }
  return p;
}

Eigen::Vector2d AxisymModel::node_force(const AxisymSystem& sys, int node) const {
  return (sys.element_force - sys.external_force).segment<2>(3 * node);
}

void AxisymModel::add_squeeze(const AxisymState& s, const Eigen::VectorXd& v, bool want_k,
                              AxisymSystem* out) const {
  // Squeeze (ironing) of an element with a node between two tools: the same hydrostatic penalty
  // as the fixed-gap holder (add_gap_holder), on the thickness at the end of the step,
  //   h exp(-(d_s + d_t) dt) <= g,  i.e.  d_s + d_t >= c = ln(h / g) / dt,
  // with g the smallest clearance of its squeezed nodes. Unlike the holder, an overshoot is
  // corrected (c > 0 when h > g): the clearance narrows as the sheet runs into the gap (over a
  // die shoulder), so the thickness must follow it, which is ironing.
  out->squeeze_pressure.assign(num_elements(), 0.0);
  if (!(step_dt_ > 0.0)) return;
  for (int e = 0; e < num_elements(); ++e) {
    const NodeContact& a = s.contact[e];
    const NodeContact& b = s.contact[e + 1];
    if (a.squeeze_tool < 0 && b.squeeze_tool < 0) continue;
    double gap = std::numeric_limits<double>::infinity();
    if (a.squeeze_tool >= 0) gap = std::min(gap, a.clearance_mm);
    if (b.squeeze_tool >= 0) gap = std::min(gap, b.clearance_mm);
    if (!(gap > 0.0)) continue;
    // At most the strain cap of a step (numerics.max_strain_increment) of thinning per step: a
    // thick rim entering the gap is ironed over a few steps instead of at an unbounded rate
    // (measured: a 0.27 mm overshoot demanded in one 0.027 mm step spiked the punch force and
    // released half the contact set). And over no less than a regular step's time: a node that
    // becomes squeezed at a contact event, in a step 1 / 10 of the grid's, had its 0.9 % overshoot
    // demanded at ~100x the flow rate; the penalty pressure then carried the punch load, pulled
    // the sheet off the punch nose and released seven nodes at once (measured: ESAFORM cup, gap
    // 1.04 mm, Swift UA, friction 0.05, stopped at 37.02 mm).
    // The log target of model/ironing.h, without its tolerance (measured there).
    const double slow_down = step_dt_ / std::max(step_dt_, squeeze_correction_s_);
    const double target = ironing_log_target(s.thickness[e], gap,
                                             scene_.numerics.max_strain_increment, slow_down, 0.0);
    out->squeeze_pressure[e] = area_rate_penalty(s, v, e, target, want_k, out);
  }
}

}  // namespace vs
