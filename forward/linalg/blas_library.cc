#include "linalg/blas_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <memory>
#include <mutex>

namespace vs {

std::string blas_library() { return library_of(dlsym(RTLD_DEFAULT, "dgemm_")); }

std::string library_of(const void* symbol) {
  Dl_info info{};
  if (symbol == nullptr || dladdr(symbol, &info) == 0 || info.dli_fname == nullptr)
    return "unknown";
  const std::unique_ptr<char, decltype(&std::free)> resolved(realpath(info.dli_fname, nullptr),
                                                             &std::free);
  return resolved ? std::string(resolved.get()) : std::string(info.dli_fname);
}

void keep_blas_on_calling_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    using SetThreads = void (*)(int);
    if (void* f = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) {
      reinterpret_cast<SetThreads>(f)(1);
    }
  });
}

}  // namespace vs
