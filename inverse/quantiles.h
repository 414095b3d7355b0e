// Two-sided confidence quantiles without a statistics library: Student-t (via the regularised
// incomplete beta function) and the standard normal (via erfc), both inverted by bisection,
// which is plenty for a handful of calls per calibration.
#pragma once

namespace vs {

// P(T <= t) for Student's t with `dof` > 0 degrees of freedom.
double student_t_cdf(double t, double dof);

// The t such that P(-t <= T <= t) = confidence, e.g. 12.706 for 0.95 and 1 dof.
double student_t_two_sided(double confidence, double dof);

// The z such that P(-z <= Z <= z) = confidence, e.g. 1.959964 for 0.95.
double normal_two_sided(double confidence);

}  // namespace vs
