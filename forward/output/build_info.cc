#include "output/build_info.h"

#include <fmt/format.h>

#include <Eigen/Core>

// Set by forward/CMakeLists.txt for vs_output; the fallbacks keep other builds compiling.
#ifndef VS_VERSION
#define VS_VERSION "unknown"
#endif
#ifndef VS_GIT_DESCRIBE
#define VS_GIT_DESCRIBE "unknown"
#endif
#ifndef VS_MARCH
#define VS_MARCH ""
#endif

namespace vs {

std::string program_version() { return VS_VERSION; }

std::string program_git_describe() { return VS_GIT_DESCRIBE; }

std::string compiler_version() {
  // GCC's __VERSION__ is a bare number ("12.2.0"); clang's already starts with its name.
#if defined(__GNUC__) && !defined(__clang__)
  return std::string("GCC ") + __VERSION__;
#elif defined(__VERSION__)
  return __VERSION__;
#else
  return "unknown";
#endif
}

std::string instruction_set() {
  const std::string march = VS_MARCH;
  return march.empty() ? "baseline" : "-march=" + march;
}

std::string eigen_version() {
  return fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
}

}  // namespace vs
