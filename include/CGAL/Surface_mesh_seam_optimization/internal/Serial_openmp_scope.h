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
// functions are looked up (dlsym) in the runtime that CHOLMOD loaded, if
// any; elsewhere the scope does nothing.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SERIAL_OPENMP_SCOPE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SERIAL_OPENMP_SCOPE_H

#if defined(_OPENMP)
#include <omp.h>
#define CGAL_SMSO_OPENMP_LEVELS_DIRECT 1
#elif defined(__unix__) || defined(__APPLE__)
// looked up at run time: a weak declaration would also make the user's own
// references to these functions weak (and null once the linker drops libgomp)
#include <dlfcn.h>
#define CGAL_SMSO_OPENMP_LEVELS_DLSYM 1
#endif

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Openmp_levels_api
{
  void (*set)(int) = nullptr;
  int (*get)() = nullptr;
};

// the runtime's functions, or null ones without a runtime (looked up once)
inline const Openmp_levels_api& openmp_levels_api()
{
  static const Openmp_levels_api api = [] {
    Openmp_levels_api a;
#if defined(CGAL_SMSO_OPENMP_LEVELS_DIRECT)
    a.set = &omp_set_max_active_levels;
    a.get = &omp_get_max_active_levels;
#elif defined(CGAL_SMSO_OPENMP_LEVELS_DLSYM)
    a.set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
    a.get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
    if(!a.set || !a.get) a = Openmp_levels_api();
#endif
    return a;
  }();
  return api;
}

// whether an OpenMP runtime is there to ask (linked or loaded by a library)
inline bool openmp_runtime_available() { return openmp_levels_api().get != nullptr; }

// the calling thread's max-active-levels-var, or -1 without a runtime
inline int openmp_max_active_levels()
{
  return openmp_runtime_available() ? openmp_levels_api().get() : -1;
}

class Serial_openmp_scope
{
public:
  explicit Serial_openmp_scope(bool active = true)
  {
    if(!active || !openmp_runtime_available()) return;
    m_saved = openmp_levels_api().get();
    if(m_saved != 0) openmp_levels_api().set(0);
  }
  ~Serial_openmp_scope()
  {
    if(m_saved > 0) openmp_levels_api().set(m_saved);
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
