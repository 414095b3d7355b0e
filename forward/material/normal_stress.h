// The through-thickness normal stress sigma_33 that plane-stress shell theory drops, prescribed
// from the contact pressures on the two faces of the sheet (issue 15, part 3; derivation and
// measurements: experiments/08_continuum_reference/README.md, sections 7 and 8).
//
// Pressure profile. Through-thickness equilibrium of a membrane at leading order in h k gives a
// linear sigma_33 between the faces; with p_l on the lower face (zeta = z / h = -1/2, the side the
// shell normal points away from) and p_u on the upper face (zeta = +1/2), both compressive >= 0:
//   sigma_33(zeta) = -p(zeta),   p(zeta) = p_l (1/2 - zeta) + p_u (1/2 + zeta).          (P)
//
// Point law. Every yield function of the solver (Hill 1948, Yld2000-2d extended to 3D) is
// pressure-independent: it depends on the stress only through sigma_11 - sigma_33,
// sigma_22 - sigma_33, sigma_12 (for Hill 1948: (sigma_2 - sigma_3)^2 + (sigma_3 - sigma_1)^2 +
// R (sigma_1 - sigma_2)^2, over 1 + R). With sigma_33 = -p known, the shifted stress
// s = (sigma_11 + p, sigma_22 + p, sigma_12) is a plane stress state with the same yield value.
// Associated flow: d_ab = lambda d sigma_bar / d sigma_ab = lambda d sigma_bar_ps / d s_ab (the
// shift has unit Jacobian), and d_33 = lambda d sigma_bar / d sigma_33 = -(d_11 + d_22) (the sum
// of the derivatives of a pressure-independent function vanishes): incompressibility, as before.
// The plastic work sigma : d = s : d_in-plane - p (d_11 + d_22) + (-p) d_33 = s : d = sigma_bar e,
// so e, the viscosity mu and the hardening of the plane-stress law are unchanged, and s is the
// plane-stress law's stress at the same rate. Hence
//   sigma_11 = s_11 - p,   sigma_22 = s_22 - p,   sigma_12 = s_12:                      (S)
// the in-plane normal stresses drop by the local pressure, for any R and any yield function.
//
// Shell power. The shell's internal power counts only the in-plane stresses: with (S) it is
// s : d - p (d_11 + d_22) = sigma_bar e - sigma_33 d_33, the continuum's power less the power of
// sigma_33 on the thinning, which the contact pressure supplies by moving with its face (a pressed
// face moves towards the mid-surface at -h' / 2, while the shell puts the contact force on the
// mid-surface node). With p fixed during a solve (lagged) the added density -p (d_11 + d_22) is
// linear in the velocity: the step potential gains -int p (d_11 + d_22) dV, its gradient is the
// force change of (S), the stiffness is unchanged and the potential stays convex.
#pragma once

namespace vs {

// Contact pressures on the two faces of a shell section [MPa], compressive >= 0.
struct FacePressure {
  double lower_MPa = 0.0;  // face zeta = -1/2 (opposite to the shell normal)
  double upper_MPa = 0.0;  // face zeta = +1/2
  bool active() const { return lower_MPa != 0.0 || upper_MPa != 0.0; }
  // p(zeta) of (P), zeta = z / h in [-1/2, 1/2].
  double at(double zeta) const { return lower_MPa * (0.5 - zeta) + upper_MPa * (0.5 + zeta); }
};

// What sigma_33 = -p adds at one point with in-plane normal rates d_11, d_22 [1/s]: the change of
// both in-plane normal stresses (S) [MPa] and of the step potential density [MPa/s].
struct NormalStressTerm {
  double stress_shift_MPa = 0.0;
  double potential = 0.0;
};
inline NormalStressTerm normal_stress_term(double p_MPa, double d11, double d22) {
  return {-p_MPa, -p_MPa * (d11 + d22)};
}

// The face of a shell a tool presses on: the lower one (zeta = -1/2) if the tool's normal into
// the sheet points along the shell normal, else the upper one. Adds pressure_MPa to that face.
inline void add_face_pressure(double tool_normal_dot_shell_normal, double pressure_MPa,
                              FacePressure* f) {
  if (tool_normal_dot_shell_normal >= 0.0) {
    f->lower_MPa += pressure_MPa;
  } else {
    f->upper_MPa += pressure_MPa;
  }
}

}  // namespace vs
