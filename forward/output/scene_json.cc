#include "output/scene_json.h"

namespace vs {
namespace {

using Json = nlohmann::ordered_json;

const char* name(Geometry g) {
  switch (g) {
    case Geometry::kAxisymmetric:
      return "axisymmetric";
    case Geometry::kShell3d:
      return "shell3d";
  }
  return "unknown";
}

const char* name(EdgeCondition e) {
  switch (e) {
    case EdgeCondition::kPinned:
      return "pinned";
    case EdgeCondition::kClamped:
      return "clamped";
    case EdgeCondition::kFree:
      return "free";
  }
  return "unknown";
}

const char* name(BlankShape shape) { return shape == BlankShape::kCircle ? "circle" : "square"; }

const char* name(BlankSymmetry symmetry) {
  return symmetry == BlankSymmetry::kQuarter ? "quarter" : "full";
}

const char* name(HardeningLaw law) {
  switch (law) {
    case HardeningLaw::kSwift:
      return "swift";
    case HardeningLaw::kHollomon:
      return "hollomon";
    case HardeningLaw::kVoce:
      return "voce";
    case HardeningLaw::kTable:
      return "table";
  }
  return "unknown";
}

const char* name(FormingLimitModel model) {
  switch (model) {
    case FormingLimitModel::kKeelerBrazier:
      return "keeler-brazier";
    case FormingLimitModel::kTable:
      return "table";
    case FormingLimitModel::kNone:
      return "none";
  }
  return "unknown";
}

const char* name(RateLaw law) {
  switch (law) {
    case RateLaw::kNone:
      return "none";
    case RateLaw::kPerzyna:
      return "perzyna";
    case RateLaw::kPower:
      return "power";
  }
  return "unknown";
}

const char* name(ElasticLaw law) {
  switch (law) {
    case ElasticLaw::kNone:
      return "none";
    case ElasticLaw::kIsotropic:
      return "isotropic";
  }
  return "unknown";
}

const char* name(AnisotropyModel m) {
  switch (m) {
    case AnisotropyModel::kNormal:
      return "normal";
    case AnisotropyModel::kHill48R:
      return "hill48_r";
    case AnisotropyModel::kHill48Stress:
      return "hill48_stress";
    case AnisotropyModel::kYld2000:
      return "yld2000";
  }
  return "?";
}

const char* name(ToolKind kind) {
  switch (kind) {
    case ToolKind::kHemisphericalPunch:
      return "hemispherical_punch";
    case ToolKind::kFlatPunch:
      return "flat_punch";
    case ToolKind::kDie:
      return "die";
    case ToolKind::kBlankHolder:
      return "blank_holder";
  }
  return "unknown";
}

const char* name(SolverKind kind) {
  switch (kind) {
    case SolverKind::kNewton:
      return "newton";
    case SolverKind::kPicard:
      return "picard";
  }
  return "unknown";
}

const char* name(TimeIntegration t) {
  switch (t) {
    case TimeIntegration::kHeun:
      return "heun";
    case TimeIntegration::kEuler:
      return "euler";
    case TimeIntegration::kImplicit:
      return "implicit";
  }
  return "heun";
}

const char* name(NormalStress n) {
  switch (n) {
    case NormalStress::kNone:
      return "none";
    case NormalStress::kContact:
      return "contact";
  }
  return "none";
}

const char* name(FrictionSurface f) {
  switch (f) {
    case FrictionSurface::kMid:
      return "mid";
    case FrictionSurface::kFace:
      return "face";
  }
  return "mid";
}

Json tool_json(const ToolSpec& t) {
  Json j;
  j["name"] = t.name;
  j["kind"] = name(t.kind);
  j["radius_mm"] = t.radius_mm;
  j["profile_radius_mm"] = t.profile_radius_mm;
  if (t.sticking()) {
    j["friction"] = "sticking";
  } else {
    j["friction"] = t.friction;
  }
  j["force_N"] = t.force_N;
  return j;
}

}  // namespace

nlohmann::ordered_json scene_to_json(const Scene& s) {
  Json j;
  j["source"] = s.source;
  j["title"] = s.title;
  j["geometry"] = name(s.geometry);

  const BlankSpec& b = s.blank;
  j["blank"] = {{"radius_mm", b.radius_mm},
                {"thickness_mm", b.thickness_mm},
                {"elements", b.elements},
                {"grading", b.grading},
                {"edge", name(b.edge)}};
  if (s.geometry == Geometry::kShell3d) {
    j["blank"]["shape"] = name(b.shape);
    j["blank"]["symmetry"] = name(b.symmetry);
    j["blank"]["divisions"] = b.divisions;
    if (b.shape == BlankShape::kCircle) j["blank"]["radial_divisions"] = b.ring_divisions();
  }

  const HardeningSpec& h = s.material.hardening;
  const RateSpec& r = s.material.rate;
  j["material"] = {{"hardening",
                    {{"law", name(h.law)},
                     {"K_MPa", h.K_MPa},
                     {"eps0", h.eps0},
                     {"n", h.n},
                     {"sigma0_MPa", h.sigma0_MPa},
                     {"Q_MPa", h.Q_MPa},
                     {"b", h.b},
                     {"table_strain", h.table_strain},
                     {"table_stress_MPa", h.table_stress_MPa},
                     {"table_scale", h.table_scale}}},
                   {"rate",
                    {{"law", name(r.law)},
                     {"gamma_per_s", r.gamma_per_s},
                     {"exponent", r.exponent},
                     {"m", r.m},
                     {"reference_rate_per_s", r.reference_rate_per_s}}},
                   {"r_value", s.material.r_value}};
  const AnisotropySpec& an = s.material.anisotropy;
  j["material"]["anisotropy"] = {{"model", name(an.model)},
                                 {"rolling_direction_deg", an.rolling_direction_deg},
                                 {"r0", an.r0},
                                 {"r45", an.r45},
                                 {"r90", an.r90},
                                 {"sigma45_ratio", an.sigma45_ratio},
                                 {"sigma90_ratio", an.sigma90_ratio},
                                 {"sigma_b_ratio", an.sigma_b_ratio},
                                 {"r_b", an.r_b},
                                 {"exponent", an.exponent}};

  const ElasticSpec& el = s.material.elastic;
  j["material"]["elastic"] = {{"law", name(el.law)},
                              {"E_MPa", el.E_MPa},
                              {"nu", el.nu},
                              {"start", el.start},
                              {"strains", el.strains}};

  Json tools = Json::array();
  for (const ToolSpec& t : s.tools) tools.push_back(tool_json(t));
  j["tools"] = tools;

  const ProcessSpec& p = s.process;
  j["process"] = {{"punch_travel_mm", p.punch_travel_mm},
                  {"punch_speed_mm_per_s", p.punch_speed_mm_per_s},
                  {"output_travels_mm", p.output_travels_mm}};

  const NumericsSpec& n = s.numerics;
  j["numerics"] = {{"thickness_points", n.thickness_points},
                   {"solver", name(n.solver)},
                   {"time_integration", name(n.time_integration)},
                   {"implicit_theta", n.implicit_theta},
                   {"implicit_solves", n.implicit_solves},
                   {"contact_events", n.contact_events},
                   {"tolerance", n.tolerance},
                   {"max_iterations", n.max_iterations},
                   {"step_fraction", n.step_fraction},
                   {"max_travel_increment_mm", n.max_travel_increment_mm},
                   {"max_travel_increment_per_length", n.max_travel_increment_per_length},
                   {"start_refinement", n.start_refinement},
                   {"max_strain_increment", n.max_strain_increment},
                   {"strain_rate_cutoff", n.strain_rate_cutoff},
                   {"friction_regularisation", n.friction_regularisation},
                   {"max_cutbacks", n.max_cutbacks},
                   {"normal_stress", name(n.normal_stress)},
                   {"friction_surface", name(n.friction_surface)}};

  const FormingLimitSpec& fl = s.forming_limit;
  j["forming_limit"] = {{"model", name(fl.model)},
                        {"table_minor", fl.table_minor},
                        {"table_major", fl.table_major},
                        {"safety_margin", fl.safety_margin}};

  j["output"] = {{"directory", s.output.directory},
                 {"plots", s.output.plots},
                 {"history", s.output.history},
                 {"measured_cup_profile", s.output.measured_cup_profile}};
  return j;
}

}  // namespace vs
