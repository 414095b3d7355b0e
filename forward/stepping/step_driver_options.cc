#include "stepping/step_driver_options.h"

#include <fmt/format.h>

#include <cmath>

namespace vs {

bool StepDriverOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(contact_tolerance > 0.0 && contact_tolerance <= attach_tolerance))
    return fail("contact_tolerance must be positive and at most attach_tolerance");
  if (!(attach_tolerance <= punch_attach_tolerance && punch_attach_tolerance < 1.0))
    return fail("punch_attach_tolerance must be at least attach_tolerance and below 1 thickness");
  if (max_contact_rounds < 1) return fail("max_contact_rounds must be at least 1");
  if (!(release_fraction >= 0.0 && release_fraction < 1.0))
    return fail("release_fraction must be in [0, 1)");
  if (!(hold_off_increments >= 0.0)) return fail("hold_off_increments must be >= 0");
  if (!(min_event_fraction > 0.0 && min_event_fraction < 1.0))
    return fail("min_event_fraction must be in (0, 1)");
  if (max_steps_with_cutbacks < 1 || max_stalled_steps < 1)
    return fail("the stop counts must be at least 1");
  if (!(stall_fraction > 0.0 && stall_fraction < 1.0))
    return fail("stall_fraction must be in (0, 1)");
  if (!(min_thickness_ratio > 0.0 && min_thickness_ratio < 1.0 && max_thickness_ratio > 1.0))
    return fail("thickness ratios must bracket 1");
  if (!(implicit_first_tolerance_factor >= 1.0 && std::isfinite(implicit_first_tolerance_factor)))
    return fail("implicit_first_tolerance_factor must be a finite number >= 1");
  if (!(residual_force_floor >= 0.0 && residual_force_floor < 1e-3))
    return fail("residual_force_floor must be in [0, 1e-3)");
  return true;
}

std::string thickness_limit_reason(double h, double h0, const StepDriverOptions& options,
                                   double shortest_element_mm, const char* fewer_what) {
  if (h >= options.min_thickness_ratio * h0) return "the mesh is folding onto itself";
  if (shortest_element_mm < h0) {
    return fmt::format(
        "the sub-thickness-mesh instability, not a resolved neck (elements as short as {:.3g} mm, "
        "shorter than the thickness {:.3g} mm; use fewer {})",
        shortest_element_mm, h0, fewer_what);
  }
  return "the sheet has necked through (fracture)";
}

}  // namespace vs
