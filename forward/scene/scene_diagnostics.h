// Error locations for scene messages: "FILE:LINE:COL: message" from toml++ source regions, and a
// map from scene addresses to where they were written, so checks that run on the finished Scene
// can still point at the right line.
#pragma once

#include <toml++/toml.h>

#include <map>
#include <string>

namespace vs {

// "FILE:LINE:COL" for a region read from a file, "FILE" for a node built in memory (line 0).
std::string source_location(const std::string& source, const toml::source_region& region);

// Throws InputError("LOCATION: message").
[[noreturn]] void fail_at(const std::string& source, const toml::source_region& region,
                          const std::string& message);

// TOML type name of a node for "expected X, got Y" messages.
std::string toml_type_name(const toml::node& node);

class SceneSourceMap {
 public:
  explicit SceneSourceMap(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  // Records where `address` ("blank.radius_mm", "tool.punch", "process.output_travels_mm[1]")
  // was written.
  void add(const std::string& address, const toml::source_region& region);

  // Throws InputError at `address`, or at the closest enclosing address that was written
  // (a key left at its default is reported at its section), or at the file.
  [[noreturn]] void fail(const std::string& address, const std::string& message) const;

 private:
  std::string source_;
  std::map<std::string, toml::source_region> regions_;
};

}  // namespace vs
