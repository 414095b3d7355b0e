#include "fd_jacobian.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vs {
namespace {

// A finite-difference formula for one parameter: d r / d x_j = sum_k coefficient_k r(x + offset_k
// e_j) / step. offset 0 refers to the known r(x). Ridders columns carry one formula per level.
struct Stencil {
  std::vector<double> offsets;
  std::vector<double> coefficients;
  double step = 0.0;
};

Stencil central(double h) { return {{-h, h}, {-0.5, 0.5}, h}; }

// Second-order one-sided: (-3 r0 + 4 r(h) - r(2h)) / 2h, mirrored for a negative h.
Stencil one_sided(double h) { return {{0.0, h, 2.0 * h}, {-1.5, 2.0, -0.5}, h}; }

// The stencils for parameter j: one per Ridders level, or a single one.
std::vector<Stencil> stencils_for(double x, double lower, double upper, double h,
                                  const FdOptions& options) {
  const double room_up = upper - x;
  const double room_down = x - lower;
  if (room_up >= h && room_down >= h) {
    if (options.method == FdMethod::kCentral) return {central(h)};
    std::vector<Stencil> levels;
    for (int k = 0; k < options.ridders_levels; ++k) levels.push_back(central(h / std::pow(2, k)));
    return levels;
  }
  if (room_up >= 2.0 * h) return {one_sided(h)};
  if (room_down >= 2.0 * h) return {one_sided(-h)};
  // The interval is narrower than the stencil: first order over the larger side.
  const double step = room_up >= room_down ? room_up : -room_down;
  if (step == 0.0) return {};
  return {{{0.0, step}, {-1.0, 1.0}, step}};
}

// Richardson tableau over the levels (error O(h^2), halving steps): the entry with the smallest
// change from its neighbours, as in Ridders' method.
Eigen::VectorXd ridders_extrapolate(const std::vector<Eigen::VectorXd>& estimates) {
  const std::size_t n = estimates.size();
  std::vector<std::vector<Eigen::VectorXd>> table(n);
  Eigen::VectorXd best = estimates.back();
  double best_error = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n; ++k) {
    table[k].push_back(estimates[k]);
    double factor = 1.0;
    for (std::size_t i = 1; i <= k; ++i) {
      factor *= 4.0;
      table[k].push_back((factor * table[k][i - 1] - table[k - 1][i - 1]) / (factor - 1.0));
      const double error = std::max((table[k][i] - table[k][i - 1]).norm(),
                                    (table[k][i] - table[k - 1][i - 1]).norm());
      if (error <= best_error) {
        best_error = error;
        best = table[k][i];
      }
    }
  }
  return best;
}

using ColumnValues = std::vector<std::optional<Eigen::VectorXd>>;

// Evaluates the non-zero offsets of every stencil of every parameter in one batch; returns,
// per parameter, the residuals in stencil/offset order.
std::vector<ColumnValues> run_stencils(const Eigen::VectorXd& x,
                                       const std::vector<std::vector<Stencil>>& stencils,
                                       const BatchResiduals& evaluate) {
  std::vector<Eigen::VectorXd> points;
  for (std::size_t j = 0; j < stencils.size(); ++j) {
    for (const auto& s : stencils[j]) {
      for (double offset : s.offsets) {
        if (offset == 0.0) continue;
        Eigen::VectorXd point = x;
        point[static_cast<Eigen::Index>(j)] += offset;
        points.push_back(point);
      }
    }
  }
  auto flat = evaluate(points);
  std::vector<ColumnValues> values(stencils.size());
  std::size_t next = 0;
  for (std::size_t j = 0; j < stencils.size(); ++j) {
    for (const auto& s : stencils[j]) {
      for (double offset : s.offsets) {
        if (offset != 0.0) values[j].push_back(std::move(flat.at(next++)));
      }
    }
  }
  return values;
}

enum class FailedSide { kNone, kUp, kDown };

// Which side of x had a failed evaluation (up wins if both did: one retry either way).
FailedSide failed_side(const std::vector<Stencil>& stencils, const ColumnValues& values) {
  std::size_t next = 0;
  FailedSide side = FailedSide::kNone;
  for (const auto& s : stencils) {
    for (double offset : s.offsets) {
      if (offset == 0.0) continue;
      if (!values.at(next++)) {
        if (offset > 0.0) return FailedSide::kUp;
        side = FailedSide::kDown;
      }
    }
  }
  return side;
}

}  // namespace

bool FdOptions::IsValid(std::string* why) const {
  if (!(relative_step > 0.0) || !(relative_step < 1.0)) {
    if (why) *why = "relative_step must be in (0, 1)";
    return false;
  }
  if (ridders_levels < 2 || ridders_levels > 10) {
    if (why) *why = "ridders_levels must be in [2, 10]";
    return false;
  }
  return true;
}

FdJacobian fd_jacobian(const Eigen::VectorXd& x, const Eigen::VectorXd& residual_at_x,
                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                       const Eigen::VectorXd& scale, const FdOptions& options,
                       const BatchResiduals& evaluate) {
  const Eigen::Index p = x.size();
  FdJacobian result;
  result.jacobian = Eigen::MatrixXd::Zero(residual_at_x.size(), p);

  // Collect every perturbed point of every parameter into one batch.
  std::vector<std::vector<Stencil>> stencils(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    stencils[j] = stencils_for(x[j], lower[j], upper[j], options.relative_step * scale[j], options);
  }
  auto values = run_stencils(x, stencils, evaluate);

  // A forward model that fails on one side (a region where the solver does not converge, just
  // past the current point) still has a derivative from the other side: retry those columns
  // one-sided, away from the failure, in a second batch.
  std::vector<Eigen::Index> retry;
  std::vector<std::vector<Stencil>> retry_stencils(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const FailedSide side = failed_side(stencils[j], values[j]);
    if (side == FailedSide::kNone) continue;
    const double h = options.relative_step * scale[j];
    const bool down_ok = x[j] - 2.0 * h >= lower[j];
    const bool up_ok = x[j] + 2.0 * h <= upper[j];
    if (side == FailedSide::kUp && down_ok) retry_stencils[j] = {one_sided(-h)};
    if (side == FailedSide::kDown && up_ok) retry_stencils[j] = {one_sided(h)};
    if (retry_stencils[j].empty()) {
      result.message = fmt::format("forward evaluation failed perturbing parameter {} ({})", j,
                                   side == FailedSide::kUp ? "upward" : "downward");
      return result;
    }
    retry.push_back(j);
  }
  if (!retry.empty()) {
    auto retried = run_stencils(x, retry_stencils, evaluate);
    for (Eigen::Index j : retry) {
      if (failed_side(retry_stencils[j], retried[j]) != FailedSide::kNone) {
        result.message =
            fmt::format("forward evaluation failed perturbing parameter {} either way", j);
        return result;
      }
      stencils[j] = retry_stencils[j];
      values[j] = retried[j];
    }
  }

  for (Eigen::Index j = 0; j < p; ++j) {
    std::vector<Eigen::VectorXd> estimates;
    std::size_t next = 0;
    for (const auto& s : stencils[j]) {
      Eigen::VectorXd derivative = Eigen::VectorXd::Zero(residual_at_x.size());
      for (std::size_t k = 0; k < s.offsets.size(); ++k) {
        const Eigen::VectorXd& r = s.offsets[k] == 0.0 ? residual_at_x : *values[j].at(next++);
        derivative += s.coefficients[k] * r;
      }
      estimates.push_back(derivative / s.step);
    }
    if (estimates.empty()) continue;  // lower == upper: the column stays zero
    result.jacobian.col(j) =
        estimates.size() == 1 ? estimates.front() : ridders_extrapolate(estimates);
  }
  result.ok = true;
  return result;
}

}  // namespace vs
