#include "stepping/axisym_observe.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace vs {

Profile make_profile(const AxisymModel& model, const AxisymState& s, double punch_travel_mm,
                     const std::vector<Vec5>& resultants,
                     const std::vector<double>& punch_node_force) {
  Profile p;
  p.punch_force_node_N = punch_node_force;
  p.punch_travel_mm = punch_travel_mm;
  const std::size_t np = model.rule().zeta.size();
  const double h0 = model.initial_thickness();
  for (int e = 0; e < model.num_elements(); ++e) {
    const Axisym2Geometry g = model.geometry(s, e);
    const double r0 = model.initial_mid_radius(e);
    p.r0_mm.push_back(r0);
    p.r_mm.push_back(g.mid_radius());
    p.z_mm.push_back(0.5 * (g.za + g.zb));
    p.thickness_mm.push_back(s.thickness[e]);
    p.eps_meridional.push_back(std::log(g.length() / model.initial_length(e)));
    p.eps_circumferential.push_back(std::log(g.mid_radius() / r0));
    p.eps_thickness.push_back(std::log(s.thickness[e] / h0));
    p.eps_effective.push_back(s.eps_bar[e * np + np / 2]);
    p.contact.push_back((s.contact[e].tool >= 0 || s.contact[e + 1].tool >= 0) ? 1 : 0);
    if (!resultants.empty()) {
      const Vec5& S = resultants[e];
      const double l = g.length();
      const double c = (g.rb - g.ra) / l, sn = (g.zb - g.za) / l;
      p.meridional_force_N_per_mm.push_back(S(0));
      p.circumferential_force_N_per_mm.push_back(S(1));
      p.vertical_force_N.push_back(-2.0 * std::numbers::pi * g.mid_radius() *
                                   (S(0) * sn + S(4) * c));
    }
  }
  for (const auto& x : s.x) {
    p.node_r_mm.push_back(x.x());
    p.node_z_mm.push_back(x.y());
  }
  return p;
}

void fill_geometry(const AxisymModel& model, const AxisymState& s, StepRecord* rec) {
  double hmin = std::numeric_limits<double>::infinity();
  double volume = 0.0;
  for (int e = 0; e < model.num_elements(); ++e) {
    const Axisym2Geometry g = model.geometry(s, e);
    volume += 2.0 * std::numbers::pi * g.mid_radius() * g.length() * s.thickness[e];
    if (s.thickness[e] < hmin) {
      hmin = s.thickness[e];
      rec->thinnest_r0_mm = model.initial_mid_radius(e);
      rec->thinnest_r_mm = g.mid_radius();
    }
  }
  rec->min_thickness_mm = hmin;
  rec->volume_mm3 = volume;
  rec->rim_draw_in_mm = model.initial_radius(model.num_nodes() - 1) - s.x.back().x();
  int contacts = 0;
  for (const auto& c : s.contact) contacts += c.tool >= 0 ? 1 : 0;
  rec->contact_nodes = contacts;
  rec->time_s = s.time_s;
}

}  // namespace vs
