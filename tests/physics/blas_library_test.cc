// linalg/blas_library.h: the BLAS that serves CHOLMOD is the system's libblas.so.3 (what Debian's
// alternatives chose), not another BLAS that a dependency loads first (Ceres brings ATLAS's
// libf77blas): the executables name libblas.so.3 first (CMakeLists.txt, VS_BLAS_LIBRARY).
#include "linalg/blas_library.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace vs {
namespace {

// The resolved file of the library loaded as libblas.so.3 (its dgemm_), or "" if it is not loaded.
std::string loaded_libblas() {
  void* handle = dlopen("libblas.so.3", RTLD_LAZY | RTLD_NOLOAD);
  if (handle == nullptr) return "";
  const std::string file = library_of(dlsym(handle, "dgemm_"));
  dlclose(handle);
  return file == "unknown" ? "" : file;
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
