#include "material/plane_stress_yield.h"

namespace vs {

DirectionalResponse uniaxial_response(const PlaneStressYield& yield, double theta_rad) {
  const YieldPoint p = yield.evaluate(uniaxial_stress_direction(theta_rad));
  return {1.0 / p.value, lankford_ratio(p.gradient, theta_rad)};
}

DirectionalResponse equibiaxial_response(const PlaneStressYield& yield) {
  const YieldPoint p = yield.evaluate(PlaneVector(1.0, 1.0, 0.0));
  return {1.0 / p.value, p.gradient(1) / p.gradient(0)};
}

}  // namespace vs
