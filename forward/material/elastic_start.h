// Isotropic elasticity as a first-order correction of the rigid-(visco)plastic flow formulation
// ([material.elastic]; issue 15, experiments/08_continuum_reference/README.md section 10).
//
// The shell carries one accumulated effective strain e per point (the time integral of the
// effective rate of its incompressible flow) and a flow stress f(e); it has no elastic strain and
// no stress history. Two corrections fit that structure.
//
// (b) The elastic start (ElasticSpec::start). Monotonic proportional loading of an
// elastic-plastic point (deformation theory, the secant view): the total equivalent strain is the
// plastic one plus the elastic one, e = e_p + sigma / E, and the stress is on the hardening curve,
// sigma = sigma_y(e_p). Read e as total, the flow stress at e is
//     f(e) = E e                                      for e <= e_y = sigma_y(0) / E,
//     f(e) = sigma, the root of g(sigma) = sigma - sigma_y(e - sigma / E) = 0   for e > e_y,  (1)
// i.e. f(e) = min(E e, sigma_y(e - f / E)). g is increasing (g' = 1 + H / E > 0, H = sigma_y'),
// g(sigma_y(0)) <= 0 <= g(sigma_y(e)), so the root is unique and lies in [sigma_y(0), sigma_y(e)];
// it is found by Newton's method safeguarded by bisection on that bracket. The tangent follows
// from d sigma = H (de - d sigma / E):
//     f'(e) = E                  (elastic),      f'(e) = E H / (E + H)   (plastic, H at e_p).  (2)
// In the step solve (backward Euler in the hardening, ViscousLaw::evaluate) f'(e) dt is the
// hardening viscosity, so a point with f = 0 (e = 0, the undeformed sheet) has the viscosity
// E dt / 3: its step is the incompressible elastic increment with modulus E, and its stress after
// the step is E (e + dt e_dot) = f(e_{n+1}). Limits of the model, by construction:
//   * no elastic unloading: a point whose stress falls keeps f(e) as its flow stress (rigid
//     below it), and the strain it accumulated elastically stays (as permanent) strain;
//   * the effective strain is that of the in-plane rates under incompressibility, and the
//     elastic strains are not incompressible. To first order the in-plane elastic strains
//     eps_el = S s (S the plane-stress compliance) raise the shell's effective strain
//     e = sqrt(eps^T A eps / 3) by (A eps_p)^T eps_el / (3 e_p) = s^T S s / sigma_bar
//     (s = sigma_bar A d / (3 e) on a proportional path) = c sigma_bar / E with
//     c = s_1^2 + s_2^2 - 2 nu s_1 s_2 for the unit stress direction (sigma_bar(s) = 1):
//     c = 1 in uniaxial tension, (4/3)(5/4 - nu) in plane strain and 2 (1 - nu) in equibiaxial
//     tension (R = 1; all 1 for nu = 1/2). (1) uses c = 1 (the uniaxial value): it under-counts
//     the elastic strain of a biaxial point by up to 1 / (2 (1 - nu)) (0.71 for nu = 0.3);
//     experiments/08_continuum_reference section 10 measures c = 1.4 against c = 1;
//   * the strain-rate cut-off sees f(e) like any flow stress: rigid zones (e ~ 0) are now soft
//     elastic ones whose stiffness is the hardening viscosity E dt / 3, not f(e_c) / (3 e_c).
//
// (a) The elastic part of the reported strains (ElasticSpec::strains). Plane stress Hooke's law
// with the in-plane stresses sigma_1, sigma_2 (and sigma_33, if known):
//     eps_el_1 = (sigma_1 - nu (sigma_2 + sigma_33)) / E,   eps_el_2 likewise,
//     eps_el_3 = (sigma_33 - nu (sigma_1 + sigma_2)) / E:                                   (3)
// uniaxial -nu sigma / E, equibiaxial -2 nu sigma / E. The shell's thickness strain is
// -(eps_1 + eps_2) of its own in-plane strains (exact volume conservation). What it misses
// depends on what its strains are:
//   * rigid-plastic (no elastic start): the shell's strains are the plastic ones, so the total
//     thickness strain is eps_3 + eps_el_3;                                                 (4a)
//   * with the elastic start: the shell's in-plane strains are total (e includes sigma / E), and
//     its thickness strain already holds -(eps_el_1 + eps_el_2) under incompressibility; it
//     misses the elastic volume change, eps_el_1 + eps_el_2 + eps_el_3 =
//     (1 - 2 nu) (sigma_1 + sigma_2 + sigma_33) / E.                                        (4b)
#pragma once

#include "material/hardening.h"
#include "scene/scene.h"

namespace vs {

// The flow stress f(e) of (1) [MPa] at total effective strain e (>= 0) for the hardening curve
// `curve` and Young's modulus E_MPa > 0, and its slope f'(e) of (2) [MPa] if slope != nullptr.
double elastic_start_stress(const Hardening& curve, double E_MPa, double e, double* slope);

// The elastic thickness strain of (3) from the in-plane stresses and sigma_33 [MPa].
double elastic_thickness_strain(double E_MPa, double nu, double sigma_1_MPa, double sigma_2_MPa,
                                double sigma_33_MPa = 0.0);

// What the reported thickness strain gains, (4a) or (4b) by elastic.start_on(); 0 when
// elastic.strains_on() is false.
double thickness_strain_correction(const ElasticSpec& elastic, double sigma_1_MPa,
                                   double sigma_2_MPa, double sigma_33_MPa = 0.0);

}  // namespace vs
