# Which vector instructions the project is compiled for: VS_ARCH
#   auto (default)  x86-64-v3 (AVX2, FMA, BMI2) when the compiler accepts it and the build
#                   machine runs it, else the compiler's baseline (x86-64: SSE2)
#   none            the compiler's baseline
#   any other value passed as -march=VALUE (e.g. native, x86-64-v3)
# Measured (experiments/05, "Vector instructions", issue 14): x86-64-v3 makes the 3D element work
# 1.5-1.7x faster (Eigen's matrix kernels use 4-wide AVX2 and FMA instead of 2-wide SSE2);
# x86-64-v4 (AVX-512) is not faster on the 2-core workplace machine.
#
# Eigen with AVX assumes 32-byte aligned heap blocks and then allocates them by hand; Eigen 3.4.0
# mixes that allocator with plain realloc/free in its sparse Cholesky (SimplicialLDLT with AMD:
# an invalid free in its destructor, found by valgrind). Keeping Eigen at 16-byte alignment
# (EIGEN_MAX_ALIGN_BYTES=16, malloc already aligned) is Eigen's documented way to build AVX code
# with the SSE ABI: the kernels then load 32-byte packets unaligned. GCC 12 warns that those
# unaligned packet loads of a Vector2d/Vector3d may read past it (-Warray-bounds); they do not (the
# partial packets are masked), so that one warning is switched off with the flag.
# One place where that is not so: Eigen's blocked products, triangular solves and LLT still pack
# their operands into buffers they fill with aligned 32-byte stores. On the stack (up to
# EIGEN_STACK_ALLOCATION_LIMIT, 128 KB) those are 32-byte aligned; from the heap (larger buffers,
# or Eigen's own OpenMP split of a product) only as malloc, 16 bytes, and the store faults. Dense
# work on large blocks must therefore stay in chunks (linalg/supernodal_cholesky.cc: 96 x 96)
# and run with Eigen's product split off. Eigen's vectorised loops also round differently
# (FMA in packets, not one by one) depending on an array's address modulo 32: arrays whose
# arithmetic must not depend on where the heap puts them live in linalg/aligned_buffer.h.
set(VS_ARCH "auto" CACHE STRING "Target instruction set: auto, none or a -march value")

include(CheckCXXCompilerFlag)
include(CheckCXXSourceRuns)

set(vs_march "")
if(VS_ARCH STREQUAL "auto")
  check_cxx_compiler_flag(-march=x86-64-v3 VS_COMPILER_HAS_X86_64_V3)
  if(VS_COMPILER_HAS_X86_64_V3)
    set(CMAKE_REQUIRED_FLAGS -march=x86-64-v3)
    check_cxx_source_runs(
      "int main() { return __builtin_cpu_supports(\"avx2\") && __builtin_cpu_supports(\"fma\") && __builtin_cpu_supports(\"bmi2\") ? 0 : 1; }"
      VS_MACHINE_RUNS_X86_64_V3)
    unset(CMAKE_REQUIRED_FLAGS)
    if(VS_MACHINE_RUNS_X86_64_V3)
      set(vs_march x86-64-v3)
    endif()
  endif()
elseif(NOT VS_ARCH STREQUAL "none")
  set(vs_march ${VS_ARCH})
endif()

if(vs_march)
  add_compile_options(-march=${vs_march} -Wno-array-bounds)
  add_compile_definitions(EIGEN_MAX_ALIGN_BYTES=16 EIGEN_MALLOC_ALREADY_ALIGNED=1)
  message(STATUS "Vector instructions: -march=${vs_march} (VS_ARCH=${VS_ARCH})")
else()
  message(STATUS "Vector instructions: compiler baseline (VS_ARCH=${VS_ARCH})")
endif()
set(VS_MARCH "${vs_march}" CACHE INTERNAL "The -march value the project is built with")
