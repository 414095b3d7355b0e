// linalg/blas_library.h: the BLAS that serves CHOLMOD is the system's libblas.so.3 (what Debian's
// alternatives chose), not another BLAS that a dependency loads first (Ceres brings ATLAS's
// libf77blas): the executables name libblas.so.3 first (CMakeLists.txt, VS_BLAS_LIBRARY).
#include "linalg/blas_library.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

namespace vs {
namespace {

// The resolved file of the library loaded as libblas.so.3, or "" if it is not loaded.
std::string loaded_libblas() {
  void* handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return "";
  void* symbol = dlsym(handle, "dgemm_");
  Dl_info info{};
  std::string file;
  if (symbol != nullptr && dladdr(symbol, &info) != 0 && info.dli_fname != nullptr) {
    const std::unique_ptr<char, decltype(&std::free)> resolved(realpath(info.dli_fname, nullptr),
                                                               &std::free);
    if (resolved) file = resolved.get();
  }
  dlclose(handle);
  return file;
}

TEST(BlasLibrary, IsTheSystemLibblasLoadedFirst) {
  const std::string used = blas_library();
  ASSERT_NE(used, "unknown");
  EXPECT_TRUE(std::filesystem::exists(used)) << used;
  const std::string system = loaded_libblas();
  ASSERT_FALSE(system.empty()) << "libblas.so.3 is not among the loaded libraries";
  EXPECT_EQ(used, system) << "dgemm_ comes from " << used << ", not from libblas.so.3 (" << system
                          << ")";
}

TEST(BlasLibrary, KeepingCallsOnTheCallingThreadIsIdempotent) {
  keep_blas_on_calling_thread();
  keep_blas_on_calling_thread();
  using GetThreads = int (*)();
  if (void* f = dlsym(RTLD_DEFAULT, "openblas_get_num_threads")) {
    EXPECT_EQ(reinterpret_cast<GetThreads>(f)(), 1);
  }
}

}  // namespace
}  // namespace vs
