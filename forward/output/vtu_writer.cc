#include "output/vtu_writer.h"

#include <fmt/format.h>

#include <stdexcept>

#include "output/number_format.h"
#include "output/svg_plot.h"

namespace vs {

namespace {

void check_size(const VtuField& f, std::size_t count, const char* where) {
  if (f.components < 1 || f.values.size() != count * static_cast<std::size_t>(f.components)) {
    throw std::invalid_argument(fmt::format("VTU {} field '{}': {} values for {} entries x {}",
                                            where, f.name, f.values.size(), count, f.components));
  }
}

void append_fields(std::string& out, const std::vector<VtuField>& fields) {
  for (const VtuField& f : fields) {
    out += fmt::format(
        "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
        "format=\"ascii\">\n          ",
        xml_escape(f.name), f.components);
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      out += format_number(f.values[i]);
      out += (i + 1) % 9 == 0 && i + 1 < f.values.size() ? "\n          " : " ";
    }
    out += "\n        </DataArray>\n";
  }
}

}  // namespace

std::string render_vtu(const VtuGrid& grid, const std::vector<VtuField>& point_data,
                       const std::vector<VtuField>& cell_data) {
  const std::size_t np = grid.points.size() / 3, nc = grid.types.size();
  if (grid.points.size() != 3 * np || grid.offsets.size() != nc) {
    throw std::invalid_argument("VTU grid: inconsistent points / offsets / types");
  }
  for (const VtuField& f : point_data) check_size(f, np, "point");
  for (const VtuField& f : cell_data) check_size(f, nc, "cell");
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  out += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", np, nc);
  out += "      <PointData>\n";
  append_fields(out, point_data);
  out += "      </PointData>\n      <CellData>\n";
  append_fields(out, cell_data);
  out += "      </CellData>\n      <Points>\n";
  append_fields(out, {VtuField{"Points", 3, grid.points}});
  out += "      </Points>\n      <Cells>\n";
  out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (std::int64_t c : grid.connectivity) out += fmt::format(" {}", c);
  out += "\n        </DataArray>\n";
  out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for (std::int64_t o : grid.offsets) out += fmt::format(" {}", o);
  out += "\n        </DataArray>\n";
  out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n         ";
  for (std::uint8_t t : grid.types) out += fmt::format(" {}", static_cast<int>(t));
  out +=
      "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string render_pvd(const std::vector<PvdEntry>& entries) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const PvdEntry& e : entries) {
    out += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       format_number(e.time), xml_escape(e.file));
  }
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

}  // namespace vs
