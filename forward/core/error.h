// Errors that cross the library boundary. Programmer errors are asserts; everything a user can
// cause (bad scene, bad CSV, a run that cannot go on) is one of these, carrying a one-line
// message that names the file, key or line at fault.
#pragma once

#include <stdexcept>
#include <string>

namespace vs {

// Bad input: unknown key, wrong type, out-of-range value, missing or malformed file.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

// A simulation that cannot continue (no convergence after all cut-backs, negative thickness...).
class SolverError : public std::runtime_error {
 public:
  explicit SolverError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace vs
