// What built this program, for run manifests and `vshell --version`.
#pragma once

#include <string>

namespace vs {

std::string program_version();       // project version, e.g. "0.1.0"
std::string program_git_describe();  // `git describe --always --dirty` at configure time
std::string compiler_version();      // e.g. "GCC 12.2.0" (from __VERSION__)
std::string instruction_set();       // "-march=x86-64-v3" or "baseline" (cmake/vs_arch.cmake)
std::string eigen_version();         // e.g. "3.4.0"

}  // namespace vs
