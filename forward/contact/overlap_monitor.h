// The run's record of a sheet that overlaps a second tool, for both geometries. Two cases, each
// with its own warning at the end of the run (the first occurrence and the largest overlap):
//   * through: a node touching one tool overlaps another (not the blank holder, whose gap has
//     its own model) without being held by the ironing constraint: the sheet passes through the
//     tool, and results beyond that travel are not trustworthy;
//   * ironing lag: a squeezed node (the ironing constraint holds it between the two tools) is
//     thicker than the clearance: the constraint thins at most the strain cap of a step
//     (numerics.max_strain_increment, model/ironing.h), and a clearance that narrows faster along
//     the node's path (the die shoulder) leaves the thickness behind (measured, the 3D ESAFORM
//     cup at 4 divisions: 0.03-0.06 mm, 3-6 % of the thickness, over 1.5 mm of travel on the die
//     shoulder at 37-39 mm; the axisymmetric cup keeps it under 1 %).
// Overlaps up to kToleranceFraction of the initial thickness are contact tolerance. The steppers
// measure the overlaps with their own geometry after every accepted state (observe()).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace vs {

class OverlapMonitor {
 public:
  static constexpr double kToleranceFraction = 0.02;

  explicit OverlapMonitor(double initial_thickness_mm)
      : tolerance_mm_(kToleranceFraction * initial_thickness_mm) {}

  double tolerance_mm() const { return tolerance_mm_; }

  // A node touching tool `touching` overlaps tool `other` by `overlap_mm` at punch travel
  // `travel_mm`; `squeezed`: the ironing constraint holds it between the two. where() names the
  // node ("initial radius 12.3 mm"); it is called only for the first occurrence of each case.
  // Overlaps within the tolerance are ignored.
  template <class Where>
  void note(double travel_mm, double overlap_mm, const std::string& touching,
            const std::string& other, const Where& where, bool squeezed) {
    if (!(overlap_mm > tolerance_mm_)) return;
    Record& r = squeezed ? lag_ : through_;
    r.max_mm = std::max(r.max_mm, overlap_mm);
    if (r.travel_mm >= 0.0) return;
    r.travel_mm = travel_mm;
    r.first_mm = overlap_mm;
    r.tools = fmt::format("'{}' and '{}'", touching, other);
    r.where = where();
  }

  bool through_seen() const { return through_.travel_mm >= 0.0; }
  bool lag_seen() const { return lag_.travel_mm >= 0.0; }
  double largest_through_mm() const { return through_.max_mm; }
  double largest_lag_mm() const { return lag_.max_mm; }

  // The run's warnings (none, one or two).
  std::vector<std::string> warnings() const {
    std::vector<std::string> out;
    if (through_seen()) {
      out.push_back(fmt::format(
          "from punch travel {:.2f} mm the sheet is squeezed between tools {} (node at {} "
          "overlaps the second tool by {:.3g} mm, up to {:.3g} mm later, more than the ironing "
          "constraint allows): results beyond that travel are not trustworthy",
          through_.travel_mm, through_.tools, through_.where, through_.first_mm, through_.max_mm));
    }
    if (lag_seen()) {
      out.push_back(fmt::format(
          "from punch travel {:.2f} mm the ironing between tools {} lags the narrowing "
          "clearance (node at {} is thicker than the clearance by {:.3g} mm, up to {:.3g} mm "
          "later; a step thins it by at most numerics.max_strain_increment): smaller steps or a "
          "larger strain cap let it keep up",
          lag_.travel_mm, lag_.tools, lag_.where, lag_.first_mm, lag_.max_mm));
    }
    return out;
  }

 private:
  struct Record {
    double travel_mm = -1.0;  // first travel with an overlap, -1: none yet
    double first_mm = 0.0;
    double max_mm = 0.0;
    std::string tools, where;
  };
  double tolerance_mm_;
  Record through_, lag_;
};

}  // namespace vs
