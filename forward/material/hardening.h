// Strain hardening: flow stress sigma_y(eps_bar) of the in-plane uniaxial tensile curve and its
// slope, for the laws of HardeningSpec, optionally with the elastic start of [material.elastic]
// (material/elastic_start.h). Pure functions of a value type; the one flow-stress law of both
// geometries.
#pragma once

#include "scene/scene.h"

namespace vs {

class Hardening {
 public:
  explicit Hardening(const HardeningSpec& spec);
  // With the elastic start of [material.elastic] (elastic.start_on()): flow_stress(e) is the
  // secant elastic-plastic curve of material/elastic_start.h at total effective strain e.
  Hardening(const HardeningSpec& spec, const ElasticSpec& elastic);

  // Flow stress [MPa] the flow sees at accumulated effective strain eps (>= 0): the hardening
  // curve, or with the elastic start the secant curve min(E e, sigma_y(e - sigma / E)).
  double flow_stress(double eps) const;
  // d flow_stress / d eps [MPa].
  double slope(double eps) const;
  // Both at once (one root solve with the elastic start).
  double flow_stress_and_slope(double eps, double* slope) const;

  // The hardening curve itself, sigma_y at effective plastic strain eps, and its slope.
  double curve_stress(double eps) const;
  double curve_slope(double eps) const;

  // Young's modulus of the elastic start [MPa], 0 without it.
  double start_modulus_MPa() const { return start_modulus_MPa_; }

 private:
  HardeningSpec spec_;
  double start_modulus_MPa_ = 0.0;
  double hollomon_plateau_strain_ = 0.0;  // strain where K eps^n reaches sigma0
};

}  // namespace vs
