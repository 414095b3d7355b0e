// Fields derived from a ShellStage for outputs and tests: in-plane principal (major, minor) true
// strains of every element from the mid-surface metric, and nodal profiles from the centre along
// the lines y = 0, x = 0 and the diagonal x = y (node sets of forming_mesh.h).
//
// Principal strains: at the element centre (r = s = 0) the covariant metrics of the initial and
// current mid-surface, G0 = [g_r0 g_s0]^T [g_r0 g_s0] and G = [g_r g_s]^T [g_r g_s], define the
// right Cauchy-Green tensor of the in-plane stretch; its eigenvalues are the eigenvalues of
// G0^-1 G = lambda^2, so eps_major/minor = ln(lambda_1/2) (the mesh is material: the same (r, s)
// is the same particle). The membrane thickness strain is -(eps_major + eps_minor)
// (incompressible).
#pragma once

#include <string>
#include <vector>

#include "run/run_result.h"

namespace vs::shell3d {

struct ElementStrains {
  std::vector<double> major, minor, thickness, effective;  // per element
  std::vector<double> r0_mm;                               // initial radius of the centre
};

ElementStrains element_strains(const ShellMesh& mesh, const ShellStage& stage);

struct LineProfile {
  std::string line;           // node set: "y0" (along x), "x0" (along y), "diagonal", "..._neg"
  std::vector<int> nodes;     // sorted by initial radius
  std::vector<double> r0_mm;  // initial distance from the punch axis
  std::vector<double> r_mm;   // current distance from the axis
  std::vector<double> z_mm;
  std::vector<double> thickness_mm;
  std::vector<double> eps_thickness;  // ln(h / h0), nodal
  std::vector<int> contact_tool;      // -1 free
};

LineProfile line_profile(const ShellMesh& mesh, const ShellStage& stage, const std::string& line,
                         double initial_thickness_mm);

// The profiles of one stage in the RunResult form, one per line of the mesh in the order "x"
// (node set y0), "y" (x0), "diagonal", then for a full blank "x_neg", "y_neg", "diagonal_neg".
// Nodal values along the line from the centre: r0_mm, r_mm, z_mm, thickness_mm, eps_thickness,
// contact (1 touching a tool); eps_meridional = ln(ds/ds0) of the line's arc length over the
// two neighbouring intervals (one at the ends); eps_circumferential = ln(r/r0) (the hoop stretch
// of the ring through the node; at the centre the meridional value, equal there by symmetry);
// eps_effective = the mean of the elements around the node; node_r_mm/node_z_mm = r_mm/z_mm.
// The forces of the axisymmetric profiles are left empty.
std::vector<Profile> shell_profiles(const ShellMesh& mesh, const ShellStage& stage,
                                    double initial_thickness_mm);

// The profile line names of a mesh as the node set names of forming_mesh.h ("y0", "x0",
// "diagonal", "..._neg") and the user-facing Profile::line names ("x", "y", "diagonal", ...).
std::vector<std::string> profile_lines(const ShellMesh& mesh);
std::string profile_line_name(const std::string& node_set);

// Linear interpolation of (x, y) (x increasing) at xq; clamped to the ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq);

}  // namespace vs::shell3d
