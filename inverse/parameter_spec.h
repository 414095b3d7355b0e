// One calibration parameter: a number in the scene, addressed by its dotted scene address
// (tool.punch.friction, material.hardening.K_MPa, ...; see scene/scene_table.h), with start
// value, bounds and a scale.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace vs {

struct ParameterSpec {
  std::string address;  // dotted scene address; also the parameter's name in reports
  double initial = 0.0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  // Typical magnitude of the parameter (in its own unit). The optimiser works on value/scale,
  // and finite-difference steps are relative_step * scale, so a step means the same thing for
  // a friction coefficient of 0.1 and a K of 500 MPa. Must be > 0.
  double scale = 1.0;
  bool fixed = false;  // kept at `initial`, not identified
  std::string where;   // config file:line, for messages

  // Checks scale > 0, finite initial, lower <= initial <= upper, lower < upper for a free
  // parameter. Sets *why (with `where`) and returns false otherwise.
  bool IsValid(std::string* why) const;
};

// Unit of a parameter from its address, following the project's rule that names carry units
// (K_MPa -> "MPa", radius_mm -> "mm"); "1" for dimensionless ones such as friction or n.
std::string unit_of_address(const std::string& address);

// The free parameters' indices into `specs`, in order.
std::vector<int> free_parameter_indices(const std::vector<ParameterSpec>& specs);

}  // namespace vs
