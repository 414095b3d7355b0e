// Directional predictions for the ESAFORM 2021 AA6016-T4 sheet (no forming simulation): r(theta)
// and sigma(theta)/sigma0 of Hill 1948 from r-values, Hill 1948 from yield stresses and
// Yld2000-2d (a = 8), identified from each lab's data, beside the measurements at 0..90 degrees.
// The test prints the Markdown tables of forward/material/ANISOTROPY.md and checks that each model
// reproduces the data it was identified from. Run:
//   build/tests/vs_physics_tests --gtest_filter='AnisotropyReport.*'
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "material/hill48.h"
#include "material/yld2000.h"
#include "material/yld2000_fit.h"

namespace vs {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Measured {
  std::vector<double> theta_deg, sigma_ratio, r;
};

// data/measured/esaform2021-aa6016t4-cup/anisotropy_uniaxial_measured.csv: lab,theta_deg,
// sigma_ratio,r (Habraken et al. 2022, Table 4, via the PolyN repository; see that README).
std::map<std::string, Measured> ReadMeasured() {
  const std::string path = std::string(VS_SOURCE_DIR) + "/data/measured/esaform2021-aa6016t4-cup/" +
                           "anisotropy_uniaxial_measured.csv";
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::map<std::string, Measured> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("lab,", 0) == 0) continue;
    std::stringstream ss(line);
    std::string lab, field;
    std::getline(ss, lab, ',');
    double v[3];
    for (double& x : v) {
      std::getline(ss, field, ',');
      x = std::stod(field);
    }
    out[lab].theta_deg.push_back(v[0]);
    out[lab].sigma_ratio.push_back(v[1]);
    out[lab].r.push_back(v[2]);
  }
  return out;
}

double At(const Measured& m, const std::vector<double>& values, double theta_deg) {
  for (size_t i = 0; i < m.theta_deg.size(); ++i) {
    if (m.theta_deg[i] == theta_deg) return values[i];
  }
  ADD_FAILURE() << "no measurement at " << theta_deg;
  return 0.0;
}

// Balanced biaxial yield-stress ratio of each lab (the `d=1.0, 0.0, ...` rows of
// matAA6016T4_TUAT_UGent.txt and matAA6016T4_UA.txt in the same folder). Neither lab measured r_b
// (both files carry the isotropic placeholder); r_b = 1 is assumed for Yld2000-2d.
const std::map<std::string, double> kSigmaB = {{"TUAT", 1.0}, {"UA", 0.975}};

TEST(AnisotropyReport, EsaformAa6016T4DirectionalPredictions) {
  const std::map<std::string, Measured> measured = ReadMeasured();
  ASSERT_EQ(measured.size(), 2u);
  for (const auto& [lab, m] : measured) {
    AnisotropyData data;
    data.sigma45 = At(m, m.sigma_ratio, 45);
    data.sigma90 = At(m, m.sigma_ratio, 90);
    data.sigma_b = kSigmaB.at(lab);
    data.r0 = At(m, m.r, 0);
    data.r45 = At(m, m.r, 45);
    data.r90 = At(m, m.r, 90);
    data.r_b = 1.0;

    const Hill48Coefficients hr = hill48_from_r_values(data.r0, data.r45, data.r90);
    const Hill48Coefficients hs = hill48_from_stresses(data.sigma45, data.sigma90, data.sigma_b);
    const Yld2000FitSummary fit = fit_yld2000(data);
    ASSERT_TRUE(fit.converged) << lab << ": " << fit.message;
    const Hill48 hill_r(hr), hill_s(hs);
    const Yld2000 yld(fit.coefficients);
    const PlaneStressYield* models[3] = {&hill_r, &hill_s, &yld};

    // Each model reproduces what it was identified from.
    for (double theta : {0.0, 45.0, 90.0}) {
      const double r_meas = At(m, m.r, theta), s_meas = At(m, m.sigma_ratio, theta);
      EXPECT_NEAR(uniaxial_response(hill_r, theta * kDeg).r_value, r_meas, 1e-12);
      EXPECT_NEAR(uniaxial_response(hill_s, theta * kDeg).stress, s_meas, 1e-12);
      EXPECT_NEAR(uniaxial_response(yld, theta * kDeg).r_value, r_meas, 1e-11);
      EXPECT_NEAR(uniaxial_response(yld, theta * kDeg).stress, s_meas, 1e-11);
    }
    EXPECT_NEAR(equibiaxial_response(hill_s).stress, data.sigma_b, 1e-12);
    EXPECT_NEAR(equibiaxial_response(yld).stress, data.sigma_b, 1e-11);
    EXPECT_NEAR(equibiaxial_response(yld).r_value, data.r_b, 1e-11);

    fmt::print("\n#### {} (sigma_b/sigma0 = {}, r_b = 1 assumed)\n\n", lab, data.sigma_b);
    fmt::print(
        "| theta deg | r meas | r Hill48-r | r Hill48-s | r Yld2000 | s/s0 meas | s/s0 Hill48-r "
        "| s/s0 Hill48-s | s/s0 Yld2000 |\n");
    fmt::print("|---|---|---|---|---|---|---|---|---|\n");
    double sq_r[3] = {0, 0, 0}, sq_s[3] = {0, 0, 0};
    for (size_t i = 0; i < m.theta_deg.size(); ++i) {
      const double theta = m.theta_deg[i] * kDeg;
      fmt::print("| {:.0f} | {:.3f}", m.theta_deg[i], m.r[i]);
      double r[3], s[3];
      for (int k = 0; k < 3; ++k) {
        const DirectionalResponse p = uniaxial_response(*models[k], theta);
        r[k] = p.r_value;
        s[k] = p.stress / uniaxial_response(*models[k], 0.0).stress;
        sq_r[k] += (r[k] - m.r[i]) * (r[k] - m.r[i]);
        sq_s[k] += (s[k] - m.sigma_ratio[i]) * (s[k] - m.sigma_ratio[i]);
      }
      fmt::print(" | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", r[0], r[1],
                 r[2], m.sigma_ratio[i], s[0], s[1], s[2]);
    }
    const double n = static_cast<double>(m.theta_deg.size());
    fmt::print("| rms | | {:.3f} | {:.3f} | {:.3f} | | {:.3f} | {:.3f} | {:.3f} |\n",
               std::sqrt(sq_r[0] / n), std::sqrt(sq_r[1] / n), std::sqrt(sq_r[2] / n),
               std::sqrt(sq_s[0] / n), std::sqrt(sq_s[1] / n), std::sqrt(sq_s[2] / n));
    fmt::print(
        "\nbiaxial: sigma_b/sigma0 Hill48-r {:.3f}, Hill48-s {:.3f}, Yld2000 {:.3f}; "
        "r_b Hill48-r {:.3f}, Hill48-s {:.3f}, Yld2000 {:.3f}\n",
        equibiaxial_response(hill_r).stress, equibiaxial_response(hill_s).stress,
        equibiaxial_response(yld).stress, equibiaxial_response(hill_r).r_value,
        equibiaxial_response(hill_s).r_value, equibiaxial_response(yld).r_value);
    fmt::print("Hill48-r F G H N = {:.4f} {:.4f} {:.4f} {:.4f}\n", hr.F, hr.G, hr.H, hr.N);
    fmt::print("Hill48-s F G H N = {:.4f} {:.4f} {:.4f} {:.4f}\n", hs.F, hs.G, hs.H, hs.N);
    fmt::print("Yld2000 a=8 alpha1..8 = {:.4f}\n", fmt::join(fit.coefficients.alpha, " "));
    fmt::print("Yld2000 identification: {} ({} Newton iterations)\n", fit.message, fit.iterations);
  }
}

}  // namespace
}  // namespace vs
