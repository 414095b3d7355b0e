#include "tensile_fit.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

#include "core/error.h"
#include "material/hardening.h"

namespace vs {

namespace {

std::string trim(std::string s) {
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '"'; };
  while (!s.empty() && is_space(s.back())) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  return s.substr(i);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

double parse_number(const std::string& cell, const std::string& where, const char* column) {
  double value = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, value);
  if (cell.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: {} is not a finite number: \"{}\"", where, column, cell));
  }
  return value;
}

}  // namespace

TensileCurve read_tensile_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the tensile curve");
  static const char* kColumns[] = {"Time", "Estrain", "Estress", "Tstrain", "Tstress"};
  TensileCurve curve;
  curve.source = path;
  std::string text;
  int line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    const std::string where = fmt::format("{}:{}", path, line_no);
    if (trim(text).empty()) continue;
    const std::vector<std::string> cells = split(text);
    if (line_no == 1) {
      bool ok = cells.size() == 5;
      for (std::size_t i = 0; ok && i < 5; ++i) ok = cells[i] == kColumns[i];
      if (!ok) {
        throw InputError(where +
                         ": expected the header Time,Estrain,Estress,Tstrain,Tstress (s, -, MPa, "
                         "-, MPa), got \"" +
                         trim(text) + "\"");
      }
      continue;
    }
    if (cells.size() != 5) {
      throw InputError(fmt::format("{}: expected 5 values, got {}", where, cells.size()));
    }
    curve.line.push_back(line_no);
    curve.time_s.push_back(parse_number(cells[0], where, kColumns[0]));
    curve.eng_strain.push_back(parse_number(cells[1], where, kColumns[1]));
    curve.eng_stress_MPa.push_back(parse_number(cells[2], where, kColumns[2]));
    curve.true_strain.push_back(parse_number(cells[3], where, kColumns[3]));
    curve.true_stress_MPa.push_back(parse_number(cells[4], where, kColumns[4]));
  }
  if (line_no == 0) throw InputError(path + ":1: empty file");
  if (curve.time_s.size() < 10) {
    throw InputError(fmt::format("{}:{}: only {} data rows, need at least 10", path, line_no,
                                 curve.time_s.size()));
  }
  return curve;
}

namespace {

// First row whose engineering strain has fallen more than `drop` below its running maximum (a
// load reversal, e.g. a tension-compression-tension test), or -1.
int first_reversal(const TensileCurve& curve, double drop) {
  double running_max = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < curve.eng_strain.size(); ++i) {
    running_max = std::max(running_max, curve.eng_strain[i]);
    if (curve.eng_strain[i] < running_max - drop) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

FitRange select_fit_range(const TensileCurve& curve, const TensileFitOptions& options) {
  if (!(options.elastic_modulus_MPa > 0.0)) throw InputError("elastic modulus must be > 0 MPa");
  FitRange range;
  const auto& es = curve.eng_stress_MPa;
  const int n = static_cast<int>(es.size());
  const auto plastic = [&](int i) {
    return curve.true_strain[i] - curve.true_stress_MPa[i] / options.elastic_modulus_MPa;
  };
  const auto argmax = [&](int end) {
    return static_cast<int>(std::max_element(es.begin(), es.begin() + end) - es.begin());
  };
  range.max_load_row = argmax(n);
  const int m = range.max_load_row;
  range.max_load_true_strain = curve.true_strain[m];
  range.max_load_plastic_strain = plastic(m);
  range.max_load_true_stress_MPa = curve.true_stress_MPa[m];
  range.max_load_eng_stress_MPa = es[m];
  range.reversal_row = first_reversal(curve, 1e-3);
  int last = m;
  if (range.reversal_row >= 0) {
    // Only the first (virgin) tension branch: up to its highest stress, before the unloading.
    last = argmax(range.reversal_row);
    range.max_load_after_reversal = m > range.reversal_row;
    range.warnings.push_back(fmt::format(
        "{}:{}: the strain reverses (load reversal, e.g. a tension-compression test); only the "
        "first tension branch up to line {} (true strain {:.4f}) is fitted, and the load maximum "
        "at line {} (true strain {:.4f}) comes after the reversal, so it is not the uniform "
        "strain of monotonic tension",
        curve.source, curve.line[range.reversal_row], curve.line[last], curve.true_strain[last],
        curve.line[m], range.max_load_true_strain));
  }
  range.end_true_strain = curve.true_strain[last];
  if (options.max_true_strain > 0.0) {
    if (options.max_true_strain > range.end_true_strain) {
      const std::string what =
          range.reversal_row >= 0
              ? fmt::format(
                    "{}:{}: max strain {} is past the end of the first tension branch "
                    "(true strain {:.4f}): the load reverses there",
                    curve.source, curve.line[last], options.max_true_strain, range.end_true_strain)
              : fmt::format(
                    "{}:{}: max strain {} is past the load maximum (true strain {:.4f}, "
                    "engineering stress {:.1f} MPa): the specimen necks there and the "
                    "true stress is no longer uniaxial",
                    curve.source, curve.line[m], options.max_true_strain,
                    range.max_load_true_strain, es[m]);
      if (!options.allow_past_maximum || range.reversal_row >= 0) {
        throw InputError(what + (range.reversal_row >= 0
                                     ? "; a hardening law cannot be fitted across a reversal"
                                     : "; pass --allow-past-maximum to fit anyway"));
      }
      range.warnings.push_back(what + "; fitted anyway (--allow-past-maximum)");
      last = n - 1;
    }
    while (last >= 0 && curve.true_strain[last] > options.max_true_strain) --last;
  }
  int first = 0;
  while (first <= last && plastic(first) <= options.min_plastic_strain) ++first;
  for (int i = first; i <= last; ++i) {
    if (plastic(i) <= options.min_plastic_strain) continue;
    range.rows.push_back(i);
    range.true_strain.push_back(curve.true_strain[i]);
    range.plastic_strain.push_back(plastic(i));
    range.true_stress_MPa.push_back(curve.true_stress_MPa[i]);
  }
  if (range.rows.size() < 5) {
    throw InputError(
        fmt::format("{}: only {} points between yield (plastic strain > {}) and the "
                    "end of the fitted range; need at least 5",
                    curve.source, range.rows.size(), options.min_plastic_strain));
  }
  return range;
}

std::string fit_law_name(FitLaw law) {
  switch (law) {
    case FitLaw::kSwift:
      return "swift";
    case FitLaw::kVoce:
      return "voce";
    case FitLaw::kHollomon:
      return "hollomon";
  }
  return "?";
}

FitLaw parse_fit_law(const std::string& name) {
  for (FitLaw law : {FitLaw::kSwift, FitLaw::kVoce, FitLaw::kHollomon}) {
    if (name == fit_law_name(law)) return law;
  }
  throw InputError("unknown hardening law \"" + name + "\": expected swift, voce, hollomon or all");
}

namespace {

struct Point {
  double e, s;
};

struct SwiftResidual : Point {
  template <typename T>
  bool operator()(const T* p, T* r) const {
    r[0] = p[0] * ceres::pow(p[1] + T(e), p[2]) - T(s);
    return true;
  }
};
struct VoceResidual : Point {
  template <typename T>
  bool operator()(const T* p, T* r) const {
    r[0] = p[0] + p[1] * (T(1.0) - ceres::exp(-p[2] * T(e))) - T(s);
    return true;
  }
};
struct HollomonResidual : Point {
  template <typename T>
  bool operator()(const T* p, T* r) const {
    r[0] = p[0] * ceres::pow(T(e), p[1]) - T(s);
    return true;
  }
};

// Least-squares line y = a + b x; returns the sum of squared residuals.
double line_fit(const std::vector<double>& x, const std::vector<double>& y, double* a, double* b) {
  const double m = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  }
  *b = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  *a = (sy - *b * sx) / m;
  double sse = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sse += std::pow(*a + *b * x[i] - y[i], 2);
  return sse;
}

// Starting values from linearised fits (log-log for the power laws, a scan over b for Voce).
std::vector<double> initial_guess(FitLaw law, const std::vector<double>& e,
                                  const std::vector<double>& s) {
  std::vector<double> ls(s.size()), x(e.size());
  for (std::size_t i = 0; i < s.size(); ++i) ls[i] = std::log(s[i]);
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> guess;
  double a = 0, b = 0;
  if (law == FitLaw::kHollomon) {
    for (std::size_t i = 0; i < e.size(); ++i) x[i] = std::log(e[i]);
    line_fit(x, ls, &a, &b);
    return {std::exp(a), b};
  }
  if (law == FitLaw::kSwift) {
    for (double eps0 : {1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1}) {
      for (std::size_t i = 0; i < e.size(); ++i) x[i] = std::log(eps0 + e[i]);
      const double sse = line_fit(x, ls, &a, &b);
      if (sse < best) best = sse, guess = {std::exp(a), eps0, b};
    }
    if (guess.empty()) guess = {2.0 * s.back(), 0.01, 0.2};
    return guess;
  }
  for (double rate : {0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0}) {
    for (std::size_t i = 0; i < e.size(); ++i) x[i] = 1.0 - std::exp(-rate * e[i]);
    const double sse = line_fit(x, s, &a, &b);
    if (sse < best && b > 0) best = sse, guess = {a, b, rate};
  }
  if (guess.empty()) guess = {s.front(), s.back() - s.front() + 1.0, 10.0};
  return guess;
}

template <typename Functor, int N>
void add_residuals(ceres::Problem& problem, double* p, const std::vector<double>& e,
                   const std::vector<double>& s) {
  for (std::size_t i = 0; i < e.size(); ++i) {
    Functor f;
    f.e = e[i];
    f.s = s[i];
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Functor, 1, N>(new Functor(f)),
                             nullptr, p);
  }
}

}  // namespace

bool considere_point(const HardeningSpec& spec, double elastic_modulus_MPa, double* plastic_strain,
                     double* true_strain) {
  const Hardening h(spec);
  // g > 0 while hardening outruns the stress; the load maximum is the first + to - change.
  const auto g = [&](double ep) {
    const double slope = h.slope(ep);
    return slope / (1.0 + slope / elastic_modulus_MPa) - h.flow_stress(ep);
  };
  double prev = 1e-7;
  bool positive = g(prev) > 0.0;
  for (double ep = 1e-4; ep <= 5.0; ep += 1e-4) {
    const double value = g(ep);
    if (positive && value <= 0.0) {
      double lo = prev, hi = ep;
      for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) > 0.0 ? lo : hi) = mid;
      }
      *plastic_strain = 0.5 * (lo + hi);
      *true_strain = *plastic_strain + h.flow_stress(*plastic_strain) / elastic_modulus_MPa;
      return true;
    }
    positive = value > 0.0;
    prev = ep;
  }
  return false;
}

LawFit fit_hardening_law(FitLaw law, const std::vector<double>& e, const std::vector<double>& s,
                         double elastic_modulus_MPa) {
  LawFit fit;
  fit.law = law;
  std::vector<double> p = initial_guess(law, e, s);
  std::vector<std::string> names;
  std::vector<double> lower, upper;
  ceres::Problem problem;
  switch (law) {
    case FitLaw::kSwift:
      add_residuals<SwiftResidual, 3>(problem, p.data(), e, s);
      names = {"K_MPa", "eps0", "n"};
      lower = {1.0, 1e-9, 1e-4};
      upper = {1e5, 1.0, 2.0};
      break;
    case FitLaw::kVoce:
      add_residuals<VoceResidual, 3>(problem, p.data(), e, s);
      names = {"sigma0_MPa", "Q_MPa", "b"};
      lower = {0.0, 0.0, 1e-3};
      upper = {1e5, 1e5, 1e4};
      break;
    case FitLaw::kHollomon:
      add_residuals<HollomonResidual, 2>(problem, p.data(), e, s);
      names = {"K_MPa", "n"};
      lower = {1.0, 1e-4};
      upper = {1e5, 2.0};
      break;
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[i] = std::clamp(p[i], lower[i], upper[i]);
    problem.SetParameterLowerBound(p.data(), static_cast<int>(i), lower[i]);
    problem.SetParameterUpperBound(p.data(), static_cast<int>(i), upper[i]);
  }
  ceres::Solver::Options options;
  options.max_num_iterations = 500;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  options.linear_solver_type = ceres::DENSE_QR;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  fit.termination = ceres::TerminationTypeToString(summary.termination_type);

  double cost = 0.0;
  std::vector<double> residuals;
  ceres::CRSMatrix crs;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, &residuals, nullptr, &crs);
  const int m = static_cast<int>(residuals.size());
  const int np = static_cast<int>(p.size());
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(m, np);
  for (int r = 0; r < crs.num_rows; ++r) {
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k) jac(r, crs.cols[k]) = crs.values[k];
  }
  Eigen::VectorXd values(np), scale(np), lo(np), hi(np);
  for (int i = 0; i < np; ++i) {
    values[i] = p[i];
    scale[i] = std::abs(p[i]) > 0.0 ? std::abs(p[i]) : 1.0;
    lo[i] = lower[i];
    hi[i] = upper[i];
  }
  fit.uncertainty = estimate_uncertainty(jac, cost, values, scale, lo, hi, names, {});

  double rss = 0.0;
  fit.fitted_MPa.resize(e.size());
  for (int i = 0; i < m; ++i) {
    fit.fitted_MPa[i] = s[i] + residuals[i];
    rss += residuals[i] * residuals[i];
    fit.max_abs_residual_MPa = std::max(fit.max_abs_residual_MPa, std::abs(residuals[i]));
  }
  fit.rms_MPa = std::sqrt(rss / m);
  fit.aic = m * std::log(std::max(rss, 1e-300) / m) + 2.0 * np;

  HardeningSpec& spec = fit.spec;
  if (law == FitLaw::kSwift) {
    spec.law = HardeningLaw::kSwift;
    spec.K_MPa = p[0], spec.eps0 = p[1], spec.n = p[2];
  } else if (law == FitLaw::kVoce) {
    spec.law = HardeningLaw::kVoce;
    spec.sigma0_MPa = p[0], spec.Q_MPa = p[1], spec.b = p[2];
  } else {
    spec.law = HardeningLaw::kHollomon;
    spec.K_MPa = p[0], spec.n = p[1];
    // Initial yield plateau: the fitted curve at the first fitted point (not a free parameter).
    spec.sigma0_MPa = p[0] * std::pow(e.front(), p[1]);
  }
  fit.considere_found = considere_point(spec, elastic_modulus_MPa, &fit.considere_plastic_strain,
                                        &fit.considere_true_strain);
  return fit;
}

}  // namespace vs
