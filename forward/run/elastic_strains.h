// The elastic part of the reported thickness strains ([material.elastic] strains = true; derived
// in material/elastic_start.h, (3)-(4b)), added to a run's strain profiles after the run, for both
// geometries. The solver itself never sees it.
//
// The in-plane stresses of a profile point: the mean stresses of the section, N / h, where the
// profile has its membrane forces (axisymmetric); else (3D lines) the deformation-theory estimate
// of a proportional path, s = f(e_bar) A eps / (3 e(eps)) with eps = (eps_meridional,
// eps_circumferential), e(eps)^2 = eps^T A eps / 3, A the Hill 1948 matrix of material.r_value and
// f the flow stress the solver uses (with the elastic start if on). sigma_33 is not in a profile
// and is taken as 0 (the contact pressure p ~ 10 MPa changes the strain by p / E ~ 5e-5).
#pragma once

#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// In-plane stresses [MPa] of profile point i (see the header comment).
Eigen::Vector2d profile_point_stress(const Scene& scene, const Profile& p, std::size_t i);

// Adds thickness_strain_correction() to eps_thickness of every profile and history profile, and
// scales thickness_mm by its exponential. Nothing if scene.material.elastic.strains_on() is false.
void add_elastic_strains(const Scene& scene, RunResult* result);

}  // namespace vs
