// ParaView output with plain-array interfaces (no solver types, so vs_output stays independent of
// the 3D shell library): an unstructured grid (.vtu, ASCII XML) with point and cell data, and a
// collection file (.pvd) that makes a series of them one time-dependent dataset. Output is
// deterministic (fixed number format, no timestamps).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vs {

// VTK cell type numbers used here.
inline constexpr std::uint8_t kVtkQuad = 9;
inline constexpr std::uint8_t kVtkBiquadraticQuad = 28;  // 4 corners, 4 midsides, centre

struct VtuGrid {
  std::vector<double> points;              // x, y, z per point
  std::vector<std::int64_t> connectivity;  // point indices of every cell, cell after cell
  std::vector<std::int64_t> offsets;       // end of each cell in connectivity
  std::vector<std::uint8_t> types;         // VTK cell type per cell
};

struct VtuField {
  std::string name;            // e.g. "thickness_mm"
  int components = 1;          // 1 (scalar) or 3 (vector)
  std::vector<double> values;  // components * count, point after point (or cell after cell)
};

// The .vtu document; throws std::invalid_argument if a field has the wrong size.
std::string render_vtu(const VtuGrid& grid, const std::vector<VtuField>& point_data,
                       const std::vector<VtuField>& cell_data);

struct PvdEntry {
  double time = 0.0;  // the series parameter (here: punch travel [mm])
  std::string file;   // relative to the .pvd file
};

std::string render_pvd(const std::vector<PvdEntry>& entries);

}  // namespace vs
