#include "global_search.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <stdexcept>

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

}  // namespace

bool GlobalSearchOptions::IsValid(std::string* why) const {
  if (algorithm != "mlsl_lds" && algorithm != "crs2" && algorithm != "direct" &&
      algorithm != "bobyqa") {
    if (why)
      *why =
          fmt::format("unknown global algorithm '{}' (mlsl_lds, crs2, direct, bobyqa)", algorithm);
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
