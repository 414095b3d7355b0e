// The step driver's constants, declared once for both geometries (they were hard-coded in each
// driver before Nov 2026). Each is a measured choice; the comment says what it guards.
#pragma once

#include <string>

#include "solver/newton.h"

namespace vs {

struct StepDriverOptions {
  // Contact search, relative to the sheet thickness: a node touches a tool when its gap is below
  // contact_tolerance; next to a patch (most of its neighbours on the tool) the search widens to
  // attach_tolerance, which fills holes inside a patch (a rigid band riding on the punch lifts
  // off by micrometres and would otherwise never come back; the front of a patch still advances
  // by exact contact events, so outputs stay smooth in the parameters).
  double contact_tolerance = 1e-8;
  double attach_tolerance = 1e-2;
  // 3D: next to a patch on a punch the search widens further, to punch_attach_tolerance. On
  // meshes of 16 divisions and more a node of the 9-node sheet can stay a little farther than
  // attach_tolerance above the punch while its neighbours touch, and then rises (to 0.05 mm, 6 %
  // of the thickness, on ex4a by 30 mm). Free inside the patch, such a node thinned apart from
  // its neighbours: single-node spikes of the thickness strain against the axisymmetric twin,
  // 0.011 at 16 and 0.027 at 32 divisions at 30 mm, 0.007 and 0.009 with 5e-2
  // (experiments/05_shell3d, "Holes in the contact patch"). Not on a die or a holder: the band a
  // cup wraps over the die shoulder loses nodes at its exit, and attaching those within 5 % of the
  // thickness made the bundled 3D cup chatter (56 cut-backs, a noise-like load curve). The
  // axisymmetric driver (2-node elements; a hole is a node between two touching ones) keeps
  // attach_tolerance.
  double punch_attach_tolerance = 5e-2;
  // Active-set rounds of one solve (release, re-solve) before it fails.
  int max_contact_rounds = 20;
  // A released node's reaction must pull by more than this fraction of the largest contact
  // reaction (round-off level: a node touching with zero force would chatter otherwise).
  double release_fraction = 1e-4;
  // A released node may not touch again before the punch has moved this many grid increments:
  // without the hysteresis a node whose reaction hovers around zero attaches and releases at
  // every step and the contact-event step shrinks to nothing (measured: ex1, 40 elements,
  // sticking, 0.037 mm grid: 20 000 steps stuck at 26.63 mm).
  double hold_off_increments = 1.0;
  // A contact event closer than this fraction of the step cap is taken at this fraction.
  double min_event_fraction = 1e-12;
  // A run stops (with the reason) after this many consecutive steps that needed a cut-back (the
  // step size keeps collapsing), or that advanced the punch by less than stall_fraction of the
  // grid increment (contact events piling up at one instant).
  int max_steps_with_cutbacks = 25;
  int max_stalled_steps = 200;
  double stall_fraction = 1e-6;
  // Thickness limits relative to the initial thickness: thinning to min_thickness_ratio is
  // fracture (necking has long run away), thickening to max_thickness_ratio means the mesh is
  // folding onto itself (measured: a cup whose flange locks in a fixed-gap holder tangles at the
  // holder edge, h = 13 h0).
  double min_thickness_ratio = 0.05;
  double max_thickness_ratio = 3.0;
  // Newton tolerance of every implicit solve but the last, as a multiple of numerics.tolerance
  // (at most kMaxLooseTolerance; 1: all solves to numerics.tolerance). Their velocity only places
  // the configuration of the next solve, which starts from it and is solved to the tolerance.
  // Measured (issue 14, tolerance 1e-6): ex1 (50 elements, implicit at 0.25), first solves 692 /
  // 606 / 506 iterations at 1 / 1e2 / 1e3, forces within 1.3e-8 / 3.8e-6; ex4a n = 8 (friction
  // 0.2, implicit at 0.25, 10 mm) 226 / 156 / 126, forces within 1e-6 at 1e3. 1e3 fails the
  // consistent-vs-lagged friction test (ex1, friction 0.2: 2.5e-5 in thickness strain against
  // 1e-5; 1.5e-6 at 1e2): a lagged iteration converges linearly, and its last update
  // understates its error.
  double implicit_first_tolerance_factor = 1e2;
  static constexpr double kMaxLooseTolerance = 0.1;
  // The Newton residual's absolute floor (NewtonOptions::force_floor) as a fraction of the
  // sheet's characteristic force sigma_y(0) h0 R (initial yield stress, thickness, blank
  // radius): far below any load the sheet carries while it deforms, far above the round-off of a
  // sheet that only moves rigidly.
  double residual_force_floor = 1e-9;

  // False with the reason if an option is out of range.
  bool IsValid(std::string* why) const;
};

// The Newton solver's force scales for a sheet with initial yield stress sigma_y0, thickness h0
// and blank radius R: the residual's floor NewtonOptions::force_floor =
// options.residual_force_floor sigma_y0 h0 R, and the round-off stagnation test's
// NewtonOptions::stagnation_force = sigma_y0 h0 R.
inline void set_newton_force_scales(const StepDriverOptions& options, double sigma_y0_MPa,
                                    double h0_mm, double radius_mm, NewtonOptions* newton) {
  const double characteristic = sigma_y0_MPa * h0_mm * radius_mm;
  newton->force_floor = options.residual_force_floor * characteristic;
  newton->stagnation_force = characteristic;
}

// Why a thickness h outside the limits of `options` (relative to h0) stops a run: "the mesh is
// folding onto itself" above them; below them "the sheet has necked through (fracture)", unless
// the mesh has elements shorter than the thickness (shortest_element_mm < h0, the case the run
// warned about at its start): then it is the sub-thickness-mesh instability, not a resolved neck.
std::string thickness_limit_reason(double h, double h0, const StepDriverOptions& options,
                                   double shortest_element_mm, const char* fewer_what);

}  // namespace vs
