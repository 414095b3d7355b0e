// The contact set's memory across the solves of a step (both geometries): which nodes the last
// solve released (they may not touch again in the same step), since when a released node may
// touch again (hold-off, StepDriverOptions::hold_off_increments), and which nodes were ever
// released (a sticking patch edge, see the axisymmetric stepper). The step driver saves and
// restores it around a cut-back; the geometry's contact search and release read and write it.
#pragma once

#include <limits>
#include <vector>

namespace vs {

struct ContactHolds {
  std::vector<char> released;         // by the last solve; empty: none
  std::vector<double> hold_until_mm;  // punch travel before which a node may not touch again
  std::vector<char> was_released;     // released at any earlier solve

  void reset(int nodes) {
    released.assign(nodes, 0);
    hold_until_mm.assign(nodes, -std::numeric_limits<double>::infinity());
    was_released.assign(nodes, 0);
  }
  // A new solve: nothing released yet.
  void new_solve(int nodes) { released.assign(nodes, 0); }
  void release(int node, double travel_mm, double hold_off_mm) {
    released[node] = 1;
    was_released[node] = 1;
    hold_until_mm[node] = travel_mm + hold_off_mm;
  }
  // May node search for contact at this travel?
  bool may_touch(int node, double travel_mm) const {
    if (!released.empty() && released[node]) return false;
    return hold_until_mm.empty() || !(travel_mm < hold_until_mm[node]);
  }
};

}  // namespace vs
