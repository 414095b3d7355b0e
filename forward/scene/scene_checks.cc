#include "scene/scene_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace vs {

namespace {

bool is_punch(const ToolSpec& t) {
  return t.kind == ToolKind::kHemisphericalPunch || t.kind == ToolKind::kFlatPunch;
}

std::string tool_address(const ToolSpec& t, std::string_view key) {
  return fmt::format("tool.{}.{}", t.name, key);
}

// The single tool of each role, after checking there is at most one (exactly one punch).
struct ToolRoles {
  const ToolSpec* punch = nullptr;
  const ToolSpec* die = nullptr;
  const ToolSpec* holder = nullptr;
};

void assign_role(const ToolSpec& tool, const ToolSpec*& slot, std::string_view role,
                 const SceneSourceMap& where) {
  if (slot != nullptr) {
    where.fail(tool_address(tool, "kind"),
               fmt::format("tool '{}' is a second {} (tool '{}' is one already); at most one "
                           "{} is allowed",
                           tool.name, role, slot->name, role));
  }
  slot = &tool;
}

ToolRoles find_roles(const Scene& scene, const SceneSourceMap& where) {
  ToolRoles roles;
  for (const ToolSpec& tool : scene.tools) {
    if (is_punch(tool)) assign_role(tool, roles.punch, "punch", where);
    if (tool.kind == ToolKind::kDie) assign_role(tool, roles.die, "die", where);
    if (tool.kind == ToolKind::kBlankHolder) assign_role(tool, roles.holder, "blank_holder", where);
  }
  if (roles.punch == nullptr) {
    where.fail("tool",
               "the scene has no punch: add a [[tool]] with kind = \"hemispherical_punch\" or "
               "\"flat_punch\"");
  }
  if (roles.holder != nullptr && roles.die == nullptr) {
    where.fail(tool_address(*roles.holder, "kind"),
               fmt::format("blank holder '{}' needs a die to press the flange against",
                           roles.holder->name));
  }
  return roles;
}

void check_tools(const Scene& scene, const ToolRoles& roles, const SceneSourceMap& where) {
  const ToolSpec& punch = *roles.punch;
  const BlankSpec& blank = scene.blank;
  if (punch.kind == ToolKind::kFlatPunch && !(punch.profile_radius_mm < punch.radius_mm)) {
    where.fail(tool_address(punch, "profile_radius_mm"),
               fmt::format("{} = {} must be < {} = {} mm (flat punch nose radius)",
                           tool_address(punch, "profile_radius_mm"), punch.profile_radius_mm,
                           tool_address(punch, "radius_mm"), punch.radius_mm));
  }
  if (!(blank.radius_mm > punch.radius_mm)) {
    where.fail("blank.radius_mm",
               fmt::format("blank.radius_mm = {} must be > punch radius {} = "
                           "{} mm",
                           blank.radius_mm, tool_address(punch, "radius_mm"), punch.radius_mm));
  }
  if (roles.holder != nullptr) {
    const ToolSpec& h = *roles.holder;
    if ((h.force_N > 0.0) == (h.gap_mm > 0.0)) {
      where.fail(tool_address(h, "kind"),
                 fmt::format("blank holder '{}' needs exactly one of force_N (prescribed force) "
                             "and gap_mm (fixed gap)",
                             h.name));
    }
    if (h.gap_mm > 0.0 && h.gap_mm < blank.thickness_mm) {
      where.fail(tool_address(h, "gap_mm"),
                 fmt::format("{} = {} must be >= blank.thickness_mm = {} mm (the holder may not "
                             "crush the blank at the start)",
                             tool_address(h, "gap_mm"), h.gap_mm, blank.thickness_mm));
    }
  }
  if (roles.die == nullptr) return;
  const ToolSpec& die = *roles.die;
  const double clearance_limit = punch.radius_mm + blank.thickness_mm;
  if (!(die.radius_mm > clearance_limit)) {
    where.fail(tool_address(die, "radius_mm"),
               fmt::format("{} = {} leaves no clearance: it must be > punch radius {} + blank "
                           "thickness {} = {} mm",
                           tool_address(die, "radius_mm"), die.radius_mm, punch.radius_mm,
                           blank.thickness_mm, clearance_limit));
  }
  if (!(blank.radius_mm > die.radius_mm)) {
    where.fail("blank.radius_mm",
               fmt::format("blank.radius_mm = {} must be > die opening {} = {} mm (the blank "
                           "must reach the die)",
                           blank.radius_mm, tool_address(die, "radius_mm"), die.radius_mm));
  }
}

void check_blank(const Scene& scene, const ToolRoles& roles, const SceneSourceMap& where) {
  const BlankSpec& blank = scene.blank;
  if (blank.edge == EdgeCondition::kFree && roles.die == nullptr) {
    where.fail("blank.edge",
               "blank.edge = \"free\" needs a die: without one nothing holds the sheet");
  }
  if (scene.geometry == Geometry::kShell3d && blank.shape != BlankShape::kCircle &&
      blank.ring_divisions() != blank.divisions) {
    where.fail("blank.radial_divisions",
               fmt::format("blank.radial_divisions = {} applies to a circular blank (the ring "
                           "around its central square); a square blank has divisions only",
                           blank.radial_divisions));
  }
  if (!(blank.thickness_mm < blank.radius_mm / 5.0)) {
    where.fail("blank.thickness_mm",
               fmt::format("blank.thickness_mm = {} must be < blank.radius_mm / 5 = {} mm (thin "
                           "shell)",
                           blank.thickness_mm, blank.radius_mm / 5.0));
  }
}

void check_material(const Scene& scene, const SceneSourceMap& where) {
  const AnisotropySpec& a = scene.material.anisotropy;
  if (!a.planar() || scene.blank.symmetry != BlankSymmetry::kQuarter) return;
  // The quarter model mirrors the sheet about x = 0 and y = 0: valid for an orthotropic sheet
  // only when those planes are material symmetry planes (RD along x or y).
  const double turns = a.rolling_direction_deg / 90.0;
  if (std::abs(turns - std::round(turns)) > 1e-12) {
    where.fail("material.anisotropy.rolling_direction_deg",
               fmt::format("material.anisotropy.rolling_direction_deg = {}: a quarter blank "
                           "(blank.symmetry = \"quarter\") mirrors the sheet about x = 0 and "
                           "y = 0, which needs RD along x or y (0, 90, 180 or -90 deg); use "
                           "blank.symmetry = \"full\" for another angle",
                           a.rolling_direction_deg));
  }
}

void check_process(const Scene& scene, const SceneSourceMap& where) {
  const ProcessSpec& p = scene.process;
  for (std::size_t i = 0; i < p.output_travels_mm.size(); ++i) {
    const std::string address = fmt::format("process.output_travels_mm[{}]", i);
    const double travel = p.output_travels_mm[i];
    if (i > 0 && !(travel > p.output_travels_mm[i - 1])) {
      where.fail(address, fmt::format("{} = {} must be > the previous output travel {} mm "
                                      "(strictly increasing)",
                                      address, travel, p.output_travels_mm[i - 1]));
    }
    if (travel > p.punch_travel_mm) {
      where.fail(address, fmt::format("{} = {} exceeds process.punch_travel_mm = {} mm", address,
                                      travel, p.punch_travel_mm));
    }
  }
}

// Shortest initial element length (axisymmetric: geometric grading, last/first = grading) or an
// estimate of the 9-node element size sqrt(area) (shell3d: the quarter circle's blocks are
// about radius / (2 divisions) across, its ring radius / (2 radial_divisions) radially; the
// quarter square's radius / divisions).
double shortest_element_mm(const Scene& scene) {
  const BlankSpec& b = scene.blank;
  if (scene.geometry == Geometry::kShell3d) {
    if (b.shape != BlankShape::kCircle) return b.radius_mm / b.divisions;
    const double n = b.divisions, m = std::max(b.divisions, b.ring_divisions());
    return b.radius_mm / (2.0 * std::sqrt(n * m));
  }
  const int n = b.elements;
  if (b.grading == 1.0 || n < 2) return b.radius_mm / n;
  const double q = std::pow(b.grading, 1.0 / (n - 1));
  const double first = b.radius_mm * (q - 1.0) / (std::pow(q, n) - 1.0);
  return std::min(first, first * b.grading);
}

int element_count(const Scene& scene) {
  const BlankSpec& b = scene.blank;
  if (scene.geometry == Geometry::kAxisymmetric) return b.elements;
  const int n = b.divisions;
  const int quarter = b.shape == BlankShape::kCircle ? n * n + 2 * n * b.ring_divisions() : n * n;
  return b.symmetry == BlankSymmetry::kFull ? 4 * quarter : quarter;
}

// Steps end on a travel grid no coarser than the smaller travel cap, so a run takes at least
// travel / cap steps, each costing time (and, with output.history, memory) in proportion to the
// element count. Scenes beyond what a 2-core, 24 GB machine finishes in hours are errors.
void check_run_size(const Scene& scene, const SceneSourceMap& where) {
  const NumericsSpec& nu = scene.numerics;
  const double shortest = shortest_element_mm(scene);
  const double per_length_cap = nu.max_travel_increment_per_length * shortest;
  const double cap = std::min(nu.max_travel_increment_mm, per_length_cap);
  const double steps = scene.process.punch_travel_mm / cap;
  const std::string cap_key = per_length_cap < nu.max_travel_increment_mm
                                  ? "numerics.max_travel_increment_per_length"
                                  : "numerics.max_travel_increment_mm";
  const std::string cap_text =
      per_length_cap < nu.max_travel_increment_mm
          ? fmt::format("{} = {} x the shortest element ({:.3g} mm) = {:.3g} mm", cap_key,
                        nu.max_travel_increment_per_length, shortest, cap)
          : fmt::format("{} = {} mm", cap_key, cap);
  if (steps > kMaxRunSteps) {
    where.fail(
        cap_key,
        fmt::format("process.punch_travel_mm = {} mm in steps of at most {} takes at "
                    "least {:.3g} steps, more than the {:.0e} a run may take: raise {} or shorten "
                    "process.punch_travel_mm",
                    scene.process.punch_travel_mm, cap_text, steps, kMaxRunSteps, cap_key));
  }
  const bool shell3d = scene.geometry == Geometry::kShell3d;
  const double elements = element_count(scene);
  const double work = steps * elements;
  const double limit = shell3d ? kMaxElementSteps3d : kMaxElementStepsAxisym;
  if (work > limit) {
    const std::string size_key = shell3d ? "blank.divisions" : "blank.elements";
    where.fail(size_key,
               fmt::format("{} elements over at least {:.3g} steps ({} in steps of at most {}) "
                           "is {:.2g} element-steps, more than the {:.0e} allowed for {} runs "
                           "({}): use fewer elements ({}), a larger {} or a shorter "
                           "process.punch_travel_mm",
                           static_cast<int>(elements), steps,
                           fmt::format("{} mm", scene.process.punch_travel_mm), cap_text, work,
                           limit, shell3d ? "shell3d" : "axisymmetric",
                           shell3d ? "up to about 0.35 ms each on 2 cores: half an hour and more"
                                   : "about 10 us and, with output.history, 150 bytes each: "
                                     "tens of minutes and 15 GB",
                           size_key, cap_key));
  }
}

}  // namespace

void check_scene_consistency(const Scene& scene, const SceneSourceMap& where) {
  const ToolRoles roles = find_roles(scene, where);
  check_tools(scene, roles, where);
  check_blank(scene, roles, where);
  check_material(scene, where);
  check_process(scene, where);
  check_run_size(scene, where);
}

const std::vector<std::string_view>& scene_consistency_rules() {
  static const std::vector<std::string_view> rules = {
      "Tool names are unique.",
      "Exactly one punch (`hemispherical_punch` or `flat_punch`), at most one `die`, at most one "
      "`blank_holder`; a blank holder requires a die.",
      "Flat punch: `profile_radius_mm` < `radius_mm`.",
      "Blank holder: exactly one of `force_N` and `gap_mm`; `gap_mm` >= blank `thickness_mm`.",
      "Blank `radius_mm` > punch `radius_mm`.",
      "Die clearance: die `radius_mm` > punch `radius_mm` + blank `thickness_mm`.",
      "With a die, the blank reaches it: blank `radius_mm` > die `radius_mm`.",
      "`edge = \"free\"` requires a die (otherwise nothing holds the sheet).",
      "Thin shell: blank `thickness_mm` < blank `radius_mm` / 5.",
      "Planar anisotropy on a quarter blank: `rolling_direction_deg` a multiple of 90 (the "
      "symmetry planes x = 0, y = 0 must be material symmetry planes); `material.r_value` is "
      "not given with a planar `material.anisotropy.model`.",
      "`output_travels_mm` strictly increasing, each in (0, `punch_travel_mm`].",
      "Run size: steps end on a travel grid no coarser than min(`max_travel_increment_mm`, "
      "`max_travel_increment_per_length` x the shortest element), so a run takes at least "
      "`punch_travel_mm` / that cap steps; at most 1e6 steps, and at most 1e8 element-steps "
      "(steps x elements; axisymmetric: about 10 us and, with `output.history`, 150 bytes each) "
      "or 5e6 element-steps for `shell3d` (0.15-0.35 ms each on 2 cores). The 3D element size is "
      "estimated as `radius_mm` / (2 sqrt(`divisions` x max(`divisions`, `radial_divisions`))) "
      "for circles and `radius_mm` / `divisions` for squares.",
      "`radial_divisions` other than `divisions` needs a circular blank.",
      "Keys marked 'axisymmetric only' / 'shell3d only' are rejected in scenes of the other "
      "`geometry`.",
  };
  return rules;
}

}  // namespace vs
