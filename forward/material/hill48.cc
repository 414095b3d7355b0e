#include "material/hill48.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace vs {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(std::string("Hill48: ") + name + " must be positive and finite, got " +
                     std::to_string(value));
  }
}

}  // namespace

Hill48Coefficients hill48_from_r_values(double r0, double r45, double r90) {
  require_positive(r0, "r0");
  require_positive(r45, "r45");
  require_positive(r90, "r90");
  Hill48Coefficients c;
  c.G = 1.0 / (1.0 + r0);
  c.H = r0 / (1.0 + r0);
  c.F = c.H / r90;
  c.N = (r45 + 0.5) * (c.F + c.G);
  return c;
}

Hill48Coefficients hill48_from_stresses(double sigma45, double sigma90, double sigma_b) {
  require_positive(sigma45, "sigma45/sigma0");
  require_positive(sigma90, "sigma90/sigma0");
  require_positive(sigma_b, "sigma_b/sigma0");
  const double a90 = 1.0 / (sigma90 * sigma90);  // F + H
  const double ab = 1.0 / (sigma_b * sigma_b);   // F + G
  const double sum = 0.5 * (1.0 + a90 + ab);     // F + G + H
  Hill48Coefficients c;
  c.F = sum - 1.0;
  c.G = sum - a90;
  c.H = sum - ab;
  c.N = 0.5 * (4.0 / (sigma45 * sigma45) - ab);
  return c;
}

Hill48Coefficients hill48_from_stresses_and_r0(double sigma45, double sigma90, double r0) {
  require_positive(sigma45, "sigma45/sigma0");
  require_positive(sigma90, "sigma90/sigma0");
  require_positive(r0, "r0");
  Hill48Coefficients c;
  c.G = 1.0 / (1.0 + r0);
  c.H = r0 / (1.0 + r0);
  c.F = 1.0 / (sigma90 * sigma90) - c.H;
  c.N = 0.5 * (4.0 / (sigma45 * sigma45) - c.F - c.G);
  return c;
}

Hill48::Hill48(const Hill48Coefficients& c) : c_(c) {
  P_ << c.G + c.H, -c.H, 0.0,  //
      -c.H, c.F + c.H, 0.0,    //
      0.0, 0.0, 2.0 * c.N;
  // Positive definite: G + H > 0, FG + GH + HF > 0 (the 2x2 determinant), N > 0.
  const double det2 = c.F * c.G + c.G * c.H + c.H * c.F;
  if (!(c.G + c.H > 0.0) || !(det2 > 0.0) || !(c.N > 0.0) || !P_.allFinite()) {
    throw InputError("Hill48: coefficients F=" + std::to_string(c.F) + " G=" + std::to_string(c.G) +
                     " H=" + std::to_string(c.H) + " N=" + std::to_string(c.N) +
                     " do not give a closed convex yield surface");
  }
  Pinv_ = P_.inverse();
}

Hill48 Hill48::NormalAnisotropy(double r_value) {
  return Hill48(hill48_from_r_values(r_value, r_value, r_value));
}

double Hill48::effective_stress(const PlaneVector& s) const {
  return std::sqrt(std::max(s.dot(P_ * s), 0.0));
}

YieldPoint Hill48::evaluate(const PlaneVector& s) const {
  YieldPoint p;
  const PlaneVector Ps = P_ * s;
  p.value = std::sqrt(std::max(s.dot(Ps), 0.0));
  if (p.value == 0.0) return p;
  p.gradient = Ps / p.value;
  p.hessian = (P_ - p.gradient * p.gradient.transpose()) / p.value;
  return p;
}

DualPoint Hill48::dual(const PlaneVector& d, const PlaneVector* /*guess*/) const {
  DualPoint p;
  const PlaneVector g = Pinv_ * d;
  p.rate = std::sqrt(std::max(d.dot(g), 0.0));
  if (p.rate > 0.0) p.direction = g / p.rate;
  p.hessian = Pinv_;
  return p;
}

}  // namespace vs
