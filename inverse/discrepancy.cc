#include "discrepancy.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace vs {

DiscrepancySource learn_discrepancy(const DiscrepancySpec& spec,
                                    const std::vector<DataSet>& data_sets,
                                    const std::vector<RunResult>& runs) {
  DiscrepancySource source;
  source.name = spec.name;
  for (const auto& [address, value] : spec.set) {
    source.edits += fmt::format("{}{}={}", source.edits.empty() ? "" : " ", address, value);
  }
  for (const DataSet& d : data_sets) {
    const Measurement& m = d.measurement;
    const auto reference = std::find_if(spec.references.begin(), spec.references.end(),
                                        [&m](const auto& entry) { return entry.first == m.name; });
    if (reference == spec.references.end()) continue;
    const RunResult& run = runs.at(static_cast<std::size_t>(d.scene));
    const SimulatedCurve forward = simulate_curve(m, run, d.scene_spec.get());
    if (!forward.ok) {
      source.message = fmt::format(
          "discrepancy '{}': the forward run at its parameters gives no curve for {}: "
          "{}",
          spec.name, m.name, run.completed() ? forward.message : run.message);
      source.curves.clear();
      return source;
    }
    const Measurement& ref = reference->second;
    DiscrepancyCurve curve;
    curve.data = m.name;
    curve.file = ref.file;
    curve.unit = ordinate_unit(m.kind);
    double sum_sq = 0.0;
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      const double c = interpolate_table(ref.x, ref.y, m.x[i]) - forward.y[i];
      curve.correction.push_back(c);
      sum_sq += c * c;
      curve.max_abs = std::max(curve.max_abs, std::abs(c));
    }
    curve.rms = std::sqrt(sum_sq / static_cast<double>(m.x.size()));
    source.curves.push_back(std::move(curve));
  }
  source.ok = true;
  return source;
}

std::vector<std::vector<double>> mean_corrections(const std::vector<DiscrepancySource>& sources,
                                                  const std::vector<DataSet>& data_sets) {
  std::vector<std::vector<double>> mean(data_sets.size());
  for (std::size_t k = 0; k < data_sets.size(); ++k) {
    int count = 0;
    for (const DiscrepancySource& s : sources) {
      for (const DiscrepancyCurve& c : s.curves) {
        if (c.data != data_sets[k].measurement.name) continue;
        if (mean[k].empty()) mean[k].assign(c.correction.size(), 0.0);
        for (std::size_t i = 0; i < c.correction.size(); ++i) mean[k][i] += c.correction[i];
        ++count;
      }
    }
    for (double& v : mean[k]) v /= count;
  }
  return mean;
}

}  // namespace vs
