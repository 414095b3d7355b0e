#include "element/shell9_kinematics.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace vs::shell3d {

int Shell9Geometry::ndof() const {
  int n = 0;
  for (int a = 0; a < 9; ++a) n += 3 + n_rot[a];
  return n;
}

int Shell9Geometry::offset(int a) const {
  int n = 0;
  for (int b = 0; b < a; ++b) n += 3 + n_rot[b];
  return n;
}

Mat3 rot_map_5dof(const Vec3& v1, const Vec3& v2) {
  Mat3 P = Mat3::Zero();
  P.col(0) = -v2;
  P.col(1) = v1;
  return P;
}

Mat3 rot_map_6dof(const Vec3& v3) {
  // dV3 = omega x V3 = -V3 x omega.
  Mat3 S;
  S << 0.0, -v3.z(), v3.y(), v3.z(), 0.0, -v3.x(), -v3.y(), v3.x(), 0.0;
  return -S;
}

PointBasis point_basis(const Shell9Geometry& g, const Shape9& sh, double t) {
  PointBasis pb;
  Vec3 gr = Vec3::Zero(), gs = Vec3::Zero(), gt = Vec3::Zero();
  double h = 0.0;
  for (int a = 0; a < 9; ++a) {
    const double c = 0.5 * g.thickness[a];
    const Vec3 p = g.x[a] + (t * c) * g.director[a];
    gr += sh.dr(a) * p;
    gs += sh.ds(a) * p;
    gt += (sh.N(a) * c) * g.director[a];
    h += sh.N(a) * g.thickness[a];
  }
  pb.J.col(0) = gr;
  pb.J.col(1) = gs;
  pb.J.col(2) = gt;
  pb.detJ = pb.J.determinant();
  pb.h = h;
  const Vec3 e3 = gr.cross(gs).normalized();
  const Vec3 e1 = gr.normalized();
  pb.frame.col(0) = e1;
  pb.frame.col(1) = e3.cross(e1);
  pb.frame.col(2) = e3;
  // Rows of J^-1 are the contravariant base vectors g^i, so C = J^-1 * frame.
  pb.C = pb.J.inverse() * pb.frame;
  return pb;
}

Mat5X covariant_B(const Shell9Geometry& g, const Shape9& sh, const PointBasis& pb, double t) {
  const Vec3 gr = pb.J.col(0), gs = pb.J.col(1), gt = pb.J.col(2);
  Mat5X B = Mat5X::Zero(5, g.ndof());
  int off = 0;
  for (int a = 0; a < 9; ++a) {
    const double c = 0.5 * g.thickness[a];
    const double Nr = sh.dr(a), Ns = sh.ds(a), N = sh.N(a);
    // Rows w.r.t. the nodal velocity v_a (3 columns) ...
    Eigen::Matrix<double, 5, 3> Bv;
    Bv.row(0) = Nr * gr.transpose();
    Bv.row(1) = Ns * gs.transpose();
    Bv.row(2) = (Ns * gr + Nr * gs).transpose();
    Bv.row(3) = (Nr * gt).transpose();
    Bv.row(4) = (Ns * gt).transpose();
    // ... and w.r.t. the director rate dV3_a (3 columns), mapped to the rotation dofs by P_a.
    Eigen::Matrix<double, 5, 3> Bd;
    Bd.row(0) = (t * c * Nr) * gr.transpose();
    Bd.row(1) = (t * c * Ns) * gs.transpose();
    Bd.row(2) = (t * c) * (Ns * gr + Nr * gs).transpose();
    Bd.row(3) = (c * N * gr + t * c * Nr * gt).transpose();
    Bd.row(4) = (c * N * gs + t * c * Ns * gt).transpose();
    if (g.has_vel_frame) {
      B.middleCols<3>(off) = Bv * g.vel_frame[a];
    } else {
      B.middleCols<3>(off) = Bv;
    }
    const int nr = g.n_rot[a];
    B.middleCols(off + 3, nr) = Bd * g.rot_map[a].leftCols(nr);
    off += 3 + nr;
  }
  return B;
}

Mat5 local_transform(const Mat3& C) {
  // eps_ab = sum_ij e_ij C(i,a) C(j,b); engineering factor f = 2 for a != b; covariant shears
  // enter as 2e_ij, hence the 1/2 on the mixed terms. Index 0 = r, 1 = s, 2 = t.
  constexpr int kPairs[5][2] = {{0, 0}, {1, 1}, {0, 1}, {0, 2}, {1, 2}};
  Mat5 T;
  for (int row = 0; row < 5; ++row) {
    const int a = kPairs[row][0], b = kPairs[row][1];
    const double f = (a == b) ? 1.0 : 2.0;
    for (int col = 0; col < 5; ++col) {
      const int i = kPairs[col][0], j = kPairs[col][1];
      T(row, col) =
          (i == j) ? f * C(i, a) * C(i, b) : 0.5 * f * (C(i, a) * C(j, b) + C(j, a) * C(i, b));
    }
  }
  return T;
}

}  // namespace vs::shell3d
