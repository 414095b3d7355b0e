// Strain hardening: flow stress sigma_y(eps_bar) of the in-plane uniaxial tensile curve and its
// slope, for the laws of HardeningSpec. Pure functions of a value type.
#pragma once

#include "scene/scene.h"

namespace vs {

class Hardening {
 public:
  explicit Hardening(const HardeningSpec& spec);

  // Flow stress [MPa] at accumulated effective plastic strain eps (>= 0).
  double flow_stress(double eps) const;
  // d flow_stress / d eps [MPa].
  double slope(double eps) const;

 private:
  HardeningSpec spec_;
  double hollomon_plateau_strain_ = 0.0;  // strain where K eps^n reaches sigma0
};

}  // namespace vs
