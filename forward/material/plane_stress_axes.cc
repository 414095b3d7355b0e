#include "material/plane_stress_axes.h"

#include <cmath>

namespace vs {

MaterialAxes::MaterialAxes(double rd_angle_rad)
    : MaterialAxes(std::cos(rd_angle_rad), std::sin(rd_angle_rad)) {}

MaterialAxes::MaterialAxes(double c, double s) {
  T_ << c * c, s * s, c * s,  //
      s * s, c * c, -c * s,   //
      -2.0 * c * s, 2.0 * c * s, c * c - s * s;
  Ts_ << c * c, s * s, 2.0 * c * s,  //
      s * s, c * c, -2.0 * c * s,    //
      -c * s, c * s, c * c - s * s;
}

PlaneVector uniaxial_stress_direction(double theta_rad) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  return {c * c, s * s, c * s};
}

double lankford_ratio(const PlaneVector& d, double theta_rad) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  const double width_rate = d(0) * s * s + d(1) * c * c - d(2) * s * c;
  const double thickness_rate = -(d(0) + d(1));
  return width_rate / thickness_rate;
}

}  // namespace vs
