// Synthetic "measured" data from a forward run with known parameters, plus documented Gaussian
// noise: for twin-experiment tests and for the synthetic data sets in data/. The provenance
// lines say SYNTHETIC, the scene, its material and friction values, the noise and the seed.
#pragma once

#include <string>
#include <vector>

#include "measurement.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

struct SyntheticDataSpec {
  MeasurementKind kind = MeasurementKind::kLoadTravel;
  std::string name;
  double travel_mm = 0.0;  // profiles: must be one of the run's profile travels
  // Abscissae (punch_travel_mm, r0_mm or angle_from_rd_deg); empty = the run's own steps /
  // element midpoints (cup_height_profile: must be given).
  std::vector<double> x;
  // Noise standard deviation = noise_absolute + noise_relative * max |clean ordinate| (internal
  // units: N or strain). With noise, the per-point sigma column is written too.
  double noise_relative = 0.0;
  double noise_absolute = 0.0;
};

// Throws InputError if the run cannot provide a requested data set (it stopped too early, or
// has no profile at travel_mm). The same seed gives the same numbers on every platform (own
// splitmix64 generator and Box-Muller transform, not <random>'s unspecified distributions).
std::vector<Measurement> make_synthetic_measurements(const Scene& scene, const RunResult& run,
                                                     const std::vector<SyntheticDataSpec>& specs,
                                                     unsigned long long seed);

// Standard normal deviates from a seed, deterministic across platforms.
class GaussianNoise {
 public:
  explicit GaussianNoise(unsigned long long seed) : state_(seed) {}
  double next();

 private:
  unsigned long long next_bits();
  unsigned long long state_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace vs
