#include "material/yld2000_fit.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace vs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Width weights: n_ww = n . w(theta).
PlaneVector width_weights(double theta_rad) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  return {s * s, c * c, -s * c};
}

double uniaxial_stress_residual(const YieldPoint& p, double sigma) { return sigma * p.value - 1.0; }
double uniaxial_r_residual(const YieldPoint& p, double theta_rad, double r) {
  return p.gradient.dot(width_weights(theta_rad)) + r * (p.gradient(0) + p.gradient(1));
}

// Block A: alpha1..alpha6 from the data at 0, 90 degrees and equibiaxial.
Eigen::VectorXd residual_a(const Yld2000& y, const AnisotropyData& d) {
  const YieldPoint p0 = y.evaluate(uniaxial_stress_direction(0.0));
  const YieldPoint p90 = y.evaluate(uniaxial_stress_direction(90.0 * kDeg));
  const YieldPoint pb = y.evaluate(PlaneVector(1.0, 1.0, 0.0));
  Eigen::VectorXd r(6);
  r << uniaxial_stress_residual(p0, d.sigma0), uniaxial_stress_residual(p90, d.sigma90),
      d.sigma_b * pb.value - 1.0, uniaxial_r_residual(p0, 0.0, d.r0),
      uniaxial_r_residual(p90, 90.0 * kDeg, d.r90), pb.gradient(1) - d.r_b * pb.gradient(0);
  return r;
}

// Block B: alpha7, alpha8 from the data at 45 degrees.
Eigen::VectorXd residual_b(const Yld2000& y, const AnisotropyData& d) {
  const YieldPoint p45 = y.evaluate(uniaxial_stress_direction(45.0 * kDeg));
  Eigen::VectorXd r(2);
  r << uniaxial_stress_residual(p45, d.sigma45), uniaxial_r_residual(p45, 45.0 * kDeg, d.r45);
  return r;
}

using Residual = Eigen::VectorXd (*)(const Yld2000&, const AnisotropyData&);

// Newton on the block of alpha indices [first, first + n) with the other coefficients fixed.
bool newton_block(Yld2000Coefficients& c, int first, int n, Residual residual,
                  const AnisotropyData& data, const Yld2000FitOptions& options, int& iterations) {
  auto eval = [&](const Yld2000Coefficients& cc) { return residual(Yld2000(cc), data); };
  Eigen::VectorXd R = eval(c);
  for (int it = 0; it < options.max_iterations; ++it) {
    if (!R.allFinite()) return false;
    if (R.cwiseAbs().maxCoeff() <= options.tolerance) return true;
    ++iterations;
    Eigen::MatrixXd J(n, n);
    for (int j = 0; j < n; ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(c.alpha[first + j]));
      Yld2000Coefficients cp = c, cm = c;
      cp.alpha[first + j] += h;
      cm.alpha[first + j] -= h;
      J.col(j) = (eval(cp) - eval(cm)) / (2.0 * h);
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    if (!lu.isInvertible()) return false;
    const Eigen::VectorXd step = -lu.solve(R);
    if (!step.allFinite()) return false;
    const double merit = R.squaredNorm();
    double t = 1.0;
    bool accepted = false;
    for (int k = 0; k < 30 && !accepted; ++k, t *= 0.5) {
      Yld2000Coefficients trial = c;
      for (int j = 0; j < n; ++j) trial.alpha[first + j] += t * step(j);
      const Eigen::VectorXd Rt = eval(trial);
      if (Rt.allFinite() && Rt.squaredNorm() <= (1.0 - 1e-4 * t) * merit) {
        c = trial;
        R = Rt;
        accepted = true;
      }
    }
    if (!accepted) return R.cwiseAbs().maxCoeff() <= options.tolerance;
  }
  return R.cwiseAbs().maxCoeff() <= options.tolerance;
}

bool solve(Yld2000Coefficients& c, const AnisotropyData& data, const Yld2000FitOptions& options,
           int& iterations) {
  return newton_block(c, 0, 6, residual_a, data, options, iterations) &&
         newton_block(c, 6, 2, residual_b, data, options, iterations);
}

AnisotropyData blend(const AnisotropyData& target, double t) {
  auto mix = [t](double v) { return 1.0 + t * (v - 1.0); };
  return {mix(target.sigma0), mix(target.sigma45), mix(target.sigma90), mix(target.sigma_b),
          mix(target.r0),     mix(target.r45),     mix(target.r90),     mix(target.r_b)};
}

void require_positive(double v, const char* name) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(std::string("Yld2000 identification: ") + name +
                     " must be positive and finite, got " + std::to_string(v));
  }
}

double max_residual(const Yld2000Coefficients& c, const AnisotropyData& data) {
  const Yld2000 y(c);
  return std::max(residual_a(y, data).cwiseAbs().maxCoeff(),
                  residual_b(y, data).cwiseAbs().maxCoeff());
}

}  // namespace

AnisotropyData predicted_anisotropy_data(const PlaneStressYield& yield) {
  AnisotropyData d;
  const DirectionalResponse u0 = uniaxial_response(yield, 0.0);
  const DirectionalResponse u45 = uniaxial_response(yield, 45.0 * kDeg);
  const DirectionalResponse u90 = uniaxial_response(yield, 90.0 * kDeg);
  const DirectionalResponse b = equibiaxial_response(yield);
  d.sigma0 = u0.stress;
  d.sigma45 = u45.stress;
  d.sigma90 = u90.stress;
  d.sigma_b = b.stress;
  d.r0 = u0.r_value;
  d.r45 = u45.r_value;
  d.r90 = u90.r_value;
  d.r_b = b.r_value;
  return d;
}

Yld2000FitSummary fit_yld2000(const AnisotropyData& data, const Yld2000FitOptions& options) {
  require_positive(data.sigma0, "sigma0");
  require_positive(data.sigma45, "sigma45");
  require_positive(data.sigma90, "sigma90");
  require_positive(data.sigma_b, "sigma_b");
  require_positive(data.r0, "r0");
  require_positive(data.r45, "r45");
  require_positive(data.r90, "r90");
  require_positive(data.r_b, "r_b");
  Yld2000Coefficients start;
  start.exponent = options.exponent;
  (void)Yld2000(start);  // validates the exponent (InputError)

  Yld2000FitSummary summary;
  Yld2000Coefficients c = start;
  bool ok = solve(c, data, options, summary.iterations);
  if (!ok) {
    c = start;
    ok = true;
    const int steps = std::max(options.continuation_steps, 1);
    summary.continuation_steps = steps;
    for (int k = 1; k <= steps && ok; ++k) {
      ok = solve(c, blend(data, static_cast<double>(k) / steps), options, summary.iterations);
    }
  }
  // Sign normalisation (header comment).
  auto& a = c.alpha;
  a[6] = std::abs(a[6]);
  a[7] = std::abs(a[7]);
  if (a[0] < 0.0) {
    a[0] = -a[0];
    a[1] = -a[1];
  }
  if (a[2] + a[3] + a[4] + a[5] < 0.0) {
    for (int i = 2; i < 6; ++i) a[i] = -a[i];
  }
  summary.coefficients = c;
  summary.max_residual = max_residual(c, data);
  summary.converged = ok && summary.max_residual <= options.tolerance;
  summary.message =
      summary.converged
          ? fmt::format("Yld2000-2d: 8 equations solved, max residual {:.1e}", summary.max_residual)
          : fmt::format("Yld2000-2d: no coefficients reproduce the data (max residual {:.1e})",
                        summary.max_residual);
  return summary;
}

}  // namespace vs
