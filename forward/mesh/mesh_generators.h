// Structured 9-node meshes. Every generator maps a uniform parameter grid of (2nu+1) x (2nv+1)
// nodes onto the surface, so midside and centre nodes lie on the exact surface (isoparametric
// curved elements), and records exact normals where the surface is analytic. Elements are
// oriented so that g_r x g_s points along the stated normal. Node sets are named per generator.
#pragma once

#include <functional>

#include "mesh/shell_mesh.h"

namespace vs::shell3d {

using SurfaceMap = std::function<Eigen::Vector3d(double u, double v)>;

// Generic block: u, v in [0, 1]; node sets "u0", "u1", "v0", "v1" (the four edges).
// `normal` may be empty (no exact normals).
ShellMesh structured_block(int nu, int nv, const SurfaceMap& map, const SurfaceMap& normal,
                           double thickness);

// Flat plate [0, lx] x [0, ly] in z = 0, normal +z. Sets "x0", "x1", "y0", "y1".
ShellMesh rectangular_plate(double lx, double ly, int nx, int ny, double thickness);

// Cylinder of radius r about the y axis: x = r sin(theta), z = r cos(theta), y in [y0, y1],
// theta in [theta0, theta1] (radians), outward normal. Sets "y0", "y1", "theta0", "theta1".
ShellMesh cylinder_patch(double r, double y0, double y1, double theta0, double theta1, int n_axial,
                         int n_circ, double thickness);

// Sphere of radius r: (r sin(p) cos(a), r sin(p) sin(a), r cos(p)), polar angle p in [p0, p1],
// azimuth a in [a0, a1], outward normal. Sets "p0", "p1", "a0", "a1".
ShellMesh sphere_patch(double r, double p0, double p1, double a0, double a1, int n_polar,
                       int n_azimuth, double thickness);

// Pretwisted strip along x: length l, width w, total twist (radians) from root (x = 0, width
// along y, normal +z) to tip. Sets "root", "tip".
ShellMesh twisted_strip(double l, double w, double twist, int n_width, int n_length,
                        double thickness);

// Quarter circular blank of radius r in z = 0 (x, y >= 0), normal +z: an n x n central square
// (corner at (r/2, r/2)) and two n x m curved blocks out to the rim. Sets "x0" (on x = 0),
// "y0" (on y = 0), "rim", "centre".
ShellMesh quarter_disc(double r, int n, int m, double thickness);

// Full circular blank of radius r in z = 0 centred on the origin, normal +z (O-grid): an n x n
// central square (corners (+-r/2, +-r/2)) and four curved n x m blocks out to the rim (m
// elements radially). With n = 2k, m = k it is quarter_disc(r, k, k) mirrored onto all four
// quadrants. Sets "edge" (the rim), "centre" (the node at the origin; it exists for any n),
// "x0" (the whole line x = 0), "y0" (the whole line y = 0), "diagonal" (the whole line x = y).
ShellMesh full_disc(double r, int n, int m, double thickness);

// Full square blank [-a, a] x [-a, a] in z = 0, normal +z, n x n elements. Sets as full_disc:
// "edge" (the four sides), "centre", "x0", "y0", "diagonal" (whole lines through the centre).
ShellMesh full_square(double a, int n, double thickness);

// Merges nodes closer than tol (first occurrence wins); node sets are concatenated and
// deduplicated, exact normals kept if every input has them.
ShellMesh merge_meshes(const std::vector<ShellMesh>& parts, double tol);

// Adds a node set of all nodes satisfying pred.
void add_node_set(ShellMesh* mesh, const std::string& name,
                  const std::function<bool(const Eigen::Vector3d&)>& pred);

}  // namespace vs::shell3d
