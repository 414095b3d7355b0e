#include "mesh/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace vs::shell3d {

ShellMesh structured_block(int nu, int nv, const SurfaceMap& map, const SurfaceMap& normal,
                           double thickness) {
  ShellMesh m;
  const int Nu = 2 * nu + 1, Nv = 2 * nv + 1;
  auto id = [Nu](int i, int j) { return j * Nu + i; };
  for (int j = 0; j < Nv; ++j)
    for (int i = 0; i < Nu; ++i) {
      const double u = static_cast<double>(i) / (Nu - 1), v = static_cast<double>(j) / (Nv - 1);
      m.nodes.push_back(map(u, v));
      if (normal) m.exact_normal.push_back(normal(u, v).normalized());
    }
  for (int ej = 0; ej < nv; ++ej)
    for (int ei = 0; ei < nu; ++ei) {
      const int i = 2 * ei, j = 2 * ej;
      m.elements.push_back({id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i, j + 2), id(i + 1, j),
                            id(i + 2, j + 1), id(i + 1, j + 2), id(i, j + 1), id(i + 1, j + 1)});
    }
  m.thickness.assign(m.nodes.size(), thickness);
  for (int i = 0; i < Nu; ++i) {
    m.node_sets["v0"].push_back(id(i, 0));
    m.node_sets["v1"].push_back(id(i, Nv - 1));
  }
  for (int j = 0; j < Nv; ++j) {
    m.node_sets["u0"].push_back(id(0, j));
    m.node_sets["u1"].push_back(id(Nu - 1, j));
  }
  return m;
}

namespace {
void rename_set(ShellMesh* m, const std::string& from, const std::string& to) {
  auto node = m->node_sets.extract(from);
  node.key() = to;
  m->node_sets.insert(std::move(node));
}
}  // namespace

ShellMesh rectangular_plate(double lx, double ly, int nx, int ny, double thickness) {
  ShellMesh m = structured_block(
      nx, ny, [=](double u, double v) { return Eigen::Vector3d(u * lx, v * ly, 0.0); },
      [](double, double) { return Eigen::Vector3d::UnitZ(); }, thickness);
  rename_set(&m, "u0", "x0");
  rename_set(&m, "u1", "x1");
  rename_set(&m, "v0", "y0");
  rename_set(&m, "v1", "y1");
  return m;
}

ShellMesh cylinder_patch(double r, double y0, double y1, double theta0, double theta1, int n_axial,
                         int n_circ, double thickness) {
  // u: circumferential, v: axial; g_theta x g_y = (r cos, 0, -r sin) x (0, 1, 0) = outward.
  auto angle = [=](double u) { return theta0 + u * (theta1 - theta0); };
  ShellMesh m = structured_block(
      n_circ, n_axial,
      [=](double u, double v) {
        const double t = angle(u);
        return Eigen::Vector3d(r * std::sin(t), y0 + v * (y1 - y0), r * std::cos(t));
      },
      [=](double u, double) {
        const double t = angle(u);
        return Eigen::Vector3d(std::sin(t), 0.0, std::cos(t));
      },
      thickness);
  rename_set(&m, "u0", "theta0");
  rename_set(&m, "u1", "theta1");
  rename_set(&m, "v0", "y0");
  rename_set(&m, "v1", "y1");
  return m;
}

ShellMesh sphere_patch(double r, double p0, double p1, double a0, double a1, int n_polar,
                       int n_azimuth, double thickness) {
  // u: polar, v: azimuth; g_p x g_a is outward for p in (0, pi).
  auto dir = [=](double u, double v) {
    const double p = p0 + u * (p1 - p0), a = a0 + v * (a1 - a0);
    return Eigen::Vector3d(std::sin(p) * std::cos(a), std::sin(p) * std::sin(a), std::cos(p));
  };
  ShellMesh m = structured_block(
      n_polar, n_azimuth, [=](double u, double v) { return Eigen::Vector3d(r * dir(u, v)); }, dir,
      thickness);
  rename_set(&m, "u0", "p0");
  rename_set(&m, "u1", "p1");
  rename_set(&m, "v0", "a0");
  rename_set(&m, "v1", "a1");
  return m;
}

ShellMesh twisted_strip(double l, double w, double twist, int n_width, int n_length,
                        double thickness) {
  // u: along x, v: across the width; width direction (0, cos, sin)(phi), phi = twist * u.
  ShellMesh m = structured_block(
      n_length, n_width,
      [=](double u, double v) {
        const double phi = twist * u, s = (v - 0.5) * w;
        return Eigen::Vector3d(u * l, s * std::cos(phi), s * std::sin(phi));
      },
      {}, thickness);
  rename_set(&m, "u0", "root");
  rename_set(&m, "u1", "tip");
  m.node_sets.erase("v0");
  m.node_sets.erase("v1");
  return m;
}

ShellMesh quarter_disc(double r, int n, int m, double thickness) {
  const double s = 0.5 * r, q = 0.25 * std::numbers::pi;
  const auto up = [](double, double) { return Eigen::Vector3d::UnitZ(); };
  std::vector<ShellMesh> parts;
  parts.push_back(structured_block(
      n, n, [=](double u, double v) { return Eigen::Vector3d(u * s, v * s, 0.0); }, up, thickness));
  // Lower block: from the square's edge x = s to the arc 0..45 degrees (u radial, v along).
  parts.push_back(structured_block(
      m, n,
      [=](double u, double v) {
        const Eigen::Vector3d a(s, v * s, 0.0), b(r * std::cos(q * v), r * std::sin(q * v), 0.0);
        return Eigen::Vector3d((1.0 - u) * a + u * b);
      },
      up, thickness));
  // Upper block: from the square's edge y = s (x from s to 0) to the arc 45..90 degrees.
  parts.push_back(structured_block(
      m, n,
      [=](double u, double v) {
        const double t = q * (1.0 + v);
        const Eigen::Vector3d a(s * (1.0 - v), s, 0.0), b(r * std::cos(t), r * std::sin(t), 0.0);
        return Eigen::Vector3d((1.0 - u) * a + u * b);
      },
      up, thickness));
  for (auto& p : parts) p.node_sets.clear();
  ShellMesh disc = merge_meshes(parts, 1e-9 * r);
  const double tol = 1e-9 * r;
  add_node_set(&disc, "x0", [tol](const Eigen::Vector3d& x) { return std::abs(x.x()) < tol; });
  add_node_set(&disc, "y0", [tol](const Eigen::Vector3d& x) { return std::abs(x.y()) < tol; });
  add_node_set(&disc, "rim",
               [=](const Eigen::Vector3d& x) { return std::abs(x.norm() - r) < 1e-9 * r; });
  add_node_set(&disc, "centre", [tol](const Eigen::Vector3d& x) { return x.norm() < tol; });
  return disc;
}

namespace {

// Rotation of a point about z by k quarter turns, exact in floating point (no cos(pi/2) round-off),
// so that rotated copies of a block share bit-identical nodes with their neighbours where the
// geometry does.
Eigen::Vector3d quarter_turns(const Eigen::Vector3d& x, int k) {
  switch (((k % 4) + 4) % 4) {
    case 1:
      return {-x.y(), x.x(), x.z()};
    case 2:
      return {-x.x(), -x.y(), x.z()};
    case 3:
      return {x.y(), -x.x(), x.z()};
    default:
      return x;
  }
}

// The node sets every full blank carries: the lines through the centre used by the output
// profiles, and the centre itself (the outline set "edge" is added by the generator).
void add_full_blank_sets(ShellMesh* mesh, double size) {
  const double tol = 1e-9 * size;
  add_node_set(mesh, "x0", [tol](const Eigen::Vector3d& x) { return std::abs(x.x()) < tol; });
  add_node_set(mesh, "y0", [tol](const Eigen::Vector3d& x) { return std::abs(x.y()) < tol; });
  add_node_set(mesh, "diagonal",
               [tol](const Eigen::Vector3d& x) { return std::abs(x.x() - x.y()) < tol; });
  add_node_set(mesh, "centre", [tol](const Eigen::Vector3d& x) { return x.norm() < tol; });
}

}  // namespace

ShellMesh full_disc(double r, int n, int m, double thickness) {
  const double s = 0.5 * r, q = 0.25 * std::numbers::pi;
  const auto up = [](double, double) { return Eigen::Vector3d::UnitZ(); };
  std::vector<ShellMesh> parts;
  parts.push_back(structured_block(
      n, n,
      [=](double u, double v) {
        return Eigen::Vector3d((2.0 * u - 1.0) * s, (2.0 * v - 1.0) * s, 0.0);
      },
      up, thickness));
  // Block k spans the arc from (2k - 1) to (2k + 1) times 45 degrees: the block at -45..45
  // degrees (u radial from the square's edge x = s, v counter-clockwise, so g_u x g_v = +z)
  // turned by k quarter turns, which keeps the orientation.
  for (int k = 0; k < 4; ++k) {
    parts.push_back(structured_block(
        m, n,
        [=](double u, double v) {
          const double t = q * (2.0 * v - 1.0);
          const Eigen::Vector3d a(s, (2.0 * v - 1.0) * s, 0.0),
              b(r * std::cos(t), r * std::sin(t), 0.0);
          return quarter_turns((1.0 - u) * a + u * b, k);
        },
        up, thickness));
  }
  for (auto& p : parts) p.node_sets.clear();
  ShellMesh disc = merge_meshes(parts, 1e-9 * r);
  add_node_set(&disc, "edge",
               [=](const Eigen::Vector3d& x) { return std::abs(x.norm() - r) < 1e-9 * r; });
  add_full_blank_sets(&disc, r);
  return disc;
}

ShellMesh full_square(double a, int n, double thickness) {
  ShellMesh m = structured_block(
      n, n,
      [=](double u, double v) {
        return Eigen::Vector3d((2.0 * u - 1.0) * a, (2.0 * v - 1.0) * a, 0.0);
      },
      [](double, double) { return Eigen::Vector3d::UnitZ(); }, thickness);
  m.node_sets.clear();
  const double tol = 1e-9 * a;
  add_node_set(&m, "edge", [=](const Eigen::Vector3d& x) {
    return std::abs(std::abs(x.x()) - a) < tol || std::abs(std::abs(x.y()) - a) < tol;
  });
  add_full_blank_sets(&m, a);
  return m;
}

ShellMesh merge_meshes(const std::vector<ShellMesh>& parts, double tol) {
  ShellMesh out;
  bool normals = true;
  for (const auto& p : parts) normals = normals && !p.exact_normal.empty();
  // Spatial hash with cells of size tol: a match lies in one of the 27 neighbouring cells.
  using Key = std::array<long long, 3>;
  std::map<Key, std::vector<int>> cells;
  auto key_of = [tol](const Eigen::Vector3d& x) {
    return Key{std::llround(std::floor(x.x() / tol)), std::llround(std::floor(x.y() / tol)),
               std::llround(std::floor(x.z() / tol))};
  };
  for (const auto& p : parts) {
    std::vector<int> map(p.nodes.size());
    for (std::size_t i = 0; i < p.nodes.size(); ++i) {
      const Key c = key_of(p.nodes[i]);
      int found = -1;
      for (long long dx = -1; dx <= 1 && found < 0; ++dx)
        for (long long dy = -1; dy <= 1 && found < 0; ++dy)
          for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto it = cells.find(Key{c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == cells.end()) continue;
            for (int k : it->second)
              if ((out.nodes[k] - p.nodes[i]).norm() < tol) found = k;
          }
      if (found < 0) {
        found = out.num_nodes();
        out.nodes.push_back(p.nodes[i]);
        out.thickness.push_back(p.thickness[i]);
        if (normals) out.exact_normal.push_back(p.exact_normal[i]);
        cells[c].push_back(found);
      }
      map[i] = found;
    }
    for (const auto& e : p.elements) {
      std::array<int, 9> f{};
      for (std::size_t a = 0; a < 9; ++a) f[a] = map[e[a]];
      out.elements.push_back(f);
    }
    for (const auto& [name, ids] : p.node_sets) {
      auto& dst = out.node_sets[name];
      for (int i : ids) dst.push_back(map[i]);
    }
  }
  for (auto& [name, ids] : out.node_sets) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  return out;
}

void add_node_set(ShellMesh* mesh, const std::string& name,
                  const std::function<bool(const Eigen::Vector3d&)>& pred) {
  auto& ids = mesh->node_sets[name];
  ids.clear();
  for (int i = 0; i < mesh->num_nodes(); ++i)
    if (pred(mesh->nodes[i])) ids.push_back(i);
}

}  // namespace vs::shell3d
