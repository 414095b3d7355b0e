// The contact set's memory across the solves of a step (both geometries): which nodes the last
// solve released (they may not touch again in the same step), since when a released node may
// touch again (hold-off, StepDriverOptions::hold_off_increments), which nodes were ever
// released (a sticking patch edge, see the axisymmetric stepper), and whether new contacts wait
// for the last solve of an implicit step (defer_new, stepping/step_driver.h). The step driver
// saves and restores it around a cut-back; the geometry's contact search and release read and
// write it.
#pragma once

#include <limits>
#include <vector>

namespace vs {

struct ContactHolds {
  std::vector<char> released;         // by the last solve; empty: none
  std::vector<double> hold_until_mm;  // punch travel before which a node may not touch again
  std::vector<char> was_released;     // released at any earlier solve
  // New contacts wait for the last solve of an implicit step (numerics.contact_entry =
  // last_solve, stepping/step_driver.h): set around the contact search of every configuration
  // but the last.
  bool defer_new = false;
  // Releases wait for the last solve of an implicit step (set around every solve but the last,
  // stepping/step_driver.h): those solves' velocities only place the next configuration, and the
  // last configuration decides which nodes leave a tool.
  bool keep_touching = false;

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
  // Does a new contact with a tool wait for the last solve? Not on a sticking tool: a node that
  // touches it stops, and leaving it free for the step it touches in lengthens the free span at
  // the edge of the stuck patch by up to a step (measured: ex1 sticking, 48 elements, at the
  // default step the neck at the patch edge thinned to 0.444 mm against 0.489 step-converged).
  bool defers(bool sticking_tool) const { return defer_new && !sticking_tool; }
  // May a node whose reaction pulls leave a tool in this solve? Always on a sticking tool: a
  // stuck node that pulls is the edge of the stuck patch, which slides from the next solve on
  // (AxisymStepper::attach); held to the last solve, the edge of the stuck cap necked deeper and
  // mesh-dependently (ex1 sticking, 24 against 48 elements: thinnest point 31 % apart, mean force
  // over 25-30 mm 6 %; AxisymForming.StickingIsNeitherPathNorMeshSensitive allows 3 %).
  bool may_release(bool sticking_tool) const { return !keep_touching || sticking_tool; }
  // May node search for contact at this travel?
  bool may_touch(int node, double travel_mm) const {
    if (!released.empty() && released[node]) return false;
    return hold_until_mm.empty() || !(travel_mm < hold_until_mm[node]);
  }
};

}  // namespace vs
