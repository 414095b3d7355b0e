#include "calibration_keys.h"

#include <fmt/format.h>

#include <limits>
#include <utility>

#include "calibration_config.h"

namespace vs {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

KeySpec key(std::string_view section, std::string_view name, KeyType type, std::string_view unit,
            Range range, std::string (*default_text)(), std::string_view doc) {
  KeySpec k;
  k.section = section;
  k.name = name;
  k.type = type;
  k.unit = unit;
  k.range = range;
  k.default_text = default_text;
  k.doc = doc;
  return k;
}

KeySpec required(std::string_view section, std::string_view name, KeyType type,
                 std::string_view doc) {
  KeySpec k = key(section, name, type, "", Range{}, nullptr, doc);
  k.required = true;
  return k;
}

KeySpec choice(std::string_view section, std::string_view name,
               std::vector<std::string_view> choices, std::string (*default_text)(),
               std::string_view doc) {
  KeySpec k = key(section, name, KeyType::kEnum, "", Range{}, default_text, doc);
  k.choices = std::move(choices);
  return k;
}

std::string quoted(const std::string& s) { return fmt::format("\"{}\"", s); }

// Defaults are read from default-constructed option structs, so they are declared once (in the
// structs' headers); captureless lambdas, as KeySpec::default_text is a plain function pointer.
const OptimizerSettings& optimizer() {
  static const OptimizerSettings o;
  return o;
}
const UncertaintyOptions& uncertainty() {
  static const UncertaintyOptions u;
  return u;
}

std::vector<KeySpec> build() {
  const auto kFloat = KeyType::kFloat;
  const auto kInt = KeyType::kInt;
  const auto kBool = KeyType::kBool;
  const auto kString = KeyType::kString;
  const Range any{-kInf, kInf, true, true};
  std::vector<KeySpec> k;

  k.push_back(required("", "scene", kString,
                       "The base scene file, relative to this file (a string); or several "
                       "scenes as [[scene]] tables, and each [[data]] names its scene."));

  k.push_back(
      required("scene", "name", kString, "Label the [[data]] tables refer to (scene = \"...\")."));
  k.back().identifier = true;
  k.push_back(required("scene", "file", kString, "Scene file, relative to this file."));

  const std::string_view p = "parameter";
  k.push_back(required(p, "address", kString,
                       "Dotted scene address of a float key: material.hardening.K_MPa, "
                       "tool.punch.friction, ... (docs/scene-reference.md, Addresses). Integer "
                       "keys (blank.elements, ...) cannot be calibrated; set them in "
                       "[forward.set]."));
  k.push_back(key(
      p, "initial", kFloat, "", any, [] { return std::string("(the scene's value)"); },
      "Start value, finite, in the parameter's own unit; omitted = the scene's value "
      "(with [forward.set] applied)."));
  k.push_back(key(
      p, "lower", kFloat, "", any, [] { return float_toml_text(-kInf); },
      "Lower bound (global_then_local needs finite bounds)."));
  k.push_back(key(
      p, "upper", kFloat, "", any, [] { return float_toml_text(kInf); }, "Upper bound."));
  k.push_back(key(
      p, "scale", kFloat, "", open_above(0), [] { return std::string("(|initial|, or 1 if 0)"); },
      "Typical magnitude in the parameter's unit: the optimiser works on value / "
      "scale, finite-difference steps are relative_step x scale, and a value below "
      "1 % of the scale counts as zero in the relative-error check."));
  k.push_back(key(
      p, "fixed", kBool, "", Range{}, [] { return std::string("false"); },
      "Hold the parameter at initial instead of identifying it."));

  const std::string_view d = "data";
  k.push_back(choice(
      d, "kind",
      {"load_travel", "thickness_strain", "circumferential_strain", "cup_height_profile"}, nullptr,
      "What the file measures: punch force against punch travel, a strain "
      "profile against the initial radius r0 at one punch travel, or the cup "
      "height (earing profile) against the angle from the rolling direction at "
      "the end of a 3D cup draw (compared with the run's final rim profile, "
      "interpolated periodically at the measured angles)."));
  k.back().required = true;
  k.push_back(required(d, "file", kString,
                       "Measurement CSV, relative to this file: the format below, or a vshell "
                       "output file (load_travel.csv, strains_travel_<T>mm.csv, "
                       "cup_profile.csv) as written; cup_height_profile also reads the "
                       "headerless 2-column form 'angle_from_rd_deg, cup_height_mm' (deg, mm) "
                       "of the ESAFORM 2021 file."));
  k.push_back(key(
      d, "source", kString, "", Range{}, [] { return std::string(""); },
      "Provenance of a file without a '# source:' line (e.g. the headerless ESAFORM "
      "profile, whose provenance is its folder's README): where the data come from. A file "
      "with its own '# source:' line cannot have this too."));
  k.push_back(key(
      d, "shape_only", kBool, "", Range{}, [] { return std::string("false"); },
      "cup_height_profile only: fit the profile's shape, up to the best constant offset "
      "(the weighted mean of measured - simulated is added to the simulated heights), so "
      "that the mean cup height, which friction and hardening set more than the r-values, "
      "drops out."));
  k.push_back(key(
      d, "sigma", kFloat, "N, 1 or mm", open_above(0), [] { return std::string(""); },
      "Standard deviation of every point, in the ordinate's internal unit (N for "
      "forces, 1 for strains, mm for cup heights); weights are 1 / sigma. Give sigma, weight or a "
      "sigma "
      "column, or leave all out for the relative default (relative_sigma)."));
  k.push_back(key(
      d, "weight", kFloat, "1/N, 1 or 1/mm", open_above(0), [] { return std::string(""); },
      "Weight of every point instead of sigma (residual = weight x difference)."));
  k.push_back(key(
      d, "relative_sigma", kFloat, "", open_closed(0, 1),
      [] { return float_toml_text(kDefaultRelativeSigma); },
      "When the data set gives no sigma, weight or sigma column: sigma = "
      "relative_sigma x (max - min) of the measured ordinate, so that curves of "
      "different quantities weigh alike. The report states the sigma used. It is a weighting, "
      "not a noise estimate: the lack-of-fit verdict of such a data set is judged against the "
      "forward resolution instead (lack_of_fit_min_resolutions)."));
  k.push_back(key(
      d, "travel_mm", kFloat, "mm", open_above(0), [] { return std::string(""); },
      "Strain profiles only: the punch travel the profile was taken at. Read from the "
      "'# punch_travel_mm=' line of a vshell strains file when omitted. (A cup height "
      "profile is always the run's final one.)"));
  k.push_back(key(
      d, "name", kString, "", Range{}, [] { return std::string("(file name without .csv)"); },
      "Label in reports and fit_<name>.csv: letters, digits, _ - ."));
  k.push_back(key(
      d, "scene", kString, "", Range{}, [] { return std::string(""); },
      "With several [[scene]]s: the scene this data set is compared with."));
  k.push_back(key(
      d, "columns", KeyType::kTable, "", Range{}, [] { return std::string(""); },
      "Column mapping for files with other headers: { NAME = \"header in the file\", "
      "... } with NAME one of punch_travel_mm, punch_force_N, punch_force_kN "
      "(load_travel), r0_mm, eps_thickness, eps_circumferential (profiles), "
      "angle_from_rd_deg, cup_height_mm (cup_height_profile), sigma. "
      "Unmapped columns of the file are then ignored."));

  const std::string_view o = "optimizer";
  k.push_back(choice(
      o, "method", {"levenberg_marquardt", "global_then_local"},
      [] { return quoted("levenberg_marquardt"); },
      "levenberg_marquardt: Ceres from the initial values; global_then_local: an "
      "NLopt global search within the bounds, then Levenberg-Marquardt."));
  k.push_back(key(
      o, "max_iterations", kInt, "", closed(0, 1000),
      [] { return std::to_string(optimizer().least_squares.max_iterations); },
      "Levenberg-Marquardt iterations (each costs 1 + 2 x free parameters forward "
      "runs with central differences)."));
  k.back().bound_reason = "each iteration is several forward runs; 1000 is hours of runs";
  k.push_back(key(
      o, "function_tolerance", kFloat, "", at_least(0),
      [] { return float_toml_text(optimizer().least_squares.function_tolerance); },
      "Ceres: stop when the relative cost decrease is below this."));
  k.push_back(key(
      o, "gradient_tolerance", kFloat, "", at_least(0),
      [] { return float_toml_text(optimizer().least_squares.gradient_tolerance); },
      "Ceres: stop when the scaled gradient is below this."));
  k.push_back(key(
      o, "parameter_tolerance", kFloat, "", at_least(0),
      [] { return float_toml_text(optimizer().least_squares.parameter_tolerance); },
      "Ceres: stop when the relative step is below this."));
  k.push_back(choice(
      o, "fd", {"central", "ridders"}, [] { return quoted("central"); },
      "Finite differences: central (2 runs per parameter) or Ridders "
      "extrapolation (2 x ridders_levels runs per parameter)."));
  k.push_back(key(
      o, "relative_step", kFloat, "", Range{0, 1, false, false},
      [] { return float_toml_text(optimizer().fd.relative_step); },
      "Finite-difference step = relative_step x scale. The noise error is ~ forward "
      "tolerance / step, the truncation error ~ step^2: 0.05 needed the fewest forward runs "
      "on the bundled fits and kept their intervals truthful, where 2e-3 gave intervals 4x "
      "too narrow on noisy data (data/calibration/README.md, Status)."));
  k.push_back(key(
      o, "ridders_levels", kInt, "", closed(2, 10),
      [] { return std::to_string(optimizer().fd.ridders_levels); },
      "Ridders: steps h, h/2, ..., h/2^(levels-1)."));
  k.push_back(key(
      o, "noise_floor_factor", kFloat, "", closed(0, 1e6),
      [] { return float_toml_text(kDefaultNoiseFloorFactor); },
      "Stop at the forward solver's noise floor: each simulated value is taken to be resolved "
      "to noise_floor_factor x [forward] tolerance x the data set's largest |value|; when the "
      "best cost decrease the linearised model still offers is below what that resolution "
      "can tell apart, the fit stops (\"stopped at the noise floor\"). The default covers the "
      "jitter measured in experiments/06_step_stability (1x the tolerance in force, ~17x in "
      "thickness strain). 0 turns the stop off."));
  k.push_back(key(
      o, "active_set", kBool, "", Range{},
      [] { return std::string(optimizer().least_squares.active_set ? "true" : "false"); },
      "Hold a parameter that the cost pushes against a bound ON the bound and solve for the "
      "others, releasing it when the cost pulls it back; false lets Ceres project its steps "
      "onto the bounds, which creeps along an active bound."));
  k.push_back(key(
      o, "threads", kInt, "", closed(1, 256), [] { return std::to_string(optimizer().threads); },
      "Forward runs in parallel (finite differences, global search batches)."));
  k.push_back(choice(
      o, "global_algorithm", {"mlsl_lds", "crs2", "direct", "bobyqa", "surface"},
      [] { return quoted(optimizer().global.algorithm); },
      "Algorithm of the global search: NLopt's mlsl_lds, crs2, direct (global) or bobyqa (local, "
      "derivative-free, from the initial values); or surface: the cost on a grid around the "
      "initial values (grid_points per free parameter, +- grid_half_width scales, run in "
      "parallel) and the minimum of the least-squares quadratic through it, for a forward model "
      "too noisy for a local search (a 3D cup's rim profile: experiments/10_earing)."));
  k.back().applies_to = {"method global_then_local"};
  k.push_back(key(
      o, "grid_points", kInt, "", closed(3, 101),
      [] { return std::to_string(optimizer().global.grid_points); },
      "global_algorithm surface: grid points per free parameter (surface_rounds (grid_points^free "
      "+ 1) evaluations, at most max_evaluations)."));
  k.back().applies_to = {"global_algorithm surface"};
  k.back().bound_reason = "a quadratic needs 3 points per parameter";
  k.push_back(key(
      o, "grid_half_width", kFloat, "scales", Range{0, 1000, false, true},
      [] { return fmt::format("{}", optimizer().global.grid_half_width); },
      "global_algorithm surface: the grid spans the initial value +- this many parameter "
      "scales (clipped to the bounds)."));
  k.back().applies_to = {"global_algorithm surface"};
  k.push_back(key(
      o, "surface_rounds", kInt, "", closed(1, 10),
      [] { return std::to_string(optimizer().global.surface_rounds); },
      "global_algorithm surface: zoom rounds; each next round is the grid again, centred on the "
      "previous round's answer with half its half width (a first grid too wide for the cost's "
      "curvature puts the quadratic's minimum off; experiments/10_earing)."));
  k.back().applies_to = {"global_algorithm surface"};
  k.push_back(key(
      o, "seed", kInt, "", at_least(0), [] { return std::to_string(optimizer().global.seed); },
      "NLopt seed: the global search is deterministic for a given seed."));
  k.back().applies_to = {"method global_then_local"};
  k.push_back(key(
      o, "max_evaluations", kInt, "", closed(1, 10000),
      [] { return std::to_string(optimizer().global.max_evaluations); },
      "Forward evaluations of the global search (its only stopping rule)."));
  k.back().applies_to = {"method global_then_local"};
  k.back().bound_reason = "each evaluation is a forward run; 10000 is hours of runs";

  const std::string_view u = "uncertainty";
  k.push_back(key(
      u, "confidence", kFloat, "", Range{0, 1, false, false},
      [] { return float_toml_text(uncertainty().confidence); },
      "Confidence level of the reported intervals."));
  k.push_back(key(
      u, "scale_by_residual_variance", kBool, "", Range{},
      [] { return std::string(uncertainty().scale_by_residual_variance ? "true" : "false"); },
      "Scale the covariance by the residual variance (Student-t intervals); false "
      "trusts the stated sigmas (normal intervals)."));
  k.push_back(key(
      u, "rank_tolerance", kFloat, "", Range{0, 1, false, false},
      [] { return float_toml_text(uncertainty().rank_tolerance); },
      "Singular values below this x the largest count as zero (undetermined "
      "directions)."));
  k.push_back(key(
      u, "correlation_threshold", kFloat, "", open_closed(0, 1),
      [] { return float_toml_text(uncertainty().correlation_threshold); },
      "|correlation| above this: both parameters are reported poorly determined."));
  k.push_back(key(
      u, "relative_error_threshold", kFloat, "", open_above(0),
      [] { return float_toml_text(uncertainty().relative_error_threshold); },
      "Standard error / |value| (or / scale for values near zero) above this: "
      "poorly determined."));

  k.push_back(key(
      u, "lack_of_fit_significance", kFloat, "", Range{0, 0.5, false, false},
      [] { return float_toml_text(uncertainty().lack_of_fit.significance); },
      "Lack-of-fit diagnostic per data set: one-sided level of the runs test and of the lag-1 "
      "autocorrelation test on the normalised residuals (simulated - measured) / sigma (or / "
      "the forward resolution when the data set states no sigma). Either test rejecting "
      "independent noise is a pattern."));
  k.push_back(key(
      u, "lack_of_fit_min_rms", kFloat, "", at_least(0),
      [] { return float_toml_text(uncertainty().lack_of_fit.min_rms); },
      "Data sets with a stated sigma (sigma, weight or a sigma column): a pattern whose rms "
      "is at least this many sigmas is reported as STRUCTURAL misfit (model-form error, not "
      "noise); smaller patterns are negligible."));
  k.push_back(key(
      u, "lack_of_fit_min_resolutions", kFloat, "", at_least(0),
      [] { return float_toml_text(uncertainty().lack_of_fit.min_resolutions); },
      "Data sets with no stated sigma (the relative default is a fraction of the range, not a "
      "noise scale): a pattern whose rms is at least this many forward resolutions "
      "(noise_floor_factor x tolerance x the curve's largest |value|; the default factor when "
      "noise_floor_factor = 0) is STRUCTURAL, and the report gives its size in the data's "
      "units and says that its size against the measurement noise is unknown. A fit that "
      "stops at the noise floor leaves at most (1 + sqrt 3) = 2.7 resolutions rms "
      "(inverse/lack_of_fit.h); smaller patterns are the solver's convergence noise."));

  k.push_back(required("model_form", "name", kString,
                       "Label of the alternative model choice in the report."));
  k.push_back(key(
      "model_form", "set", KeyType::kTable, "", Range{}, [] { return std::string("none"); },
      "Scene edits of the alternative, as in [forward.set] and added to it: "
      "{ \"blank.elements\" = 48 }, { \"numerics.thickness_points\" = 9 }, "
      "{ \"numerics.strain_rate_cutoff\" = 1e-4 }, { \"numerics.transverse_shear_scale\" = 0.3 } "
      "(the shell's shear penalty, a choice with no material value that moves thickness "
      "profiles by the size of a shell's model-form error). Checked before any forward "
      "run. An alternative has set, drop_data or both."));
  k.push_back(key(
      "model_form", "drop_data", KeyType::kStringArray, "", Range{},
      [] { return std::string("none"); },
      "Data sets (their names in the report) the alternative fit leaves out: "
      "[\"thick_15\"]. A data choice as a model-form alternative: when the data "
      "sets agree on the parameters only within the statistical intervals, leaving "
      "one out moves the fit little; when the model cannot represent all of them at "
      "once, the range shows it. What it keeps must still determine the free "
      "parameters (checked before any forward run)."));

  k.push_back(key(
      "model_form", "discrepancy", KeyType::kStringArray, "", Range{},
      [] { return std::string("(every source)"); },
      "The [[discrepancy]] sources (their names) the alternative keeps: [\"continuum, "
      "friction 0\"] refits with that source's correction alone, [] without any correction. "
      "With two or more sources an alternative per source is added by itself; use this for "
      "other subsets or for the fit without correction."));

  k.push_back(required("discrepancy", "name", kString,
                       "Label of the reference in the report and in model_form.discrepancy."));
  k.push_back(
      key("discrepancy", "set", KeyType::kTable, "", Range{}, nullptr,
          "The parameters the reference was computed with, every free one (and a fixed one where "
          "it differs), plus any other scene edit that makes the forward model the reference's "
          "twin, as in [forward.set] and added to it: { \"tool.punch.friction\" = 0.0, "
          "\"material.hardening.K_MPa\" = 530 }. The forward model is run once at these values "
          "before the fit."));
  k.back().required = true;
  k.push_back(
      key("discrepancy", "files", KeyType::kTable, "", Range{}, nullptr,
          "The reference's curves, one per data set it covers, by data-set name: { thick_25 = "
          "\"continuum/thick_25.csv\", load = \"continuum/load.csv\" }, relative to this file, "
          "in the data set's format and kind (measurement files below; vshell's own outputs are "
          "read too). Each must span its data set's abscissae (it is interpolated linearly, never "
          "extrapolated); a data set no source covers is not corrected."));
  k.back().required = true;

  k.push_back(key(
      "forward", "tolerance", kFloat, "", closed(0, 0.1),
      [] { return float_toml_text(ForwardSettings{}.tolerance); },
      "numerics.tolerance of every forward run during the calibration (finite "
      "differences need tight convergence); 0 keeps the scene's value."));
  k.push_back(key(
      "forward", "set", KeyType::kTable, "", Range{}, [] { return std::string(""); },
      "Scene edits for every forward run, as \"address\" = value (a coarser mesh, "
      "held parameters): [forward.set] \"blank.elements\" = 24. Checked as the scene "
      "would check them."));

  k.push_back(key(
      "output", "directory", kString, "", Range{},
      [] { return quoted(CalibrationConfig{}.output_directory); },
      "Report folder, relative to the current folder (vshell calibrate -o "
      "overrides it)."));
  k.push_back(key(
      "output", "plots", kBool, "", Range{},
      [] { return std::string(CalibrationConfig{}.plots ? "true" : "false"); },
      "Write the measured-vs-fitted and cost plots (SVG)."));
  return k;
}

}  // namespace

const std::vector<KeySpec>& calibration_keys() {
  static const std::vector<KeySpec> keys = build();
  return keys;
}

const std::vector<SectionSpec>& calibration_sections() {
  static const std::vector<SectionSpec> sections = {
      {"", "(top level)", "The base scene."},
      {"scene", "[[scene]]", "Several base scenes (instead of scene = \"...\"), one table each."},
      {"parameter", "[[parameter]]", "One table per scene number to identify or hold."},
      {"data", "[[data]]", "One table per measured curve."},
      {"optimizer", "[optimizer]", "Least-squares method, finite differences, parallel runs."},
      {"uncertainty", "[uncertainty]",
       "Covariance, intervals and the plain-language checks. Each interval also includes the "
       "parameter's forward resolution (how far the forward solver's convergence noise lets "
       "the fit stop from the least-squares optimum; calibration.json forward_resolution), "
       "and each data set gets a lack-of-fit verdict (noise, structural, negligible): a "
       "systematic pattern is judged against the stated sigma or, when the data set states "
       "none, against the forward solver's resolution, never against the relative default. "
       "When the fit stopped before converging, a structural verdict says that part of the "
       "misfit may be the unfinished fit (calibration.json fit_converged false)."},
      {"forward", "[forward]", "Settings of every forward run of the calibration."},
      {"model_form", "[[model_form]]",
       "Model-form sensitivity: one table per alternative model choice (a finer mesh, another "
       "element rule, the strain-rate cut-off, ...). After the fit, the fit is repeated under "
       "each alternative from the identified values, and the report gives, beside each "
       "statistical interval, the model-form range: the smallest and largest value over the "
       "main fit and the alternatives."},
      {"discrepancy", "[[discrepancy]]",
       "Model-discrepancy correction: curves of a higher-fidelity reference model (a continuum "
       "FE run of the same test, ...) computed at known parameters, one table per reference. "
       "Before the fit the forward model is run at each reference's parameters; at every point "
       "of each data set a reference covers, reference - forward is the correction, and the "
       "fit compares the data with forward + correction (the mean over the references that "
       "cover the data set). It removes the forward model's model-form error to the extent "
       "that this error does not change with the parameters: with two or more references each "
       "alone is refitted as a model-form alternative, so the range shows how far that "
       "assumption moves the fit. The report gives each correction's size per data set, and "
       "fit_<name>.csv its value per point (experiments/08_continuum_reference, section 13)."},
      {"output", "[output]", "The report folder."},
  };
  return sections;
}

const KeySpec* find_calibration_key(std::string_view section, std::string_view name) {
  for (const KeySpec& k : calibration_keys()) {
    if (k.section == section && k.name == name) return &k;
  }
  return nullptr;
}

std::string calibration_reference_markdown() {
  std::string out =
      "<!-- Generated by calibration_reference_markdown() (inverse/calibration_keys.cc) from the\n"
      "     key declaration there. Do not edit by hand; regenerate with\n"
      "     build/tests/vs_inverse_tests --gtest_also_run_disabled_tests "
      "--gtest_filter='*RegenerateCalibrationReference*' -->\n\n"
      "# Calibration config reference\n\n"
      "`vshell calibrate CONFIG [-o DIR] [--quiet]` identifies scene numbers (friction, "
      "hardening, R, ...) from measured curves. CONFIG is a TOML file; every key below has a "
      "type, a default (or is required), a unit and an allowed range. Unknown keys, wrong "
      "types and out-of-range values are errors reported as one line `FILE:LINE: key '...': "
      "message`, before any forward run. Units as in scenes: mm, N, s, MPa; parameters are in "
      "the unit of their scene key.\n\n"
      "Exit codes: 0 the fit converged or stopped at its iteration limit (the report says "
      "which), 2 bad input, 3 the calibration failed (every forward run failing, or the run at "
      "the initial parameters failing): the reason is printed on stderr as one line and "
      "written to `calibration.json` (`termination = \"failed\"`, `failure`).\n\n"
      "```toml\n"
      "scene = \"../scenes/ex1_hemispherical_stretching.toml\"\n\n"
      "[[parameter]]\n"
      "address = \"tool.punch.friction\"\n"
      "initial = 0.07\nlower = 0.0\nupper = 0.5\nscale = 0.1\n\n"
      "[[data]]\n"
      "kind = \"thickness_strain\"\n"
      "file = \"thick_20mm.csv\"\n"
      "travel_mm = 20\n"
      "sigma = 0.002\n\n"
      "[forward.set]\n"
      "\"blank.elements\" = 24\n"
      "```\n\n"
      "## Keys\n\n";
  for (const SectionSpec& section : calibration_sections()) {
    out += fmt::format("### {}\n\n{}\n\n", section.header, section.doc);
    out += key_table_markdown(calibration_keys(), section.name) + "\n";
  }
  out +=
      "## Measurement files\n\n"
      "CSV, one header line of column names, then one point per line; the abscissa strictly "
      "increasing. Lines starting with `#` before the header are provenance `# key: value`; "
      "`# source:` and `# units:` are required. The units line names the unit of each column "
      "(any order; remarks in parentheses are ignored) and must match the columns: `mm` for "
      "`punch_travel_mm` and `r0_mm`, `N` or `kN` for the force, `1` or `-` for strains, "
      "`deg` for `angle_from_rd_deg` and `mm` for `cup_height_mm`. A "
      "UTF-8 byte order mark is skipped; invisible characters in a header (tabs, no-break "
      "spaces) are named in the error (`U+0009 TAB`).\n\n"
      "| kind | columns |\n|---|---|\n"
      "| `load_travel` | `punch_travel_mm`, `punch_force_N` or `punch_force_kN`, optional "
      "`sigma` |\n"
      "| `thickness_strain` | `r0_mm`, `eps_thickness`, optional `sigma` |\n"
      "| `circumferential_strain` | `r0_mm`, `eps_circumferential`, optional `sigma` |\n"
      "| `cup_height_profile` | `angle_from_rd_deg`, `cup_height_mm`, optional `sigma` |\n\n"
      "`sigma` is the per-point standard deviation in the unit of the ordinate column as "
      "written (kN for `punch_force_kN`). Other headers: map them with `columns`.\n\n"
      "vshell's own outputs are accepted as they are written: `load_travel.csv` (kind "
      "`load_travel`; the step at travel 0 is kept) and `strains_travel_<T>mm.csv` (kind "
      "`thickness_strain` or `circumferential_strain`; `travel_mm` from its "
      "`# punch_travel_mm=` line). They need no provenance lines; their other columns are "
      "ignored.\n\n"
      "### Cup height profiles\n\n"
      "`cup_height_profile` data are the cup height around the rim of a drawn cup against the "
      "angle from the rolling direction (angles in [0, 360], increasing, spanning less than one "
      "turn). They are compared with the run's FINAL rim profile (the `cup_profile.csv` the run "
      "writes: a quarter model unfolded to 360 deg), read as a periodic piecewise-linear function "
      "of the angle (joined across 0/360) at the measured angles; the scene must be a 3D cup "
      "(`geometry = \"shell3d\"`, free blank edge), a run that did not complete or has no rim "
      "profile is a failed evaluation with the reason, and parameters may not move `blank.*` or "
      "the rolling direction (the rim is identified with the configured scene). Besides the CSV "
      "form, the headerless 2-column form of the ESAFORM 2021 file is read: every line `angle, "
      "height` in deg and mm (comma and/or spaces); its provenance is a `# source:` line or the "
      "data set's `source` key. A run's own `cup_profile.csv` is read as written. "
      "`shape_only = true` compares the profile up to the best constant offset (the weighted "
      "mean of measured - simulated, added to the simulated heights and reported as "
      "`shape_offset_mm`): the mean height, set by friction and hardening as much as by the "
      "r-values, then drops out, and each such offset counts as a parameter in the degrees of "
      "freedom of the residual variance and the intervals.\n\n"
      "## Weights\n\n"
      "Residuals are `weight x (simulated - measured)` with weight = 1 / sigma per point "
      "(the `sigma` column), per data set (`sigma`), or `weight`. With none of these the "
      "data set gets sigma = `relative_sigma` x (max - min) of its measured ordinate (1 % by "
      "default), and the report says so.\n\n"
      "## Report folder\n\n"
      "`calibration.json` (identified values, standard errors, intervals, correlations, "
      "statements, termination and whether the fit stopped at the noise floor, parameters at "
      "a bound with the bound's effect, the lack-of-fit diagnostic per data set, the "
      "model-form fits and ranges, the forward model's warnings at the identified "
      "parameters and in each model-form fit (`forward_warnings`: e.g. elements shorter than "
      "the thickness; the printed report repeats them, and the progress says at once when the "
      "run at the initial parameters warns); non-finite numbers are left out "
      "rather than written as null), "
      "`evaluations.csv` (every forward evaluation; a failed one has status `failed`, an "
      "empty cost and the reason), `fit_<name>.csv` and `.svg` (measured against simulated at "
      "the optimum), `cost.svg` and `identified_<scene>.toml` per scene (the scene with the "
      "identified values written in, as the fit ran it: `vshell run` on it reproduces the "
      "fit's forward run, into `run_identified_<scene>` beside the report).\n";
  return out;
}

}  // namespace vs
