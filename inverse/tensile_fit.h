// Hardening laws fitted to a measured uniaxial tensile curve (issue 6).
//
// The curve is a CSV with the NIST NUMISHEET 2020 columns Time,Estrain,Estress,Tstrain,Tstress
// (s, -, MPa, -, MPa). The fit uses the true stress against the plastic strain
//   eps_p = true strain - true stress / E
// from yield (eps_p > min_plastic_strain) up to the load maximum (largest engineering stress):
// past it the specimen necks and the "true" values are no longer uniaxial. A curve whose strain
// reverses (the NIST file is tension to 0.05, compression, then tension to fracture) is fitted
// on its first tension branch only, with a warning. Each law is fitted
// with Ceres (autodiff residuals model - measured, in MPa); intervals come from
// estimate_uncertainty() on the Jacobian at the optimum. The points of one curve are strongly
// autocorrelated (the residual is model error, not noise), so those intervals are too narrow as
// statements about the material; they do say how well each parameter is pinned by the curve.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "uncertainty.h"

namespace vs {

struct TensileCurve {
  std::string source;     // file name, for messages
  std::vector<int> line;  // 1-based line of each row in the file
  std::vector<double> time_s, eng_strain, eng_stress_MPa, true_strain, true_stress_MPa;
};

// Strict reader: header must be exactly the five columns (quotes optional), every row five finite
// numbers, at least 10 rows. Errors: InputError "FILE:LINE: what".
TensileCurve read_tensile_csv(const std::string& path);

struct TensileFitOptions {
  double elastic_modulus_MPa = 70000.0;
  double min_plastic_strain = 0.002;  // yield: first point with eps_p above this
  double max_true_strain = 0.0;       // > 0: fit only up to this true strain
  bool allow_past_maximum = false;    // max_true_strain beyond the load maximum: warn, not refuse
};

// The points the fit uses and the load maximum of the curve.
struct FitRange {
  std::vector<int> rows;  // indices into the curve
  std::vector<double> true_strain, plastic_strain, true_stress_MPa;
  int max_load_row = 0;  // row of the largest engineering stress
  double max_load_true_strain = 0.0;
  double max_load_plastic_strain = 0.0;
  double max_load_true_stress_MPa = 0.0;
  double max_load_eng_stress_MPa = 0.0;
  // First row where the strain reverses (-1: monotonic tension). With a reversal only the first
  // tension branch is fitted and the file's load maximum is not a monotonic necking point.
  int reversal_row = -1;
  bool max_load_after_reversal = false;
  double end_true_strain = 0.0;  // where the usable range ends (load maximum or branch end)
  std::vector<std::string> warnings;
};

// Throws InputError when the range is empty or asks for data past the load maximum without
// allow_past_maximum.
FitRange select_fit_range(const TensileCurve& curve, const TensileFitOptions& options);

enum class FitLaw { kSwift, kVoce, kHollomon };

std::string fit_law_name(FitLaw law);
FitLaw parse_fit_law(const std::string& name);  // swift | voce | hollomon; else InputError

struct LawFit {
  FitLaw law = FitLaw::kSwift;
  HardeningSpec spec;  // the fitted law, usable in a scene (Hollomon: sigma0 = K e_first^n, fixed)
  UncertaintySummary uncertainty;  // names/values/intervals of the fitted parameters
  std::vector<double> fitted_MPa;  // model at each fitted point
  double rms_MPa = 0.0;
  double max_abs_residual_MPa = 0.0;
  double aic = 0.0;  // m ln(RSS / m) + 2 p
  std::string termination;
  // Considere: true strain where d sigma / d eps_true = sigma (with the elastic part sigma / E).
  bool considere_found = false;
  double considere_true_strain = 0.0;
  double considere_plastic_strain = 0.0;
};

// Fits one law to (plastic strain, true stress) pairs.
LawFit fit_hardening_law(FitLaw law, const std::vector<double>& plastic_strain,
                         const std::vector<double>& true_stress_MPa, double elastic_modulus_MPa);

// Considere point of `spec` with elastic modulus E (plastic strain searched in [0, 5]).
bool considere_point(const HardeningSpec& spec, double elastic_modulus_MPa, double* plastic_strain,
                     double* true_strain);

}  // namespace vs
