#include "scene/scene_checks.h"

#include <fmt/format.h>

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
  if (scene.geometry == Geometry::kShell3d && roles.holder != nullptr &&
      roles.holder->gap_mm > 0.0) {
    where.fail(tool_address(*roles.holder, "gap_mm"),
               fmt::format("{} = {}: geometry = \"shell3d\" has no fixed-gap blank holder yet "
                           "(use {}, or the axisymmetric geometry)",
                           tool_address(*roles.holder, "gap_mm"), roles.holder->gap_mm,
                           tool_address(*roles.holder, "force_N")));
  }
  if (blank.edge == EdgeCondition::kFree && roles.die == nullptr) {
    where.fail("blank.edge",
               "blank.edge = \"free\" needs a die: without one nothing holds the sheet");
  }
  if (!(blank.thickness_mm < blank.radius_mm / 5.0)) {
    where.fail("blank.thickness_mm",
               fmt::format("blank.thickness_mm = {} must be < blank.radius_mm / 5 = {} mm (thin "
                           "shell)",
                           blank.thickness_mm, blank.radius_mm / 5.0));
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

}  // namespace

void check_scene_consistency(const Scene& scene, const SceneSourceMap& where) {
  const ToolRoles roles = find_roles(scene, where);
  check_tools(scene, roles, where);
  check_blank(scene, roles, where);
  check_process(scene, where);
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
      "`output_travels_mm` strictly increasing, each in (0, `punch_travel_mm`].",
      "Keys marked 'axisymmetric only' / 'shell3d only' are rejected in scenes of the other "
      "`geometry`; `geometry = \"shell3d\"` has no fixed-gap blank holder (`gap_mm`) yet.",
  };
  return rules;
}

}  // namespace vs
