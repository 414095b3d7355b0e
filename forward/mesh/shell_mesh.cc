#include "mesh/shell_mesh.h"

#include <limits>
#include <stdexcept>

namespace vs::shell3d {

const std::vector<int>& ShellMesh::set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it == node_sets.end()) throw std::out_of_range("ShellMesh: no node set '" + name + "'");
  return it->second;
}

int ShellMesh::nearest_node(const Eigen::Vector3d& p) const {
  int best = -1;
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < num_nodes(); ++i) {
    const double di = (nodes[static_cast<std::size_t>(i)] - p).squaredNorm();
    if (di < d) {
      d = di;
      best = i;
    }
  }
  return best;
}

ShellMesh quad9_from_quad4(const std::vector<Eigen::Vector3d>& corners,
                           const std::vector<std::array<int, 4>>& quads, double thickness) {
  ShellMesh m;
  m.nodes = corners;
  std::map<std::pair<int, int>, int> edge_node;
  auto midside = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto it = edge_node.find(key);
    if (it != edge_node.end()) return it->second;
    const int id = m.num_nodes();
    m.nodes.push_back(
        0.5 * (corners[static_cast<std::size_t>(a)] + corners[static_cast<std::size_t>(b)]));
    edge_node.emplace(key, id);
    return id;
  };
  for (const auto& q : quads) {
    std::array<int, 9> e{};
    for (int k = 0; k < 4; ++k) e[static_cast<std::size_t>(k)] = q[static_cast<std::size_t>(k)];
    for (int k = 0; k < 4; ++k)
      e[static_cast<std::size_t>(4 + k)] =
          midside(q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)]);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += 0.25 * corners[static_cast<std::size_t>(q[k])];
    e[8] = m.num_nodes();
    m.nodes.push_back(c);
    m.elements.push_back(e);
  }
  m.thickness.assign(m.nodes.size(), thickness);
  return m;
}

}  // namespace vs::shell3d
