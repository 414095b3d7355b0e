#include "output/step_csv.h"

#include <fmt/format.h>

#include "output/number_format.h"

namespace vs {

const std::string& load_travel_csv_header() {
  static const std::string header =
      "step,time_s,punch_travel_mm,punch_force_N,iterations,residual_norm,update_norm,"
      "contact_nodes,cutbacks,min_thickness_mm,thinnest_r0_mm,thinnest_r_mm,volume_mm3,"
      "rim_draw_in_mm";
  return header;
}

std::string load_travel_csv_row(const StepRecord& r) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}", r.step, format_number(r.time_s),
                     format_number(r.punch_travel_mm), format_number(r.punch_force_N), r.iterations,
                     format_number(r.residual_norm), format_number(r.update_norm), r.contact_nodes,
                     r.cutbacks, format_number(r.min_thickness_mm), format_number(r.thinnest_r0_mm),
                     format_number(r.thinnest_r_mm), format_number(r.volume_mm3),
                     format_number(r.rim_draw_in_mm));
}

std::string load_travel_csv(const std::vector<StepRecord>& steps) {
  std::string out = load_travel_csv_header() + '\n';
  for (const StepRecord& r : steps) out += load_travel_csv_row(r) + '\n';
  return out;
}

std::string thinnest_point_csv(const std::vector<StepRecord>& steps, double initial_thickness_mm) {
  std::string out =
      "punch_travel_mm,min_thickness_mm,thinning_percent,thinnest_r0_mm,thinnest_r_mm\n";
  for (const StepRecord& r : steps) {
    out += fmt::format("{},{},{},{},{}\n", format_number(r.punch_travel_mm),
                       format_number(r.min_thickness_mm),
                       format_number(100.0 * (1.0 - r.min_thickness_mm / initial_thickness_mm)),
                       format_number(r.thinnest_r0_mm), format_number(r.thinnest_r_mm));
  }
  return out;
}

}  // namespace vs
