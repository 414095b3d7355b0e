// The thickness bound of a sheet squeezed between two tools (ironing), shared by both geometries
// (AxisymModel::add_squeeze, the ironing form of shell3d::GapHolder3).
//
// Over a step dt the thickness h of a squeezed point ends at h exp(-a dt), with a the in-plane
// area rate (d_s + d_t in the axisymmetric element, the surface divergence in 3D). Held in the
// clearance g, a >= c = L / dt with the log target
//   L = min(ln(h / g), cap) correction:
//   * h <= g: L <= 0, the sheet may thicken towards the clearance and no further;
//   * h > g (an overshoot: the clearance narrows as the sheet runs into it, over a die shoulder,
//     or the sheet arrives thicker than it): L > 0, the sheet is thinned back, which is ironing;
//     cap (the strain cap of a step) and correction (<= 1: the step over the time of a regular
//     step) spread a large overshoot over steps.
// Tolerance (not used: both models call it with 0, see the measurements). The penalty that
// enforces the bound (k = 1e3 times the nominal viscosity sigma / (3 eps_dot_nom)) leaves the
// violation p / k behind, and a sheet that thins flows plastically, at p ~ sigma: each ironing
// step leaves an overshoot of about 3e-3 of the nominal step strain, whose correction in the
// next step again demands plastic thinning at p ~ sigma. An ironed wall can so keep a pressure of
// the order of the flow stress, and the friction of both faces on it. A tolerance (an overshoot
// below it not corrected) removes that, and was measured in 3D (Nov 2026) in three forms:
//   * L = 0 in the band (g, g e^tol]: the tight cup of tests/shell3d/ironing_test.cc completes
//     its 20 mm, but the ESAFORM cup stalls at 46 mm, when the drawn cup moves rigidly
//     (|dx|/|x| = 9e-16, |r|/|f| = 0.03), and so do 17 of the 18 axisymmetric ESAFORM cups of
//     experiments/04 at 42-43 mm;
//   * L = min(ln(h / g), 0) - 1e-6 (a rigid wall off the penalty's kink): the ESAFORM cup stalls
//     at 45.5 mm (|r|/|f| = 0.11), the tight cup diverges at 17.8 mm;
//   * L = ln(h / g) - tol: the wall cycles between thickening to g e^tol and being ironed back;
//     the tight cup diverges at 17.9 mm.
// Without it (tolerance 0, the form both models use) the ESAFORM cup draws to the end (48 mm in
// 3D, 45 mm axisymmetric) and the tight cup to 17.9 mm, where it diverges as the thickened rim
// enters the clearance (the test stops at 17 mm). The tolerance branch is kept, tested, for that
// work.
#pragma once

#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace vs {

inline constexpr double kIroningTolerance = 2e-3;  // relative overshoot left uncorrected
// Below the tolerance the bound is min(ln(h / g), 0) - kIroningSlack: a wall that moves rigidly
// (area rate 0 up to round-off) is then strictly inside it, never on the penalty's kink.
inline constexpr double kIroningSlack = 1e-6;

// The log target L of the header comment; tolerance 0: min(ln(h / g), cap) correction for every
// h (the form both models use).
inline double ironing_log_target(double h, double g, double cap, double correction,
                                 double tolerance) {
  const double log_ratio = std::log(h / g);
  if (tolerance <= 0.0) return std::min(log_ratio, cap) * correction;
  if (log_ratio > tolerance) return std::min(log_ratio, cap) * correction;
  return std::min(log_ratio, 0.0) - kIroningSlack;
}

// The time over which a squeezed overshoot is ironed out (the models' squeeze correction time):
// a regular (grid) step's, so that a node squeezed at a short contact-event step is not ironed
// at a multiple of the flow rate; with the implicit update theta of it, because that update moves
// the geometry with theta of the end-of-step rate.
inline double ironing_correction_time_s(const Scene& scene, double grid_increment_mm) {
  const double theta = scene.numerics.time_integration == TimeIntegration::kImplicit
                           ? scene.numerics.implicit_theta
                           : 1.0;
  return theta * grid_increment_mm / scene.process.punch_speed_mm_per_s;
}

}  // namespace vs
