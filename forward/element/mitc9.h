// MITC9 assumed covariant strains (Bucalem & Bathe, IJNME 36 (1993) 3729-3754): the covariant
// components are sampled ("tied") at points where the displacement-based element is accurate and
// re-interpolated with lower-order functions, which removes membrane and shear locking without
// spurious modes. With a = 1/sqrt(3), b = sqrt(3/5):
//   e_rr, 2e_rt: tied at r = +-a, s = -b, 0, b; interpolated linearly in r, quadratically in s;
//   e_ss, 2e_st: the same with r and s exchanged;
//   2e_rs:       tied at r = +-a, s = +-a; interpolated bilinearly.
// The tying is done at the same thickness coordinate t as the integration point.
#pragma once

#include <array>

#include "element/shell9_kinematics.h"

namespace vs::shell3d {

struct Mitc9TyingB {
  std::array<Mat5X, 6> r_points;   // full covariant B at the e_rr / e_rt tying points
  std::array<Mat5X, 6> s_points;   // at the e_ss / e_st tying points
  std::array<Mat5X, 4> rs_points;  // at the e_rs tying points
};

// Evaluates the covariant B at all tying points for thickness coordinate t.
Mitc9TyingB mitc9_tying(const Shell9Geometry& g, double t);

// Assumed covariant B at (r, s) from the tying values.
Mat5X mitc9_assumed_B(const Mitc9TyingB& tying, double r, double s);

}  // namespace vs::shell3d
