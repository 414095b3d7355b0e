// Identification of the eight Yld2000-2d coefficients (yld2000.h) from the eight classical data:
// yield stresses sigma0, sigma45, sigma90 (uniaxial at 0/45/90 degrees to RD), sigma_b
// (equibiaxial), Lankford ratios r0, r45, r90 and the equibiaxial ratio r_b = d22 / d11
// (Barlat et al. 2003, section 5; plane_stress_yield.h for the response definitions).
//
// Equations (stresses in units of the normalising stress, normally sigma0 = 1; u(theta) the unit
// uniaxial stress, b = (1, 1, 0); n = dsigma_bar/ds, the flow direction):
//   sigma_theta sigma_bar(u(theta)) - 1 = 0                          theta = 0, 45, 90
//   sigma_b sigma_bar(b) - 1 = 0
//   n_ww(theta) + r_theta (n_11 + n_22)(theta) = 0                   (r = d_ww / d33, d33 = -(d11 +
//   d22)) n_22(b) - r_b n_11(b) = 0
// with n_ww = n . (sin^2, cos^2, -sin cos). At 0, 90 degrees and b the shear stress vanishes, so
// X'xy = X''xy = 0 and alpha7, alpha8 do not enter: the six equations at 0, 90 and b fix
// alpha1..alpha6, and then the two at 45 degrees fix alpha7, alpha8 (which enter squared; their
// sign is immaterial and reported positive). Each block is solved by Newton's method with a
// central-difference Jacobian and a backtracking line search on |R|^2, started at the isotropic
// point alpha = 1 (which solves the isotropic data sigma = r = 1 exactly for every exponent). If
// that fails, the data are approached by continuation from the isotropic data in equal steps,
// each Newton solve started from the previous solution.
// phi is unchanged by X' -> -X' (alpha1, alpha2 together) and X'' -> -X'' (alpha3..alpha6), so
// the result is reported with alpha1 > 0 and alpha3 + ... + alpha6 > 0.
#pragma once

#include <string>

#include "material/yld2000.h"

namespace vs {

struct AnisotropyData {
  double sigma0 = 1.0;  // yield stresses in units of the normalising stress (sigma0 = 1 normally)
  double sigma45 = 1.0;
  double sigma90 = 1.0;
  double sigma_b = 1.0;
  double r0 = 1.0;  // Lankford ratios
  double r45 = 1.0;
  double r90 = 1.0;
  double r_b = 1.0;  // d22 / d11 in equibiaxial tension
};

// The eight data a yield function predicts (sigma = 1 / sigma_bar(u)).
AnisotropyData predicted_anisotropy_data(const PlaneStressYield& yield);

struct Yld2000FitOptions {
  double exponent = 8.0;
  double tolerance = 1e-12;  // on the largest equation residual
  int max_iterations = 60;   // Newton iterations per block and continuation step
  int continuation_steps = 8;
};

struct Yld2000FitSummary {
  Yld2000Coefficients coefficients;
  bool converged = false;
  int iterations = 0;          // Newton iterations, all blocks and steps
  int continuation_steps = 0;  // 0: direct solve from alpha = 1
  double max_residual = 0.0;   // largest residual of the eight equations at the result
  std::string message;         // one line
};

// Throws InputError for non-positive or non-finite data or an exponent below 2.
Yld2000FitSummary fit_yld2000(const AnisotropyData& data, const Yld2000FitOptions& options = {});

}  // namespace vs
