// The BLAS behind CHOLMOD's supernodal factorisation (dgemm, dsyrk, dpotrf), as loaded at run
// time: which library it is, and keeping its calls on the calling thread.
#pragma once

#include <string>

namespace vs {

// The file of the loaded library that provides dgemm_, symbolic links resolved (for example
// /usr/lib/x86_64-linux-gnu/openblas-serial/libblas.so.3: Debian's alternatives choose it), or
// "unknown". Two runs agree to the last bit only with the same BLAS; run.json records it.
std::string blas_library();

// The file of the loaded library that holds `symbol`, symbolic links resolved, or "unknown".
std::string library_of(const void* symbol);

// Makes a multithreaded OpenBLAS (Debian's libopenblas0-pthread or -openmp) run every call on the
// calling thread; no effect on any other BLAS, and idempotent. The solver's own OpenMP teams
// already use the cores, and:
//   - the OpenMP build plans its teams for a fixed thread count, which DynamicTeams (around every
//     CHOLMOD call) does not grant: measured, a 2-thread 3D run waited forever in
//     dsyrk_thread_LN under dpotrf;
//   - the pthread build adds its own threads to the solver's (oversubscribed cores) and splits
//     its work by their count, so the bits would depend on the machine.
// SparseSpdSolver calls it before its first factorisation.
void keep_blas_on_calling_thread();

}  // namespace vs
