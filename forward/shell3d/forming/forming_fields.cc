#include "shell3d/forming/forming_fields.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "shell3d/lagrange9.h"

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
