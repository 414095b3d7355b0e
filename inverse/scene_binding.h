// How a parameter vector is written into a copy of a base scene. The base scene is parsed once
// into a TOML table; every evaluation copies the table, sets the parameters by their dotted
// addresses and rebuilds a validated Scene in memory (no disk I/O, so it is cheap and safe to
// do from the finite-difference worker threads).
#pragma once

#include <toml++/toml.h>

#include <string>
#include <utility>
#include <vector>

#include "parameter_spec.h"
#include "scene/scene.h"

namespace vs {

// Settings applied to every scene copy during a calibration.
struct ForwardSettings {
  // Overrides numerics.tolerance. Finite-difference derivatives are only as good as the forward
  // convergence (error ~ tolerance / step, numerics.md §5.3), so calibration runs converge much
  // more tightly than the paper's 1e-3. <= 0 keeps the scene's value.
  double tolerance = 1e-9;
  // Extra scene edits (address, value as text), e.g. {"blank.elements", "24"} for a coarse mesh.
  std::vector<std::pair<std::string, std::string>> overrides;
};

class SceneBinding {
 public:
  // `table` is the parsed base scene (read_scene_table), `source` its file (for messages),
  // `base_dir` the folder that relative references in it are resolved against.
  // `data_travels_mm` are the travels at which measured profiles were taken: they are merged
  // into process.output_travels_mm so that the solver stops exactly there.
  // Throws InputError if the edited base scene is invalid.
  SceneBinding(toml::table table, std::string source, std::string base_dir,
               const ForwardSettings& settings, const std::vector<double>& data_travels_mm);

  // Records which of `parameters` this scene has. Returns, for each parameter, an empty string
  // if it applies here or the reason (from scene_table) if its address does not resolve.
  std::vector<std::string> attach(const std::vector<ParameterSpec>& parameters);

  // The scene with `values` (one per attached parameter list entry, all parameters, fixed ones
  // included) written in. Throws InputError if a value is outside the scene's range.
  Scene bind(const std::vector<double>& values) const;

  // The scene as configured, before any parameter is written (for validation and reports).
  Scene base_scene() const;

  // The number at `address` in the configured base scene (its default when the file omits it).
  double value_of(const std::string& address) const;

  // Whether `address` names an integer key (blank.elements, ...).
  bool is_integer(const std::string& address) const;

  const std::string& source() const { return source_; }
  bool applies(int parameter) const { return applies_.at(parameter); }

 private:
  toml::table table_;
  std::string source_;
  std::string base_dir_;
  std::vector<std::string> addresses_;
  std::vector<bool> applies_;
};

}  // namespace vs
