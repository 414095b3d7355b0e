#include "run/built_components.h"

#include <fmt/format.h>

namespace vs {

namespace {

std::string friction_words(const ToolSpec& t) {
  if (t.sticking()) return "sticking (no slip)";
  if (t.friction == 0.0) return "frictionless";
  return fmt::format("regularised Coulomb friction {}", t.friction);
}

std::string kind_name(ToolKind k) {
  switch (k) {
    case ToolKind::kHemisphericalPunch:
      return "hemispherical punch";
    case ToolKind::kFlatPunch:
      return "flat punch";
    case ToolKind::kDie:
      return "die";
    case ToolKind::kBlankHolder:
      return "blank holder";
  }
  return "tool";
}

}  // namespace

std::vector<std::string> tool_components(const Scene& scene) {
  std::vector<std::string> lines;
  for (const ToolSpec& t : scene.tools) {
    std::string what = "contact";
    if (t.kind == ToolKind::kBlankHolder) {
      what = t.gap_mm > 0.0 ? fmt::format("fixed gap {} mm to the die face", t.gap_mm)
                            : fmt::format("force {} N on the flange", t.force_N);
    }
    lines.push_back(
        fmt::format("tool '{}' ({}): {}, {}", t.name, kind_name(t.kind), what, friction_words(t)));
  }
  return lines;
}

}  // namespace vs
