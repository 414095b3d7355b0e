#include "material/yld2000.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "material/dual_potential.h"

namespace vs {
namespace {

// q = ((Xxx - Xyy)/2)^2 + Xxy^2, its gradient and (constant) Hessian Q.
double q_of(const PlaneVector& X) {
  const double h = 0.5 * (X(0) - X(1));
  return h * h + X(2) * X(2);
}
PlaneVector q_gradient(const PlaneVector& X) {
  const double h = 0.5 * (X(0) - X(1));
  return {h, -h, 2.0 * X(2)};
}
PlaneMatrix q_hessian() {
  PlaneMatrix Q;
  Q << 0.5, -0.5, 0.0, -0.5, 0.5, 0.0, 0.0, 0.0, 2.0;
  return Q;
}

// |y|^p with the limits of the series at y = 0 (0^0 = 1; negative powers only ever multiply a
// vanishing coefficient there, see u_series). An integer p (the exponents 6 and 8 of steel and
// aluminium, and the exponents of the series and the derivatives derived from them) by repeated
// squaring: std::pow was a third of a Yld2000-2d cup's run time (perf, the TUAT cup).
double abs_pow(double y, double p) {
  const double ay = std::abs(y);
  if (p == std::floor(p) && std::abs(p) <= 64.0) {
    auto n = static_cast<int>(std::abs(p));
    double r = 1.0, b = ay;
    for (; n > 0; n >>= 1, b *= b) {
      if (n & 1) r *= b;
    }
    return p < 0.0 ? 1.0 / r : r;
  }
  return std::pow(ay, p);
}
double sign(double y) { return y > 0.0 ? 1.0 : (y < 0.0 ? -1.0 : 0.0); }

// |y|^(p-2), |y|^(p-1), |y|^p for p >= 2 from one power and two products (0^0 = 1 at y = 0).
struct AbsPowers {
  double pm2, pm1, p;
};
AbsPowers abs_powers(double y, double p) {
  const double ay = std::abs(y);
  const double pm2 = abs_pow(ay, p - 2.0);
  return {pm2, pm2 * ay, pm2 * ay * ay};
}

// u(x, q) = |x - sqrt(q)|^a + |x + sqrt(q)|^a and its derivatives in x and q.
struct U {
  double value = 0.0, x = 0.0, q = 0.0, xx = 0.0, xq = 0.0, qq = 0.0;
};

// Binomial series (sqrt(q) < |x|, or x = q = 0): u = 2 sum_k C(a, 2k) |x|^(a-2k) q^k.
U u_series(double a, double x, double q) {
  U u;
  const double ax = std::abs(x);
  const double sx = sign(x);
  double binom = 1.0;  // C(a, 2k)
  double qk = 1.0;     // q^k
  double qk1 = 0.0;    // q^(k-1)
  double qk2 = 0.0;    // q^(k-2)
  auto power = [ax](double p) { return (ax == 0.0 && p < 0.0) ? 0.0 : abs_pow(ax, p); };
  for (int k = 0; k <= 12; ++k) {
    if (k > 0) {
      binom *= (a - (2.0 * k - 2.0)) * (a - (2.0 * k - 1.0)) / ((2.0 * k - 1.0) * (2.0 * k));
      qk2 = qk1;
      qk1 = qk;
      qk *= q;
    }
    if (binom == 0.0) break;  // even integer a: the series ends
    const double p = a - 2.0 * k;
    const double c = 2.0 * binom;
    // |x|^p, |x|^(p-1), |x|^(p-2) (one power for x != 0).
    const double pm2 = power(p - 2.0);
    const double pm1 = ax > 0.0 ? pm2 * ax : power(p - 1.0);
    const double p0 = ax > 0.0 ? pm1 * ax : power(p);
    u.value += c * p0 * qk;
    u.x += c * p * pm1 * sx * qk;
    u.xx += c * p * (p - 1.0) * pm2 * qk;
    u.q += c * k * p0 * qk1;
    u.xq += c * k * p * pm1 * sx * qk1;
    u.qq += c * k * (k - 1.0) * p0 * qk2;
  }
  return u;
}

// Closed form for sqrt(q) >= |x| / 10 (q > 0).
U u_closed(double a, double x, double q) {
  U u;
  const double D = std::sqrt(q);
  const double yp = x + D;
  const double ym = x - D;
  const AbsPowers pp = abs_powers(yp, a), pm = abs_powers(ym, a);
  const double h1p = a * pp.pm1 * sign(yp);
  const double h1m = a * pm.pm1 * sign(ym);
  const double h2p = a * (a - 1.0) * pp.pm2;
  const double h2m = a * (a - 1.0) * pm.pm2;
  u.value = pp.p + pm.p;
  u.x = h1p + h1m;
  u.xx = h2p + h2m;
  const double uD = h1p - h1m;   // du/dsqrt(q)
  const double uDD = h2p + h2m;  // d2u/dsqrt(q)^2
  const double uxD = h2p - h2m;  // d2u/dx dsqrt(q)
  u.q = uD / (2.0 * D);
  u.xq = uxD / (2.0 * D);
  u.qq = (uDD * D - uD) / (4.0 * D * D * D);
  return u;
}

U u_of(double a, double x, double q) {
  return (q <= 0.01 * x * x) ? u_series(a, x, q) : u_closed(a, x, q);
}

// Phi = phi'(L' s) + phi''(L'' s) with gradient and Hessian in s.
struct PhiPoint {
  double value = 0.0;
  PlaneVector gradient = PlaneVector::Zero();
  PlaneMatrix hessian = PlaneMatrix::Zero();
};

PhiPoint phi_of(double a, const PlaneMatrix& L1, const PlaneMatrix& L2, const PlaneVector& s,
                bool derivatives) {
  PhiPoint out;
  const PlaneMatrix Q = q_hessian();
  // phi' = (4 q')^(a/2) = 2^a q'^(a/2).
  {
    const PlaneVector X = L1 * s;
    const double q = q_of(X);
    const double c = abs_pow(2.0, a);
    // q^(a/2-2), q^(a/2-1), q^(a/2) (q > 0; a >= 2, so q^(a/2) = 0 at q = 0).
    const double qm2 = q > 0.0 ? abs_pow(q, 0.5 * a - 2.0) : 0.0;
    const double qm1 = q > 0.0 ? qm2 * q : 0.0;
    out.value += q > 0.0 ? c * qm1 * q : 0.0;
    if (derivatives) {
      // phi'_q = 2^a (a/2) q^(a/2-1): at q = 0 it is 4 for a = 2 and 0 for a > 2; the phi'_qq term
      // multiplies grad q grad q^T = O(q) and vanishes at q = 0 for a > 2 (is 0 for a = 2).
      const double pq = q > 0.0 ? c * 0.5 * a * qm1 : (a == 2.0 ? 4.0 : 0.0);
      const double pqq = q > 0.0 ? c * 0.5 * a * (0.5 * a - 1.0) * qm2 : 0.0;
      const PlaneVector gq = q_gradient(X);
      const PlaneVector gX = pq * gq;
      const PlaneMatrix hX = pq * Q + pqq * gq * gq.transpose();
      out.gradient += L1.transpose() * gX;
      out.hessian += L1.transpose() * hX * L1;
    }
  }
  // phi'' = u(3T, q'').
  {
    const PlaneVector X = L2 * s;
    const double q = q_of(X);
    const double x = 1.5 * (X(0) + X(1));
    const U u = u_of(a, x, q);
    out.value += u.value;
    if (derivatives) {
      const PlaneVector gx(1.5, 1.5, 0.0);
      const PlaneVector gq = q_gradient(X);
      const PlaneVector gX = u.x * gx + u.q * gq;
      const PlaneMatrix cross = gx * gq.transpose();
      const PlaneMatrix hX = u.xx * gx * gx.transpose() + u.xq * (cross + cross.transpose()) +
                             u.qq * gq * gq.transpose() + u.q * Q;
      out.gradient += L2.transpose() * gX;
      out.hessian += L2.transpose() * hX * L2;
    }
  }
  return out;
}

}  // namespace

Yld2000::Yld2000(const Yld2000Coefficients& c) : c_(c) {
  const double a = c.exponent;
  if (!(a >= 2.0) || !std::isfinite(a)) {
    throw InputError("Yld2000: exponent a must be >= 2 (8 for aluminium, 6 for steel), got " +
                     std::to_string(a));
  }
  for (int i = 0; i < 8; ++i) {
    if (!std::isfinite(c.alpha[i])) {
      throw InputError("Yld2000: alpha" + std::to_string(i + 1) + " is not finite");
    }
  }
  const auto& al = c.alpha;
  L1_ << 2.0 * al[0] / 3.0, -al[0] / 3.0, 0.0,  //
      -al[1] / 3.0, 2.0 * al[1] / 3.0, 0.0,     //
      0.0, 0.0, al[6];
  L2_ << (-2.0 * al[2] + 2.0 * al[3] + 8.0 * al[4] - 2.0 * al[5]) / 9.0,
      (al[2] - 4.0 * al[3] - 4.0 * al[4] + 4.0 * al[5]) / 9.0, 0.0,
      (4.0 * al[2] - 4.0 * al[3] - 4.0 * al[4] + al[5]) / 9.0,
      (-2.0 * al[2] + 8.0 * al[3] + 2.0 * al[4] - 2.0 * al[5]) / 9.0, 0.0,  //
      0.0, 0.0, al[7];
}

double Yld2000::effective_stress(const PlaneVector& s) const {
  const double scale = s.cwiseAbs().maxCoeff();
  if (scale == 0.0) return 0.0;
  const PhiPoint p = phi_of(c_.exponent, L1_, L2_, s / scale, false);
  return scale * std::pow(0.5 * p.value, 1.0 / c_.exponent);
}

YieldPoint Yld2000::evaluate(const PlaneVector& s) const {
  YieldPoint out;
  const double scale = s.cwiseAbs().maxCoeff();
  if (scale == 0.0) return out;
  const double a = c_.exponent;
  const PhiPoint p = phi_of(a, L1_, L2_, s / scale, true);
  if (!(p.value > 0.0)) return out;  // s in the null space of both transformations
  const double sb = std::pow(0.5 * p.value, 1.0 / a);  // sigma_bar of the scaled stress
  const double f = sb / (a * p.value);
  out.value = scale * sb;
  out.gradient = f * p.gradient;
  out.hessian =
      (f / scale) * (p.hessian + ((1.0 / a - 1.0) / p.value) * p.gradient * p.gradient.transpose());
  return out;
}

DualPoint Yld2000::dual(const PlaneVector& d, const PlaneVector* guess) const {
  return solve_dual(*this, d, guess);
}

}  // namespace vs
