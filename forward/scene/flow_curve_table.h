// Tabulated flow curves for hardening law "table": the point rules shared by the inline
// `table = [[strain, stress], ...]` and by CSV files, and the strict CSV reader.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vs {

struct FlowCurveTable {
  std::vector<double> strain;      // effective plastic strain, strictly increasing from 0
  std::vector<double> stress_MPa;  // > 0
};

// Why (strain, stress) cannot follow the points already in `curve`, or "" if it can.
std::string flow_curve_point_problem(const FlowCurveTable& curve, double strain, double stress);

// Most points a flow curve may have (inline or from a file): far beyond any measured curve, and
// small enough that the curve fits inline in a scene file (scene.toml of a run folder echoes it;
// 100 000 points are ~4 MB of the 16 MiB a scene file may have).
inline constexpr std::size_t kMaxFlowCurvePoints = 100000;

// Why a complete curve is unusable (too few or too many points), or "".
std::string flow_curve_size_problem(const FlowCurveTable& curve);

// Reads a CSV curve: optional '#' comment lines and blank lines, the header
// `plastic_strain,stress_MPa`, then one `strain,stress` row per line. Any malformed line raises
// InputError "FILE:LINE: message".
FlowCurveTable read_flow_curve_csv(const std::string& path);

}  // namespace vs
