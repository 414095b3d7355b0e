#include "synthetic.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "output/number_format.h"
#include "residual_pipeline.h"

namespace vs {
namespace {

std::string scene_parameters(const Scene& scene) {
  const auto& h = scene.material.hardening;
  std::string text = fmt::format("material.r_value={}", format_number(scene.material.r_value));
  switch (h.law) {
    case HardeningLaw::kSwift:
      text += fmt::format(" swift K_MPa={} eps0={} n={}", format_number(h.K_MPa),
                          format_number(h.eps0), format_number(h.n));
      break;
    case HardeningLaw::kHollomon:
      text += fmt::format(" hollomon K_MPa={} n={} sigma0_MPa={}", format_number(h.K_MPa),
                          format_number(h.n), format_number(h.sigma0_MPa));
      break;
    case HardeningLaw::kVoce:
      text += fmt::format(" voce sigma0_MPa={} Q_MPa={} b={}", format_number(h.sigma0_MPa),
                          format_number(h.Q_MPa), format_number(h.b));
      break;
    case HardeningLaw::kTable:
      text += fmt::format(" table table_scale={}", format_number(h.table_scale));
      break;
  }
  for (const auto& tool : scene.tools) {
    text += fmt::format(" tool.{}.friction={}", tool.name, format_number(tool.friction));
  }
  return text;
}

}  // namespace

unsigned long long GaussianNoise::next_bits() {
  // splitmix64 (Steele, Lea & Flood 2014): tiny, full period, good enough for test noise.
  unsigned long long z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double GaussianNoise::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // Uniforms in (0, 1] from the top 53 bits; Box-Muller gives two deviates per pair.
  const double u1 = (static_cast<double>(next_bits() >> 11) + 1.0) * 0x1.0p-53;
  const double u2 = static_cast<double>(next_bits() >> 11) * 0x1.0p-53;
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

std::vector<Measurement> make_synthetic_measurements(const Scene& scene, const RunResult& run,
                                                     const std::vector<SyntheticDataSpec>& specs,
                                                     unsigned long long seed) {
  GaussianNoise noise(seed);
  std::vector<Measurement> out;
  for (const auto& spec : specs) {
    Measurement m;
    m.name = spec.name;
    m.kind = spec.kind;
    m.file = "(synthetic)";
    m.travel_mm = spec.travel_mm;
    m.x = spec.x;
    if (m.x.empty() && spec.kind == MeasurementKind::kLoadTravel) {
      for (const auto& step : run.steps) m.x.push_back(step.punch_travel_mm);
    }
    if (m.x.empty()) {
      for (const auto& p : run.profiles) {
        if (std::abs(p.punch_travel_mm - spec.travel_mm) <= 1e-6 * std::max(1.0, spec.travel_mm)) {
          m.x = p.r0_mm;
          break;
        }
      }
    }
    const SimulatedCurve clean = simulate_curve(m, run, &scene);
    if (!clean.ok || m.x.empty()) {
      throw InputError(fmt::format("synthetic data set '{}': {}", spec.name,
                                   clean.ok ? "no abscissae" : clean.message));
    }
    double amplitude = 0.0;
    for (double y : clean.y) amplitude = std::max(amplitude, std::abs(y));
    const double sigma = spec.noise_absolute + spec.noise_relative * amplitude;
    m.y = clean.y;
    if (sigma > 0.0) {
      for (double& y : m.y) y += sigma * noise.next();
      m.point_sigma.assign(m.y.size(), sigma);
    }
    m.provenance = {
        {"source", fmt::format("SYNTHETIC data, not a measurement: vs::make_synthetic_measurements "
                               "from scene {} ({})",
                               scene.source, scene.title)},
        {"units", spec.kind == MeasurementKind::kLoadTravel         ? "mm, N"
                  : spec.kind == MeasurementKind::kCupHeightProfile ? "deg, mm"
                                                                    : "mm, 1 (true strain)"},
        {"generating parameters", scene_parameters(scene)},
        {"noise",
         sigma > 0.0
             ? fmt::format("gaussian, sigma = {} ({} x max|y| + {})", format_number(sigma),
                           format_number(spec.noise_relative), format_number(spec.noise_absolute))
             : std::string("none")},
        {"seed", fmt::format("{} (splitmix64 + Box-Muller, vs::GaussianNoise)", seed)},
    };
    if (is_strain_profile(spec.kind)) {
      m.provenance.emplace_back("punch travel",
                                fmt::format("{} mm", format_number(spec.travel_mm)));
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace vs
