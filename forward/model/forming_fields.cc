#include "model/forming_fields.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "element/lagrange9.h"

namespace vs::shell3d {

namespace {

Eigen::Matrix2d metric(const std::array<int, 9>& el, const std::vector<Eigen::Vector3d>& x,
                       const Shape9& sh) {
  Eigen::Vector3d gr = Eigen::Vector3d::Zero(), gs = Eigen::Vector3d::Zero();
  for (int a = 0; a < 9; ++a) {
    gr += sh.dr(a) * x[el[a]];
    gs += sh.ds(a) * x[el[a]];
  }
  Eigen::Matrix2d G;
  G << gr.dot(gr), gr.dot(gs), gs.dot(gr), gs.dot(gs);
  return G;
}

}  // namespace

ElementStrains element_strains(const ShellMesh& mesh, const ShellStage& stage) {
  ElementStrains out;
  const int ne = mesh.num_elements();
  out.major.resize(ne);
  out.minor.resize(ne);
  out.thickness.resize(ne);
  out.r0_mm.resize(ne);
  out.effective = stage.eps_effective;
  const Shape9 centre = lagrange9(0.0, 0.0);
  for (int e = 0; e < ne; ++e) {
    const auto& el = mesh.elements[e];
    const Eigen::Matrix2d G0 = metric(el, mesh.nodes, centre);
    const Eigen::Matrix2d G = metric(el, stage.x, centre);
    // Symmetric form L^-1 G L^-T (G0 = L L^T) has the eigenvalues of G0^-1 G.
    const Eigen::LLT<Eigen::Matrix2d> llt(G0);
    const Eigen::Matrix2d Li = llt.matrixL().solve(Eigen::Matrix2d::Identity());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Li * G * Li.transpose());
    const Eigen::Vector2d lam2 = eig.eigenvalues();  // ascending
    out.minor[e] = 0.5 * std::log(lam2(0));
    out.major[e] = 0.5 * std::log(lam2(1));
    out.thickness[e] = -(out.major[e] + out.minor[e]);
    const Eigen::Vector3d& c0 = mesh.nodes[el[8]];
    out.r0_mm[e] = std::hypot(c0.x(), c0.y());
  }
  return out;
}

LineProfile line_profile(const ShellMesh& mesh, const ShellStage& stage, const std::string& line,
                         double initial_thickness_mm) {
  LineProfile p;
  p.line = line;
  p.nodes = mesh.set(line);
  auto r0 = [&](int i) { return std::hypot(mesh.nodes[i].x(), mesh.nodes[i].y()); };
  std::sort(p.nodes.begin(), p.nodes.end(), [&](int a, int b) { return r0(a) < r0(b); });
  for (int i : p.nodes) {
    p.r0_mm.push_back(r0(i));
    p.r_mm.push_back(std::hypot(stage.x[i].x(), stage.x[i].y()));
    p.z_mm.push_back(stage.x[i].z());
    p.thickness_mm.push_back(stage.thickness_mm[i]);
    p.eps_thickness.push_back(std::log(stage.thickness_mm[i] / initial_thickness_mm));
    p.contact_tool.push_back(stage.contact_tool[i]);
  }
  return p;
}

std::vector<std::string> profile_lines(const ShellMesh& mesh) {
  std::vector<std::string> lines;
  for (const char* line : {"y0", "x0", "diagonal"}) {
    if (mesh.node_sets.count(line) != 0) lines.emplace_back(line);
  }
  for (const char* line : {"y0_neg", "x0_neg", "diagonal_neg"}) {
    if (mesh.node_sets.count(line) != 0) lines.emplace_back(line);
  }
  return lines;
}

std::string profile_line_name(const std::string& node_set) {
  std::string name = node_set;
  if (name.rfind("y0", 0) == 0)
    name.replace(0, 2, "x");
  else if (name.rfind("x0", 0) == 0)
    name.replace(0, 2, "y");
  return name;
}

std::vector<Profile> shell_profiles(const ShellMesh& mesh, const ShellStage& stage,
                                    double initial_thickness_mm) {
  // Elements around each node (for the nodal effective strain).
  std::vector<std::vector<int>> around(mesh.nodes.size());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    for (int a : mesh.elements[e]) around[a].push_back(e);
  }
  std::vector<Profile> out;
  for (const std::string& set : profile_lines(mesh)) {
    const LineProfile lp = line_profile(mesh, stage, set, initial_thickness_mm);
    Profile p;
    p.punch_travel_mm = stage.punch_travel_mm;
    p.line = profile_line_name(set);
    p.r0_mm = lp.r0_mm;
    p.r_mm = lp.r_mm;
    p.z_mm = lp.z_mm;
    p.thickness_mm = lp.thickness_mm;
    p.eps_thickness = lp.eps_thickness;
    p.node_r_mm = lp.r_mm;
    p.node_z_mm = lp.z_mm;
    const std::size_t n = lp.nodes.size();
    // Interval lengths along the line, current and initial.
    std::vector<double> ds(n > 0 ? n - 1 : 0), ds0(ds.size());
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const int a = lp.nodes[k], b = lp.nodes[k + 1];
      ds[k] = (stage.x[b] - stage.x[a]).norm();
      ds0[k] = (mesh.nodes[b] - mesh.nodes[a]).norm();
    }
    for (std::size_t k = 0; k < n; ++k) {
      double l = 0.0, l0 = 0.0;
      if (k > 0) {
        l += ds[k - 1];
        l0 += ds0[k - 1];
      }
      if (k + 1 < n) {
        l += ds[k];
        l0 += ds0[k];
      }
      const double em = l0 > 0.0 ? std::log(l / l0) : 0.0;
      p.eps_meridional.push_back(em);
      p.eps_circumferential.push_back(lp.r0_mm[k] > 0.0 ? std::log(lp.r_mm[k] / lp.r0_mm[k]) : em);
      p.contact.push_back(lp.contact_tool[k] >= 0 ? 1 : 0);
      const std::vector<int>& els = around[static_cast<std::size_t>(lp.nodes[k])];
      double sum = 0.0;
      for (int e : els) sum += stage.eps_effective[static_cast<std::size_t>(e)];
      p.eps_effective.push_back(els.empty() ? 0.0 : sum / static_cast<double>(els.size()));
    }
    out.push_back(std::move(p));
  }
  return out;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq) {
  if (x.empty()) return std::nan("");
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t j = static_cast<std::size_t>(it - x.begin());
  const double t = (xq - x[j - 1]) / (x[j] - x[j - 1]);
  return (1.0 - t) * y[j - 1] + t * y[j];
}

}  // namespace vs::shell3d
