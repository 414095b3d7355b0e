// A scope in which OpenMP sizes every parallel region's team dynamically (libgomp: at most this
// thread's team size and the idle cores), for calling libraries that ask for fixed teams.
#pragma once

#include <omp.h>

namespace vs {

// CHOLMOD 3 (SuiteSparse 5) opens an OpenMP region of a fixed 4 threads (num_threads(
// CHOLMOD_OMP_NUM_THREADS)) to clear and scatter into every large supernode: thousands of tiny
// regions a factorisation, each waking 4 threads. On 2 cores that oversubscribes them and the
// spinning waiters stall the work (measured, ex4a n = 16, 15 845 unknowns: 0.194 s a numeric
// factorisation against 0.068 s with OMP_THREAD_LIMIT = 2 or 1; n = 32: 1.11 s against 0.53 s).
// With dynamic adjustment on (a per-thread setting), libgomp caps a region's team at this
// thread's team size and at the idle cores (the cores minus the 15-minute load average), whatever
// the region asks for. The scope sets it and restores the thread's setting at its end;
// SparseSpdSolver opens one around each CHOLMOD call.
class DynamicTeams {
 public:
  DynamicTeams() : was_(omp_get_dynamic()) { omp_set_dynamic(1); }
  ~DynamicTeams() { omp_set_dynamic(was_); }
  DynamicTeams(const DynamicTeams&) = delete;
  DynamicTeams& operator=(const DynamicTeams&) = delete;

 private:
  int was_;
};

}  // namespace vs
