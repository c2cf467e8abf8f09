// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// CHOLMOD 3 (SuiteSparse 5, as Debian ships it) built with OpenMP opens
// parallel regions of a fixed 4 threads (CHOLMOD_OMP_NUM_THREADS) around
// the memory loops of each supernode: thousands per factorization, each
// waking sleeping threads. BLAS does the arithmetic, so the regions gain
// nothing; on 2 cores they made the factorization of 97k unknowns 1.6x
// slower (0.40 s against 0.22 s) and cost 4 s of system time in a
// 96544-face distortion-only run. The library cannot set OMP_THREAD_LIMIT
// (read once at load), but max-active-levels-var is the calling thread's
// own ICV (OpenMP 5.0): set to 0 it makes the regions this thread opens run
// on the thread alone, for the scope's lifetime only.
//
// The package does not depend on OpenMP: without -fopenmp the two runtime
// functions are weak references, resolved by the runtime that CHOLMOD
// loaded (if any); elsewhere the scope does nothing.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SERIAL_OPENMP_SCOPE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SERIAL_OPENMP_SCOPE_H

#if defined(_OPENMP)
#include <omp.h>
#define CGAL_SMSO_OPENMP_LEVELS_DIRECT 1
#elif defined(__ELF__) && (defined(__GNUC__) || defined(__clang__))
extern "C" {
void omp_set_max_active_levels(int) __attribute__((weak));
int omp_get_max_active_levels(void) __attribute__((weak));
}
#define CGAL_SMSO_OPENMP_LEVELS_WEAK 1
#endif

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// whether an OpenMP runtime is there to ask (linked or loaded by a library)
inline bool openmp_runtime_available()
{
#if defined(CGAL_SMSO_OPENMP_LEVELS_DIRECT)
  return true;
#elif defined(CGAL_SMSO_OPENMP_LEVELS_WEAK)
  return &omp_set_max_active_levels != nullptr && &omp_get_max_active_levels != nullptr;
#else
  return false;
#endif
}

// the calling thread's max-active-levels-var, or -1 without a runtime
inline int openmp_max_active_levels()
{
  if(!openmp_runtime_available()) return -1;
#if defined(CGAL_SMSO_OPENMP_LEVELS_DIRECT) || defined(CGAL_SMSO_OPENMP_LEVELS_WEAK)
  return omp_get_max_active_levels();
#else
  return -1;
#endif
}

class Serial_openmp_scope
{
public:
  explicit Serial_openmp_scope(bool active = true)
  {
#if defined(CGAL_SMSO_OPENMP_LEVELS_DIRECT) || defined(CGAL_SMSO_OPENMP_LEVELS_WEAK)
    if(!active || !openmp_runtime_available()) return;
    m_saved = omp_get_max_active_levels();
    if(m_saved != 0) omp_set_max_active_levels(0);
#else
    (void)active;
#endif
  }
  ~Serial_openmp_scope()
  {
#if defined(CGAL_SMSO_OPENMP_LEVELS_DIRECT) || defined(CGAL_SMSO_OPENMP_LEVELS_WEAK)
    if(m_saved > 0) omp_set_max_active_levels(m_saved);
#endif
  }
  Serial_openmp_scope(const Serial_openmp_scope&) = delete;
  Serial_openmp_scope& operator=(const Serial_openmp_scope&) = delete;

private:
  int m_saved = -1;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
