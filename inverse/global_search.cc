#include "global_search.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <stdexcept>
#include <vector>

namespace vs {
namespace {

struct SearchState {
  Objective* objective = nullptr;
  nlopt::opt* opt = nullptr;
  int max_evaluations = 0;
  GlobalSearchSummary* summary = nullptr;
  double worst_cost = 0.0;
  bool any_success = false;
};

// NLopt works on z = x / scale, in [lower/scale, upper/scale].
double nlopt_cost(const std::vector<double>& z, std::vector<double>& /*gradient*/, void* data) {
  auto* state = static_cast<SearchState*>(data);
  Objective& objective = *state->objective;
  const Eigen::VectorXd x =
      Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()))
          .cwiseProduct(objective.scale());
  GlobalSearchSummary& summary = *state->summary;
  // Some algorithms (CRS2's initial population) overrun maxeval slightly: the limit is a
  // promise to the user, so it is enforced here.
  if (summary.evaluations >= state->max_evaluations) {
    state->opt->force_stop();
    return std::isfinite(summary.cost) ? 10.0 * state->worst_cost + 1.0 : 1e20;
  }
  ++summary.evaluations;
  const auto evaluation = objective.evaluate(x);
  if (!evaluation->ok || !std::isfinite(evaluation->cost)) {
    ++summary.failed_evaluations;
    return state->any_success ? 10.0 * state->worst_cost + 1.0 : 1e20;
  }
  state->any_success = true;
  state->worst_cost = std::max(state->worst_cost, evaluation->cost);
  if (evaluation->cost < summary.cost) {
    summary.cost = evaluation->cost;
    summary.x = x;
  }
  return evaluation->cost;
}

const char* result_name(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
      return "SUCCESS";
    case nlopt::STOPVAL_REACHED:
      return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED:
      return "FTOL_REACHED";
    case nlopt::XTOL_REACHED:
      return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED:
      return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED:
      return "MAXTIME_REACHED";
    default:
      return "FAILURE";
  }
}

// The quadratic's basis at u: 1, u_i, and u_i u_j (i <= j).
Eigen::VectorXd quadratic_basis(const Eigen::VectorXd& u) {
  const Eigen::Index n = u.size();
  Eigen::VectorXd f(1 + n + n * (n + 1) / 2);
  Eigen::Index k = 0;
  f(k++) = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) f(k++) = u(i);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i; j < n; ++j) f(k++) = u(i) * u(j);
  return f;
}

// One round of the response surface: the grid of +- half_width scales around x0.
GlobalSearchSummary surface_round(Objective& objective, const Eigen::VectorXd& x0,
                                  const GlobalSearchOptions& options, double half_width) {
  const Eigen::Index n = objective.num_parameters();
  GlobalSearchSummary summary;
  summary.x = x0;
  summary.cost = std::numeric_limits<double>::infinity();
  // Grid coordinates u in [-1, 1] per parameter, x = x0 + u w (w the half width), clipped.
  Eigen::VectorXd lo(n), hi(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = half_width * objective.scale()(i);
    lo(i) = std::max(objective.lower()(i), x0(i) - w);
    hi(i) = std::min(objective.upper()(i), x0(i) + w);
  }
  auto to_x = [&](const Eigen::VectorXd& u) {
    return Eigen::VectorXd(0.5 * (lo + hi) + 0.5 * (hi - lo).cwiseProduct(u));
  };
  const int m = options.grid_points;
  long count = 1;
  for (Eigen::Index i = 0; i < n; ++i) count *= m;
  std::vector<Eigen::VectorXd> us, xs;
  for (long c = 0; c < count; ++c) {
    Eigen::VectorXd u(n);
    long rest = c;
    for (Eigen::Index i = 0; i < n; ++i) {
      u(i) = -1.0 + 2.0 * static_cast<double>(rest % m) / (m - 1);
      rest /= m;
    }
    us.push_back(u);
    xs.push_back(to_x(u));
  }
  const auto evaluations = objective.cache().evaluate_batch(xs);
  summary.evaluations = static_cast<int>(evaluations.size());
  std::vector<Eigen::VectorXd> good_u;
  std::vector<double> good_cost;
  for (std::size_t k = 0; k < evaluations.size(); ++k) {
    const auto& e = evaluations[k];
    if (!e->ok || !std::isfinite(e->cost)) {
      ++summary.failed_evaluations;
      continue;
    }
    good_u.push_back(us[k]);
    good_cost.push_back(e->cost);
    if (e->cost < summary.cost) {
      summary.cost = e->cost;
      summary.x = xs[k];
    }
  }
  const Eigen::Index terms = quadratic_basis(Eigen::VectorXd::Zero(n)).size();
  if (static_cast<Eigen::Index>(good_u.size()) < terms + 1) {
    summary.result =
        fmt::format("BEST_GRID_POINT (only {} of {} grid runs succeeded)", good_u.size(), count);
    return summary;
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(good_u.size()), terms);
  Eigen::VectorXd c(A.rows());
  for (Eigen::Index r = 0; r < A.rows(); ++r) {
    A.row(r) = quadratic_basis(good_u[static_cast<std::size_t>(r)]).transpose();
    c(r) = good_cost[static_cast<std::size_t>(r)];
  }
  const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(c);
  summary.surface_rms = std::sqrt((A * coef - c).squaredNorm() / static_cast<double>(A.rows()));
  Eigen::VectorXd g = coef.segment(1, n);
  Eigen::MatrixXd H(n, n);
  Eigen::Index k = 1 + n;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j, ++k) {
      H(i, j) = H(j, i) = (i == j ? 2.0 : 1.0) * coef(k);
    }
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(H);
  if (llt.info() != Eigen::Success) {
    summary.result = "BEST_GRID_POINT (the quadratic through the grid costs has no minimum)";
    return summary;
  }
  const Eigen::VectorXd u_star = (-llt.solve(g)).cwiseMax(-1.0).cwiseMin(1.0);
  const Eigen::VectorXd x_star = to_x(u_star);
  const auto e = objective.evaluate(x_star);
  ++summary.evaluations;
  if (!e->ok || !std::isfinite(e->cost)) {
    ++summary.failed_evaluations;
    summary.result = "BEST_GRID_POINT (the forward run at the quadratic's minimum failed)";
    return summary;
  }
  summary.x = x_star;
  summary.cost = e->cost;
  summary.result = "SURFACE_MINIMUM";
  return summary;
}

// surface_rounds rounds, each centred on the previous round's answer with half its half width.
GlobalSearchSummary surface_search(Objective& objective, const Eigen::VectorXd& x0,
                                   const GlobalSearchOptions& options) {
  GlobalSearchSummary summary;
  summary.x = x0;
  double half_width = options.grid_half_width;
  for (int round = 0; round < options.surface_rounds; ++round, half_width *= 0.5) {
    GlobalSearchSummary r = surface_round(objective, summary.x, options, half_width);
    r.evaluations += summary.evaluations;
    r.failed_evaluations += summary.failed_evaluations;
    if (options.surface_rounds > 1) {
      r.result = fmt::format("{} (round {} of {}, +- {:g} scales)", r.result, round + 1,
                             options.surface_rounds, half_width);
    }
    summary = r;
  }
  return summary;
}

}  // namespace

long surface_evaluations(const GlobalSearchOptions& options, int free_parameters) {
  long count = 1;
  for (int i = 0; i < free_parameters && count <= 100000; ++i) count *= options.grid_points;
  return static_cast<long>(options.surface_rounds) * (count + 1);
}

bool GlobalSearchOptions::IsValid(std::string* why) const {
  if (algorithm != "mlsl_lds" && algorithm != "crs2" && algorithm != "direct" &&
      algorithm != "bobyqa" && algorithm != "surface") {
    if (why)
      *why = fmt::format("unknown global algorithm '{}' (mlsl_lds, crs2, direct, bobyqa, surface)",
                         algorithm);
    return false;
  }
  if (grid_points < 3) {
    if (why) *why = "grid_points must be >= 3 (a quadratic needs three points per parameter)";
    return false;
  }
  if (surface_rounds < 1 || surface_rounds > 10) {
    if (why) *why = "surface_rounds must be in [1, 10]";
    return false;
  }
  if (!(grid_half_width > 0.0) || !std::isfinite(grid_half_width)) {
    if (why) *why = "grid_half_width must be > 0";
    return false;
  }
  if (max_evaluations < 1) {
    if (why) *why = "max_evaluations must be >= 1";
    return false;
  }
  if (!(local_relative_x_tolerance > 0.0)) {
    if (why) *why = "local_relative_x_tolerance must be > 0";
    return false;
  }
  return true;
}

GlobalSearchSummary global_search(Objective& objective, const Eigen::VectorXd& x0,
                                  const GlobalSearchOptions& options) {
  if (options.algorithm == "surface") return surface_search(objective, x0, options);
  const auto p = static_cast<unsigned>(objective.num_parameters());
  GlobalSearchSummary summary;
  summary.x = x0;
  summary.cost = std::numeric_limits<double>::infinity();

  nlopt::algorithm algorithm = nlopt::GN_MLSL_LDS;
  if (options.algorithm == "crs2") algorithm = nlopt::GN_CRS2_LM;
  if (options.algorithm == "direct") algorithm = nlopt::GN_DIRECT_L;
  if (options.algorithm == "bobyqa") algorithm = nlopt::LN_BOBYQA;
  nlopt::opt opt(algorithm, p);

  std::vector<double> lower(p), upper(p), z(p);
  for (unsigned i = 0; i < p; ++i) {
    lower[i] = objective.lower()[i] / objective.scale()[i];
    upper[i] = objective.upper()[i] / objective.scale()[i];
    z[i] = x0[i] / objective.scale()[i];
  }
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_maxeval(options.max_evaluations);
  if (algorithm == nlopt::GN_MLSL_LDS) {
    nlopt::opt local(nlopt::LN_BOBYQA, p);
    local.set_xtol_rel(options.local_relative_x_tolerance);
    opt.set_local_optimizer(local);
  }
  if (algorithm == nlopt::LN_BOBYQA) opt.set_xtol_rel(options.local_relative_x_tolerance);

  SearchState state{&objective, &opt, options.max_evaluations, &summary};
  opt.set_min_objective(nlopt_cost, &state);
  nlopt::srand(options.seed);
  double best = 0.0;
  try {
    summary.result = result_name(opt.optimize(z, best));
  } catch (const nlopt::forced_stop&) {
    summary.result = "MAXEVAL_REACHED";
  } catch (const std::exception& e) {
    // Round-off or a forced stop: the best point seen so far is still the answer.
    summary.result = fmt::format("STOPPED ({})", e.what());
  }
  return summary;
}

}  // namespace vs
