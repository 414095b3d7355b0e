#include "scene/scene_keys.h"

#include <fmt/format.h>

#include <cmath>
#include <type_traits>
#include <utility>

#include "scene/text_checks.h"

namespace vs {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where each section lives in a Scene. [[tool]] keys live in the ToolSpec being read.
Scene& top(Scene& s, ToolSpec&) { return s; }
BlankSpec& blank(Scene& s, ToolSpec&) { return s.blank; }
MaterialSpec& material(Scene& s, ToolSpec&) { return s.material; }
HardeningSpec& hardening(Scene& s, ToolSpec&) { return s.material.hardening; }
RateSpec& rate(Scene& s, ToolSpec&) { return s.material.rate; }
AnisotropySpec& anisotropy(Scene& s, ToolSpec&) { return s.material.anisotropy; }
ElasticSpec& elastic(Scene& s, ToolSpec&) { return s.material.elastic; }
ToolSpec& tool(Scene&, ToolSpec& t) { return t; }
ProcessSpec& process(Scene& s, ToolSpec&) { return s.process; }
NumericsSpec& numerics(Scene& s, ToolSpec&) { return s.numerics; }
FormingLimitSpec& forming_limit(Scene& s, ToolSpec&) { return s.forming_limit; }
OutputSpec& output(Scene& s, ToolSpec&) { return s.output; }

template <auto kSection, auto kMember>
auto& member(Scene& s, ToolSpec& t) {
  return kSection(s, t).*kMember;
}

// Enum keys: the enumerators are declared in the same order as KeySpec::choices.
template <auto kSection, auto kMember>
int get_enum(Scene& s, ToolSpec& t) {
  return static_cast<int>(kSection(s, t).*kMember);
}

template <auto kSection, auto kMember>
void set_enum(Scene& s, ToolSpec& t, int index) {
  auto& value = kSection(s, t).*kMember;
  value = static_cast<std::remove_reference_t<decltype(value)>>(index);
}

template <auto kSection, auto kMember>
KeyField float_field() {
  KeyField f;
  f.number = &member<kSection, kMember>;
  return f;
}
template <auto kSection, auto kMember>
KeyField int_field() {
  KeyField f;
  f.integer = &member<kSection, kMember>;
  return f;
}
template <auto kSection, auto kMember>
KeyField bool_field() {
  KeyField f;
  f.flag = &member<kSection, kMember>;
  return f;
}
template <auto kSection, auto kMember>
KeyField string_field() {
  KeyField f;
  f.text = &member<kSection, kMember>;
  return f;
}
template <auto kSection, auto kMember>
KeyField array_field() {
  KeyField f;
  f.numbers = &member<kSection, kMember>;
  return f;
}
template <auto kSection, auto kMember>
KeyField enum_field() {
  KeyField f;
  f.get_choice = &get_enum<kSection, kMember>;
  f.set_choice = &set_enum<kSection, kMember>;
  return f;
}

KeySpec make(std::string_view section, std::string_view name, KeyType type, KeyField field,
             std::string_view unit, Range range, std::string_view doc) {
  KeySpec k;
  k.section = section;
  k.name = name;
  k.type = type;
  k.field = field;
  k.unit = unit;
  k.range = range;
  k.doc = doc;
  return k;
}

KeySpec choice(std::string_view section, std::string_view name, KeyField field,
               std::vector<std::string_view> choices, std::string_view doc) {
  KeySpec k = make(section, name, KeyType::kEnum, field, "", Range{}, doc);
  k.choices = std::move(choices);
  return k;
}

std::vector<KeySpec> build_keys() {
  std::vector<KeySpec> keys;
  auto add = [&keys](KeySpec k) -> KeySpec& {
    keys.push_back(std::move(k));
    return keys.back();
  };
  const auto kFloat = KeyType::kFloat;
  const auto kInt = KeyType::kInt;

  // Top level.
  add(make("", "title", KeyType::kString, string_field<&top, &Scene::title>(), "", Range{},
           "Free text shown in outputs and plots."));
  add(choice("", "geometry", enum_field<&top, &Scene::geometry>(), {"axisymmetric", "shell3d"},
             "Model geometry: axisymmetric (2-node conical shell along the meridian) or shell3d "
             "(9-node 3D shell; keys marked 'shell3d only' apply)."));

  // [blank]
  add(make("blank", "radius_mm", kFloat, float_field<&blank, &BlankSpec::radius_mm>(), "mm",
           open_above(0),
           "Initial outer radius of the circular blank (shell3d square blank: half side)."));
  add(make("blank", "thickness_mm", kFloat, float_field<&blank, &BlankSpec::thickness_mm>(), "mm",
           open_above(0), "Initial sheet thickness (must be < radius_mm / 5: thin shell)."));
  add(make("blank", "elements", kInt, int_field<&blank, &BlankSpec::elements>(), "",
           closed(4, 2000),
           "Number of 2-node elements along the meridian (axisymmetric only). The travel per "
           "step is capped relative to the element length, so run time and per-step history "
           "grow with the square of the count: ex1 to 10 mm takes 0.25 s at 50 elements, 2.6 s "
           "at 200 and, extrapolated, about 5 min and 4 GB of history at 2000 (the limit; see "
           "the run-size rule)."))
      .geometry = "axisymmetric";
  keys.back().bound_reason =
      "run time and per-step history grow with the square of the element count (2000 "
      "elements: minutes and GBs)";
  add(make("blank", "grading", kFloat, float_field<&blank, &BlankSpec::grading>(), "",
           open_above(0),
           "Length ratio last/first element (geometric); < 1 refines the rim, > 1 the pole "
           "(axisymmetric only)."))
      .geometry = "axisymmetric";
  add(choice("blank", "edge", enum_field<&blank, &BlankSpec::edge>(), {"pinned", "clamped", "free"},
             "Edge (rim) condition: pinned (no motion, rotation free; in 3D also none along the "
             "edge), clamped (also no rotation), free (draws in; needs a die). See 'Edge "
             "conditions'."));
  add(choice("blank", "shape", enum_field<&blank, &BlankSpec::shape>(), {"circle", "square"},
             "Blank outline (shell3d only): circle of radius radius_mm, or square of half side "
             "radius_mm centred on the punch axis."))
      .geometry = "shell3d";
  add(choice("blank", "symmetry", enum_field<&blank, &BlankSpec::symmetry>(), {"quarter", "full"},
             "Part meshed (shell3d only): quarter = x, y >= 0 with symmetry planes x = 0 and "
             "y = 0 (forces reported for the whole blank); full = the whole blank, no symmetry "
             "planes (4x the elements)."))
      .geometry = "shell3d";
  add(make("blank", "divisions", kInt, int_field<&blank, &BlankSpec::divisions>(), "",
           closed(1, 64),
           "9-node elements along each quarter-model block edge (shell3d only): the quarter "
           "circle has 3 n x n blocks (3 n^2 elements), the quarter square one (n^2); a full "
           "blank is the quarter mesh mirrored onto all four quadrants (4x the elements). A "
           "3D step costs about 0.15-0.35 ms per element on 2 cores (ex4a, friction 0.2, to "
           "30 mm: 2.2 s at 8, 17-20 s at 16, 3.8 min at 32; a 2-core AMD EPYC, 27 Nov 2026); "
           "the run-size rule bounds divisions x travel."))
      .geometry = "shell3d";
  {
    KeySpec& k = add(make(
        "blank", "radial_divisions", kInt, int_field<&blank, &BlankSpec::radial_divisions>(), "",
        closed(1, 128),
        "Circular blank (shell3d only): 9-node elements across the ring from the central "
        "square to the rim, m; the quarter circle then has n^2 + 2 n m elements. More than "
        "divisions refines the outer ring (the flange, the die shoulder, the wall) without the "
        "centre: on a deep-drawn cup the ring's nodes run over the die shoulder one by one, and "
        "too few of them make the contact chatter (experiments/10_earing). Default: divisions."));
    k.geometry = "shell3d";
    k.default_text = [] { return std::string("(= divisions)"); };
  }

  // [material]
  add(make("material", "r_value", kFloat, float_field<&material, &MaterialSpec::r_value>(), "",
           closed(0.05, 20),
           "Normal anisotropy (Lankford) R; Hill 1948, planar isotropy, normalised to the "
           "in-plane uniaxial curve."));

  // [material.anisotropy]
  const std::string_view an = "material.anisotropy";
  add(choice(an, "model", enum_field<&anisotropy, &AnisotropySpec::model>(),
             {"normal", "hill48_r", "hill48_stress", "yld2000"},
             "Yield function: normal = Hill 1948 with normal anisotropy material.r_value (no "
             "planar anisotropy); hill48_r = Hill 1948 from r0, r45, r90; hill48_stress = Hill "
             "1948 from sigma45_ratio, sigma90_ratio, sigma_b_ratio; yld2000 = Barlat Yld2000-2d "
             "from all eight data and exponent. Normalised to the RD tensile curve "
             "(material.hardening)."))
      .geometry = "shell3d";
  add(make(an, "rolling_direction_deg", kFloat,
           float_field<&anisotropy, &AnisotropySpec::rolling_direction_deg>(), "deg",
           closed(-180, 180),
           "Angle of the rolling direction RD from the x axis (counter-clockwise); the material "
           "axes then follow the sheet (convected). A quarter blank needs RD along x or y."))
      .geometry = "shell3d";
  auto aniso = [&](std::string_view name, KeyField field, Range range, std::string_view doc,
                   std::vector<std::string_view> used_by) {
    KeySpec& k = add(make(an, name, kFloat, field, "", range, doc));
    k.geometry = "shell3d";
    k.required = true;
    k.applies_to = std::move(used_by);
  };
  aniso("r0", float_field<&anisotropy, &AnisotropySpec::r0>(), closed(0.05, 20),
        "Lankford ratio in tension along RD.", {"hill48_r", "yld2000"});
  aniso("r45", float_field<&anisotropy, &AnisotropySpec::r45>(), closed(0.05, 20),
        "Lankford ratio in tension at 45 deg to RD.", {"hill48_r", "yld2000"});
  aniso("r90", float_field<&anisotropy, &AnisotropySpec::r90>(), closed(0.05, 20),
        "Lankford ratio in tension along TD.", {"hill48_r", "yld2000"});
  aniso("sigma45_ratio", float_field<&anisotropy, &AnisotropySpec::sigma45_ratio>(), closed(0.5, 2),
        "Yield stress at 45 deg to RD over the RD yield stress.", {"hill48_stress", "yld2000"});
  aniso("sigma90_ratio", float_field<&anisotropy, &AnisotropySpec::sigma90_ratio>(), closed(0.5, 2),
        "Yield stress along TD over the RD yield stress.", {"hill48_stress", "yld2000"});
  aniso("sigma_b_ratio", float_field<&anisotropy, &AnisotropySpec::sigma_b_ratio>(), closed(0.5, 2),
        "Equibiaxial yield stress over the RD yield stress.", {"hill48_stress", "yld2000"});
  aniso("r_b", float_field<&anisotropy, &AnisotropySpec::r_b>(), closed(0.05, 20),
        "Equibiaxial strain-rate ratio d_TD / d_RD (1 when not measured: say so in the scene).",
        {"yld2000"});
  aniso("exponent", float_field<&anisotropy, &AnisotropySpec::exponent>(), closed(2, 20),
        "Yld2000-2d exponent: 8 for aluminium (FCC), 6 for steel (BCC).", {"yld2000"});

  // [material.hardening]
  const std::string_view h = "material.hardening";
  add(choice(h, "law", enum_field<&hardening, &HardeningSpec::law>(),
             {"swift", "hollomon", "voce", "table"},
             "Flow curve: swift K (eps0 + eps)^n; hollomon max(sigma0, K eps^n); voce sigma0 + "
             "Q (1 - exp(-b eps)); table piecewise linear."));
  add(make(h, "K_MPa", kFloat, float_field<&hardening, &HardeningSpec::K_MPa>(), "MPa",
           open_above(0), "Strength coefficient K."))
      .applies_to = {"swift", "hollomon"};
  add(make(h, "eps0", kFloat, float_field<&hardening, &HardeningSpec::eps0>(), "",
           open_closed(0, 1),
           "Swift pre-strain; > 0 so the virgin material has a non-zero yield stress."))
      .applies_to = {"swift"};
  add(make(h, "n", kFloat, float_field<&hardening, &HardeningSpec::n>(), "", closed(0, 1),
           "Strain-hardening exponent (not the Perzyna exponent)."))
      .applies_to = {"swift", "hollomon"};
  add(make(h, "sigma0_MPa", kFloat, float_field<&hardening, &HardeningSpec::sigma0_MPa>(), "MPa",
           open_above(0), "Initial yield stress (Hollomon plateau, Voce start)."))
      .applies_to = {"hollomon", "voce"};
  add(make(h, "Q_MPa", kFloat, float_field<&hardening, &HardeningSpec::Q_MPa>(), "MPa", at_least(0),
           "Voce saturation increment."))
      .applies_to = {"voce"};
  add(make(h, "b", kFloat, float_field<&hardening, &HardeningSpec::b>(), "", open_above(0),
           "Voce saturation rate."))
      .applies_to = {"voce"};
  add(make(h, "table", KeyType::kPairArray, KeyField{}, "[-, MPa]", open_above(0),
           "Inline curve [[plastic_strain, stress_MPa], ...]: strain strictly increasing from "
           "0, stress > 0, at least 2 points. Give table or table_file."))
      .applies_to = {"table"};
  add(make(h, "table_file", KeyType::kString, KeyField{}, "", Range{},
           "CSV curve, relative to the scene file: '#' comments, header "
           "plastic_strain,stress_MPa, same rules as table."))
      .applies_to = {"table"};
  add(make(h, "table_scale", kFloat, float_field<&hardening, &HardeningSpec::table_scale>(), "",
           open_above(0), "Multiplies every table stress (calibration handle)."))
      .applies_to = {"table"};

  // [material.rate]
  const std::string_view r = "material.rate";
  add(choice(r, "law", enum_field<&rate, &RateSpec::law>(), {"none", "perzyna", "power"},
             "Rate law: none; perzyna sigma_y + (rate / gamma)^(1/exponent) (paper eq. 7); "
             "power sigma_y (rate / reference_rate)^m."));
  add(make(r, "gamma_per_s", kFloat, float_field<&rate, &RateSpec::gamma_per_s>(), "1/s",
           open_above(0), "Perzyna fluidity gamma."))
      .applies_to = {"perzyna"};
  add(make(r, "exponent", kFloat, float_field<&rate, &RateSpec::exponent>(), "", open_above(0),
           "Perzyna exponent (paper eq. 7 n; not the hardening n)."))
      .applies_to = {"perzyna"};
  add(make(r, "m", kFloat, float_field<&rate, &RateSpec::m>(), "", closed(0, 1),
           "Power-law strain-rate sensitivity."))
      .applies_to = {"power"};
  add(make(r, "reference_rate_per_s", kFloat, float_field<&rate, &RateSpec::reference_rate_per_s>(),
           "1/s", open_above(0), "Power-law reference strain rate."))
      .applies_to = {"power"};

  // [material.elastic]
  const std::string_view el = "material.elastic";
  add(choice(el, "law", enum_field<&elastic, &ElasticSpec::law>(), {"none", "isotropic"},
             "Elasticity: none = rigid-(visco)plastic; isotropic = Hooke's law with E_MPa and "
             "nu, as a first-order correction (the elastic start of the flow stress and the "
             "elastic part of the reported thickness strain; see 'Elasticity')."));
  add(make(el, "E_MPa", kFloat, float_field<&elastic, &ElasticSpec::E_MPa>(), "MPa",
           closed(1e3, 1e7),
           "Young's modulus (1e3-1e7 MPa holds every sheet material; a far smaller E leaves the "
           "first step without stiffness)."))
      .applies_to = {"isotropic"};
  keys.back().required = true;
  keys.back().bound_reason =
      "no sheet material is that stiff, and the step that crosses yield would overshoot the flow "
      "stress by E times its strain increment";
  add(make(el, "nu", kFloat, float_field<&elastic, &ElasticSpec::nu>(), "", open(-1, 0.5),
           "Poisson's ratio."))
      .applies_to = {"isotropic"};
  keys.back().required = true;
  add(make(el, "start", KeyType::kBool, bool_field<&elastic, &ElasticSpec::start>(), "", Range{},
           "Elastic start: the flow stress at accumulated strain e is the secant "
           "elastic-plastic curve min(E e, sigma_y(e - sigma / E)) (monotonic loading; no "
           "elastic unloading)."))
      .applies_to = {"isotropic"};
  add(make(el, "strains", KeyType::kBool, bool_field<&elastic, &ElasticSpec::strains>(), "",
           Range{},
           "Reported thickness strains (and thicknesses) of the strain profiles include the "
           "elastic part from the current in-plane stress by Hooke's law."))
      .applies_to = {"isotropic"};

  // [[tool]]
  auto& name =
      add(make("tool", "name", KeyType::kString, string_field<&tool, &ToolSpec::name>(), "",
               Range{}, "Unique label used in outputs and addresses (tool.NAME.key)."));
  name.required = true;
  name.identifier = true;
  add(choice("tool", "kind", enum_field<&tool, &ToolSpec::kind>(),
             {"hemispherical_punch", "flat_punch", "die", "blank_holder"},
             "Tool type; exactly one punch, at most one die and one blank holder."))
      .required = true;
  auto& radius = add(make("tool", "radius_mm", kFloat, float_field<&tool, &ToolSpec::radius_mm>(),
                          "mm", open_above(0),
                          "Punch radius (sphere radius / flat punch outer radius) or die "
                          "opening radius."));
  radius.required = true;
  radius.applies_to = {"hemispherical_punch", "flat_punch", "die"};
  add(make("tool", "profile_radius_mm", kFloat, float_field<&tool, &ToolSpec::profile_radius_mm>(),
           "mm", open_above(0), "Flat-punch nose radius (< radius_mm) or die shoulder radius."))
      .applies_to = {"flat_punch", "die"};
  add(make("tool", "friction", kFloat, float_field<&tool, &ToolSpec::friction>(), "",
           closed(0, kInf),
           "Coulomb coefficient with the sheet, at most 10; inf or \"sticking\" = no slip."))
      .sticking_alias = true;
  add(make("tool", "force_N", kFloat, float_field<&tool, &ToolSpec::force_N>(), "N", open_above(0),
           "Blank holder with a prescribed total (360 degree) force, shared over the flange nodes "
           "on the die face. Give either force_N or gap_mm."))
      .applies_to = {"blank_holder"};
  add(make("tool", "gap_mm", kFloat, float_field<&tool, &ToolSpec::gap_mm>(), "mm", open_above(0),
           "Blank holder at a fixed gap from the die face (>= blank thickness): the flange may "
           "thicken up to the gap; beyond it the holder presses back with whatever pressure keeps "
           "the thickness at the gap (its friction acts on that pressure). Give either force_N or "
           "gap_mm."))
      .applies_to = {"blank_holder"};

  // [process]
  add(make("process", "punch_travel_mm", kFloat,
           float_field<&process, &ProcessSpec::punch_travel_mm>(), "mm", open_above(0),
           "Total punch travel."));
  add(make("process", "punch_speed_mm_per_s", kFloat,
           float_field<&process, &ProcessSpec::punch_speed_mm_per_s>(), "mm/s", open_above(0),
           "Punch speed; matters only for rate-sensitive materials."));
  add(make("process", "output_travels_mm", KeyType::kFloatArray,
           array_field<&process, &ProcessSpec::output_travels_mm>(), "mm", open_above(0),
           "Travels at which strain distributions are written: strictly increasing, each "
           "<= punch_travel_mm; at most 500 (each writes files and stops the step grid)."))
      .max_items = 500;
  keys.back().bound_reason = "each output travel writes files and ends a step";

  // [numerics]
  const std::string_view nu = "numerics";
  add(make(nu, "thickness_points", kInt, int_field<&numerics, &NumericsSpec::thickness_points>(),
           "", closed(3, 9), "Simpson integration points through the thickness."))
      .choices = {"3", "5", "7", "9"};
  add(choice(nu, "solver", enum_field<&numerics, &NumericsSpec::solver>(), {"newton", "picard"},
             "newton: direct iterations then Newton with line search; picard: the paper's "
             "direct iteration only."));
  add(choice(nu, "time_integration", enum_field<&numerics, &NumericsSpec::time_integration>(),
             {"heun", "euler", "implicit"},
             "heun: explicit predictor-corrector (two solves per step, second order, stable only "
             "below about 0.025 element lengths per step); euler: the paper's update with the "
             "start-of-step velocity (first order); implicit: the velocity solved in the "
             "end-of-step configuration (two solves per step by default, one on 3D meshes from "
             "30 000 unknowns: implicit_solves; with "
             "the configuration's dependence on the velocity), stable at steps set by accuracy: "
             "with "
             "max_travel_increment_per_length = 0.25 it runs ex1 about 8x faster than heun at "
             "its default step, within 0.2 % in force (experiments/06_step_stability); in 3D "
             "(ex4a, 8 divisions, friction 0.2, to 30 mm, with the 3D defaults contact_events = "
             "false and start_refinement = 3) 3.7 s instead of heun's 46 s, within 1.4 % in force "
             "and 0.005 in thickness strain of the axisymmetric twin (experiments/06)."));
  add(make(nu, "implicit_theta", kFloat, float_field<&numerics, &NumericsSpec::implicit_theta>(),
           "", closed(0.5, 1),
           "Implicit update x_{n+1} = x_n + dt ((1 - theta) v_n + theta v_{n+1}): 0.5 trapezoidal "
           "(second order), 1 backward Euler (first order; damps the stiffest modes fully)."));
  add(make(
          nu, "implicit_solves", kInt, int_field<&numerics, &NumericsSpec::implicit_solves>(), "",
          closed(1, 3),
          "Implicit update: velocity solves per step, each in the configuration moved with the "
          "previous solve's velocity. 2: the update of implicit_theta (second order). 1: one "
          "solve in the configuration moved with the start velocity (first order, its error "
          "proportional to the step; a stiff mode is damped only weakly at large steps), about "
          "1.5x faster in 3D. 3: one more solve (the axisymmetric ex1: force within 0.005 % of 2). "
          "Default: 2, except shell3d scenes with the implicit update, where it follows the "
          "model's size: 2 below 30 000 unknowns, 1 from there (the run prints which). Measured "
          "on ex4a (quarter disc, friction 0.2, to 30 mm) against a mesh-converged axisymmetric "
          "twin (transverse_shear_scale 0.1 on both sides), largest thickness-strain difference at "
          "30 mm, one solve against two: 8 divisions (4 085 unknowns) 0.0068 / 0.0034, 16 "
          "(15 845) 0.0052 / 0.0021, 32 (62 405) 0.0030 / 0.0015; at the default penalty 32 "
          "divisions take 136-139 s instead of 215-217 s. On a draw one solve is less accurate "
          "(ex2 in 3D, 4 divisions: force 0.3-0.6 % instead of 0.02-0.07 % off, 1.8 % where the "
          "force drops at 40 mm; experiments/05_shell3d)."))
      .default_text = [] {
    return std::string("(2; shell3d with implicit: 1 from 30 000 unknowns, else 2)");
  };
  add(choice(nu, "contact_entry", enum_field<&numerics, &NumericsSpec::contact_entry>(),
             {"first_solve", "last_solve"},
             "Implicit update with two or more solves: where a node that reaches a tool during a "
             "step starts to touch it. first_solve: in the first solve's configuration (moved "
             "with the start velocity), so the step's geometry counts it in contact for "
             "implicit_theta of the step. last_solve: it stays free until the last solve's "
             "configuration, is put onto the tool there and touches from the last solve on, so "
             "the geometry counts it free for the whole step: right where nodes touch late in "
             "their steps (nodes wrapping onto a punch). Sticking tools always take first_solve. "
             "Measured (experiments/05_shell3d, \"New contacts in the last solve\"): ex4a "
             "quarter disc, 16 divisions, friction 0.2, to 30 mm, against the same mesh at 1/4 "
             "of the step with contact events: thickness strain within 0.0036 instead of 0.0108 "
             "at the same cost; with max_travel_increment_per_length = 0.5, 19-21 s instead of "
             "30-31 s at the defaults, within 1.5 % in force and 0.006 in thickness strain of the "
             "axisymmetric twin. Not the default: where nodes touch early in their steps (ex4a, 4 "
             "divisions, 0.5 mm steps, 4 mm) the mean force is 2.44 % above the twin instead of "
             "1.87 %, and with contact events it takes 5-7 % more steps."));
  add(make(nu, "contact_events", KeyType::kBool,
           bool_field<&numerics, &NumericsSpec::contact_events>(), "", Range{},
           "Implicit update: end steps at contact events (heun always does). false: a node that "
           "reaches a tool within a step touches it within the step (contact_entry). That saves "
           "most steps of a 3D mesh (every node touches at its own instant; ex4a n = 8, friction "
           "0.2, 10 mm: 18 steps instead of 70, force within 0.25 %) but samples the moving "
           "contact front at the steps: on ex1 (69 elements, 0.25 element lengths per step) the "
           "thickness "
           "strain along the dome ripples by +-0.01. In 3D the events also made the outputs jump "
           "(ex4a, 8 divisions, force at 10 mm: 2 N under a 1e-5 change of friction; without "
           "them 4.5 mN per 1e-5, smooth). Default: false for shell3d scenes with the implicit "
           "update, else true."))
      .default_text = [] { return std::string("(false for shell3d with implicit, else true)"); };
  add(make(nu, "tolerance", kFloat, float_field<&numerics, &NumericsSpec::tolerance>(), "",
           closed(1e-12, 0.1), "Relative velocity change and relative residual."));
  add(make(nu, "max_iterations", kInt, int_field<&numerics, &NumericsSpec::max_iterations>(), "",
           closed(1, 1000),
           "Iterations per step before the step is cut back (a converging step takes 2-10; "
           "more than 1000 only delays the cut-back)."))
      .bound_reason = "a step that has not converged in 1000 iterations will not; it is cut back";
  add(make(nu, "step_fraction", kFloat, float_field<&numerics, &NumericsSpec::step_fraction>(), "",
           closed(0.05, 1),
           "Fraction of the step to the next contact event taken. A fraction f approaches each "
           "event in about ln(1/f)/f steps (60 at 0.05, 92 000 at 1e-4: ex1 to 10 mm takes 352 "
           "steps at 1, 1182 at 0.05, 5349 at 0.01), hence the lower bound."))
      .bound_reason = "a fraction f takes about ln(1/f)/f steps per contact event (92 000 at 1e-4)";
  keys.back().bound_reason_below = true;
  add(make(nu, "max_travel_increment_mm", kFloat,
           float_field<&numerics, &NumericsSpec::max_travel_increment_mm>(), "mm", open_above(0),
           "Cap on punch travel per step (steps end on a fixed grid of this spacing, or of the "
           "next key's, whichever is smaller; the run-size rule bounds the number of steps)."));
  add(make(nu, "max_travel_increment_per_length", kFloat,
           float_field<&numerics, &NumericsSpec::max_travel_increment_per_length>(), "",
           open_above(0),
           "Cap on punch travel per step relative to the shortest initial element length "
           "(axisymmetric: element length; shell3d: sqrt(area) of the 9-node element). At "
           "0.025, heun outputs are smooth in the parameters to the solver tolerance; from "
           "about 0.05 the explicit update makes load curves and strains jitter (1e-3 at 0.05 "
           "with 24 elements, up to 1 % at 0.1). The implicit update stays smooth (2e-8 at 0.4; "
           "experiments/06_step_stability, experiments/05_shell3d). Default: 0.25 with the "
           "implicit update (a cap for accuracy), 0.025 with heun or euler (their stability)."))
      .default_text = [] { return std::string("(0.25 with implicit, 0.025 with heun or euler)"); };
  add(make(nu, "start_refinement", kInt, int_field<&numerics, &NumericsSpec::start_refinement>(),
           "", closed(0, 6),
           "Levels of refinement of the start of the step grid: the first L grid increments are "
           "split into 2^L, 2^(L-1), ..., 2 steps (3: 8, 4 and 2), for the bending-dominated "
           "start and the first contact events. On ex4a's 0.5 mm grid (4 divisions, friction "
           "0.2) the implicit update is 7.5 % off its axisymmetric twin at 1-2 mm without it, "
           "1.6 % with 3 (experiments/06_step_stability). Default: 3 for shell3d scenes with "
           "the implicit update, else 0."))
      .default_text = [] { return std::string("(3 for shell3d with implicit, else 0)"); };
  add(make(nu, "max_strain_increment", kFloat,
           float_field<&numerics, &NumericsSpec::max_strain_increment>(), "", closed(1e-3, 0.5),
           "Cap on the effective strain increment per step (at least 1e-3: a forming run "
           "reaches strains of order 1, so smaller caps mean millions of steps)."))
      .bound_reason = "strains of order 1 in steps below 1e-3 take millions of steps";
  keys.back().bound_reason_below = true;
  add(make(nu, "strain_rate_cutoff", kFloat,
           float_field<&numerics, &NumericsSpec::strain_rate_cutoff>(), "", closed(1e-12, 0.5),
           "Cut-off strain rate relative to punch_speed / blank radius: below it the flow law "
           "turns viscous (rigid regions creep at about this rate). With heun, 1e-2 and "
           "max_travel_increment_per_length = 0.05 halve the run time, answers within ~1 % "
           "(experiments/01_performance). In 3D the cut-off is the main lever: with heun, 1e-2 "
           "and max_travel_increment_per_length = 0.035 run ex4a (n = 4, "
           "friction 0.2) in about half the time, within 0.2 % in force and 0.007 in thickness "
           "strain of the axisymmetric solver from ~6 mm on (the first mm are 2-8 % low; 3e-3 "
           "keeps the whole curve within 2 %; experiments/05_shell3d)."));
  add(make(nu, "friction_regularisation", kFloat,
           float_field<&numerics, &NumericsSpec::friction_regularisation>(), "", closed(1e-8, 0.1),
           "Coulomb arctan slip velocity relative to the punch speed."));
  add(make(nu, "transverse_shear_scale", kFloat,
           float_field<&numerics, &NumericsSpec::transverse_shear_scale>(), "", closed(1e-2, 1e2),
           "Factor on the transverse-shear penalty (Mindlin shear carried with the viscosity of "
           "the section's mid point at the nominal rate punch_speed / blank radius, outside the "
           "flow rule). A numerical choice with no material value: on the continuum references "
           "0.1 / 10 move the ex1 pole thickness strain at 25 mm by about -0.005 / +0.005 to "
           "+0.04, and no factor is closer on every reference "
           "(experiments/08_continuum_reference, section 14); a model-form alternative for a "
           "calibration."));
  add(make(nu, "max_cutbacks", kInt, int_field<&numerics, &NumericsSpec::max_cutbacks>(), "",
           closed(0, 30), "Step halvings before the run stops."));
  add(choice(nu, "element_rule", enum_field<&numerics, &NumericsSpec::element_rule>(),
             {"mitc9", "paper_selective"},
             "9-node shell strains (shell3d only): mitc9 assumed strains (no membrane locking) or "
             "the paper's selective rule (in-plane 3x3, transverse shear 2x2)."))
      .geometry = "shell3d";
  add(choice(nu, "normal_stress", enum_field<&numerics, &NumericsSpec::normal_stress>(),
             {"none", "contact"},
             "Through-thickness normal stress: none = plane stress (the paper's shell); contact = "
             "sigma_33 linear from minus the contact pressure on a touched face (nodal normal "
             "reaction / nodal area, lagged: the converged value at the start of each solve) to "
             "the other face, which lowers the in-plane stresses by the local pressure "
             "(experiments/08_continuum_reference, section 8)."));
  add(choice(nu, "friction_surface", enum_field<&numerics, &NumericsSpec::friction_surface>(),
             {"mid", "face"},
             "Where sticking and Coulomb friction act: mid = on the mid-surface velocity (the "
             "paper's shell); face = on the velocity of the face that touches the tool, v +/- "
             "(h/2) dV3/dt, so a sticking tool holds that face and friction has its moment about "
             "the mid-surface (docs/contact_face.md). Flange nodes pressed from both faces (blank "
             "holder, ironing) keep the mid-surface."));

  // [forming_limit]
  const std::string_view fl = "forming_limit";
  add(choice(fl, "model", enum_field<&forming_limit, &FormingLimitSpec::model>(),
             {"keeler-brazier", "table", "none"},
             "Forming-limit curve drawn on the FLD and measured against by the margin of every "
             "element (outputs only). keeler-brazier: FLC0 = (23.3 + 14.13 t) n / 0.21 % "
             "engineering major strain (t = blank thickness in mm, fitted for t <= 3 mm; n = "
             "material.hardening.n for swift/hollomon, the slope of ln sigma over ln eps between "
             "0.1 and 0.2 strain for voce/table), left branch at constant thickness strain, right "
             "branch rising 0.6 x the engineering minor strain (see 'Forming-limit curve'); "
             "table: the points below; none: no curve."));
  add(make(fl, "points", KeyType::kPairArray, KeyField{}, "[-, -]", Range{},
           "The curve as [[minor_true_strain, major_true_strain], ...]: 2 to 100 points, minor "
           "strictly increasing in [-1, 1], major in (0, 2]; linear between points, constant "
           "beyond the ends."))
      .applies_to = {"table"};
  keys.back().required = true;
  add(make(fl, "safety_margin", kFloat,
           float_field<&forming_limit, &FormingLimitSpec::safety_margin>(), "", closed(0, 1),
           "Band below the FLC, in major true strain, whose elements are 'marginal' (at or above "
           "the FLC: 'failed'; below the band: 'safe'). 0.1 is about the 10 % engineering major "
           "strain rule of thumb for steel (8 % for aluminium)."));

  // [output]
  add(make("output", "directory", KeyType::kString, string_field<&output, &OutputSpec::directory>(),
           "", Range{}, "Run directory, relative to the current working directory."));
  add(make("output", "plots", KeyType::kBool, bool_field<&output, &OutputSpec::plots>(), "",
           Range{}, "Write SVG plots."));
  add(make("output", "history", KeyType::kBool, bool_field<&output, &OutputSpec::history>(), "",
           Range{}, "Keep per-step element strains (FLD paths, deformed stages)."));
  add(make("output", "measured_cup_profile", KeyType::kString,
           string_field<&output, &OutputSpec::measured_cup_profile>(), "", Range{},
           "Measured cup-height profile drawn beside the computed one (cup_profile.svg, "
           "run.json), relative to the scene file: lines 'angle_from_rd_deg, cup_height_mm' "
           "(comma and/or blanks), '#' comments, angles in [0, 360] not repeating, at least 3 "
           "points. Empty: none."))
      .geometry = "shell3d";
  return keys;
}

// A TOML basic string. Control characters (and DEL) are escaped; a string that is not valid
// UTF-8 (a path of a folder named in another encoding) cannot be written in TOML at all: its
// bytes above 0x7F are replaced by U+FFFD (the loader refuses such a value given with --set).
std::string toml_string(std::string_view text) {
  std::string fixed;
  if (!valid_utf8(text)) {
    for (char c : text)
      fixed += static_cast<unsigned char>(c) < 0x80 ? std::string(1, c) : "\uFFFD";
    text = fixed;
  }
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          out += fmt::format("\\u{:04x}", static_cast<int>(c));
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{}", x);
}

}  // namespace

bool Range::contains(double x) const {
  if (std::isnan(x)) return false;
  const bool above = lo_closed ? x >= lo : x > lo;
  const bool below = hi_closed ? x <= hi : x < hi;
  return above && below;
}

std::string Range::text() const {
  return fmt::format("{}{}, {}{}", lo_closed ? '[' : '(', number_text(lo), number_text(hi),
                     hi_closed ? ']' : ')');
}

Range open_above(double lo) { return Range{lo, kInf, false, false}; }
Range at_least(double lo) { return Range{lo, kInf, true, false}; }
Range closed(double lo, double hi) { return Range{lo, hi, true, true}; }
Range open_closed(double lo, double hi) { return Range{lo, hi, false, true}; }
Range open(double lo, double hi) { return Range{lo, hi, false, false}; }

std::string KeySpec::address_in_section() const {
  if (section.empty()) return std::string(name);
  return fmt::format("{}.{}", section, name);
}

const std::vector<KeySpec>& scene_keys() {
  static const std::vector<KeySpec> keys = build_keys();
  return keys;
}

const std::vector<SectionSpec>& scene_sections() {
  static const std::vector<SectionSpec> sections = {
      {"", "(top level)", "Title and model geometry."},
      {"blank", "[blank]", "The blank (circular, or square in 3D) and its mesh."},
      {"material", "[material]", "Sheet material: anisotropy here, flow curve and rate law below."},
      {"material.hardening", "[material.hardening]",
       "Strain hardening; the keys allowed depend on `law`."},
      {"material.rate", "[material.rate]", "Strain-rate sensitivity; the keys depend on `law`."},
      {"material.anisotropy", "[material.anisotropy]",
       "Planar anisotropy (shell3d only); the keys required depend on `model`."},
      {"material.elastic", "[material.elastic]",
       "Isotropic elasticity as a first-order correction (both geometries); the keys depend on "
       "`law`."},
      {"tool", "[[tool]]", "Rigid tools, one table each; the keys allowed depend on `kind`."},
      {"process", "[process]", "Punch motion and output stages."},
      {"numerics", "[numerics]", "Integration, nonlinear solver and step control."},
      {"forming_limit", "[forming_limit]",
       "Forming-limit curve for the FLD and the margin of every element (outputs only); the "
       "keys allowed depend on `model`."},
      {"output", "[output]", "What is written where."},
  };
  return sections;
}

const KeySpec* find_key(std::string_view section, std::string_view name) {
  for (const KeySpec& k : scene_keys()) {
    if (k.section == section && k.name == name) return &k;
  }
  return nullptr;
}

const VariantSelector* find_selector(std::string_view section) {
  static const std::vector<VariantSelector> selectors = {
      {"material.hardening", "law", "hardening law"},
      {"material.rate", "law", "rate law"},
      {"material.anisotropy", "model", "anisotropy model"},
      {"tool", "kind", "tool kind"},
      {"material.elastic", "law", "elasticity law"},
      {"forming_limit", "model", "forming limit model"},
  };
  for (const VariantSelector& s : selectors) {
    if (s.section == section) return &s;
  }
  return nullptr;
}

bool key_applies(const KeySpec& key, std::string_view variant) {
  if (key.applies_to.empty()) return true;
  for (std::string_view v : key.applies_to) {
    if (v == variant) return true;
  }
  return false;
}

std::string float_toml_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

bool read_key_value(const KeySpec& key, Scene& scene, ToolSpec& tool, KeyValue* value) {
  const KeyField& f = key.field;
  switch (key.type) {
    case KeyType::kFloat:
      if (f.number) *value = f.number(scene, tool);
      return f.number != nullptr;
    case KeyType::kInt:
      if (f.integer) *value = f.integer(scene, tool);
      return f.integer != nullptr;
    case KeyType::kBool:
      if (f.flag) *value = f.flag(scene, tool);
      return f.flag != nullptr;
    case KeyType::kString:
      if (f.text) *value = f.text(scene, tool);
      return f.text != nullptr;
    case KeyType::kEnum:
      if (f.get_choice) {
        *value = std::string(key.choices.at(static_cast<std::size_t>(f.get_choice(scene, tool))));
      }
      return f.get_choice != nullptr;
    case KeyType::kFloatArray:
      if (f.numbers) *value = f.numbers(scene, tool);
      return f.numbers != nullptr;
    case KeyType::kPairArray:
    case KeyType::kStringArray:
    case KeyType::kTable:
      return false;
  }
  return false;
}

std::string key_value_toml(const KeyValue& value) {
  struct Text {
    std::string operator()(double x) const { return float_toml_text(x); }
    std::string operator()(int x) const { return std::to_string(x); }
    std::string operator()(bool x) const { return x ? "true" : "false"; }
    std::string operator()(const std::string& x) const { return toml_string(x); }
    std::string operator()(const std::vector<double>& x) const {
      std::string s = "[";
      for (std::size_t i = 0; i < x.size(); ++i) s += (i ? ", " : "") + float_toml_text(x[i]);
      return s + "]";
    }
    std::string operator()(const KeyPairs& x) const {
      std::string s = "[";
      for (std::size_t i = 0; i < x.size(); ++i) {
        s += fmt::format("{}[{}, {}]", i ? ", " : "", float_toml_text(x[i][0]),
                         float_toml_text(x[i][1]));
      }
      return s + "]";
    }
  };
  return std::visit(Text{}, value);
}

std::string default_toml_text(const KeySpec& key) {
  if (key.required) return "";
  if (key.default_text != nullptr) return key.default_text();
  Scene scene;
  ToolSpec tool;
  KeyValue value;
  return read_key_value(key, scene, tool, &value) ? key_value_toml(value) : "";
}

double default_number(const KeySpec& key) {
  Scene scene;
  ToolSpec tool_spec;
  if (key.field.number) return key.field.number(scene, tool_spec);
  if (key.field.integer) return key.field.integer(scene, tool_spec);
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace vs
