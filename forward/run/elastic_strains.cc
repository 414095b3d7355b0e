#include "run/elastic_strains.h"

#include <cmath>

#include "material/elastic_start.h"
#include "material/hardening.h"
#include "material/viscous_law.h"

namespace vs {

namespace {

Eigen::Vector2d deformation_theory_stress(const Scene& scene, const Profile& p, std::size_t i) {
  const Eigen::Vector2d eps(p.eps_meridional[i], p.eps_circumferential[i]);
  const Eigen::Matrix2d A = anisotropy_matrix(scene.material.r_value);
  const double e2 = eps.dot(A * eps) / 3.0;
  if (!(e2 > 1e-24)) return Eigen::Vector2d::Zero();
  const Hardening flow(scene.material.hardening, scene.material.elastic);
  const double e_bar = i < p.eps_effective.size() ? p.eps_effective[i] : std::sqrt(e2);
  return flow.flow_stress(e_bar) * (A * eps) / (3.0 * std::sqrt(e2));
}

void correct(const Scene& scene, Profile* p) {
  const ElasticSpec& el = scene.material.elastic;
  for (std::size_t i = 0; i < p->eps_thickness.size(); ++i) {
    const Eigen::Vector2d s = profile_point_stress(scene, *p, i);
    const double d = thickness_strain_correction(el, s(0), s(1));
    p->eps_thickness[i] += d;
    if (i < p->thickness_mm.size()) p->thickness_mm[i] *= std::exp(d);
  }
}

}  // namespace

Eigen::Vector2d profile_point_stress(const Scene& scene, const Profile& p, std::size_t i) {
  const bool forces = p.meridional_force_N_per_mm.size() > i &&
                      p.circumferential_force_N_per_mm.size() > i && p.thickness_mm.size() > i;
  if (forces) {
    const double h = p.thickness_mm[i];
    return Eigen::Vector2d(p.meridional_force_N_per_mm[i] / h,
                           p.circumferential_force_N_per_mm[i] / h);
  }
  if (p.eps_meridional.size() > i && p.eps_circumferential.size() > i) {
    return deformation_theory_stress(scene, p, i);
  }
  return Eigen::Vector2d::Zero();
}

void add_elastic_strains(const Scene& scene, RunResult* result) {
  if (!scene.material.elastic.strains_on()) return;
  for (Profile& p : result->profiles) correct(scene, &p);
  for (Profile& p : result->history) correct(scene, &p);
}

}  // namespace vs
