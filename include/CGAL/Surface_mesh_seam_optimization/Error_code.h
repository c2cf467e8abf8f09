// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Result codes of the package: returned, never thrown, never exit().

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ERROR_CODE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ERROR_CODE_H

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Result codes. `OK` and the `WARNING_*` codes mean a valid result (no
/// flipped and no degenerate UV triangle, checked before writing) was written
/// into the user's maps; every `ERROR_*` code means the user's maps were left
/// untouched. New codes are appended, so the values of the others do not change.
enum Error_code
{
  OK = 0,                            ///< success
  WARNING_MAXIMUM_ITERATIONS,        ///< iteration limit reached; best result so far written
  WARNING_CANCELLED,                 ///< the visitor stopped the run; best result so far written
  WARNING_BOUND_NOT_MET,             ///< converged, but the distortion bound could not be met
  ERROR_EMPTY_MESH,                  ///< the mesh has no face
  ERROR_NON_TRIANGULAR_MESH,         ///< a face is not a triangle
  ERROR_NON_MANIFOLD_MESH,           ///< a vertex or an edge is not manifold
  ERROR_NON_FINITE_COORDINATES,      ///< a point has a NaN or infinite coordinate
  ERROR_DEGENERATE_TRIANGLE,         ///< a triangle has (numerically) zero 3D area
  ERROR_NOT_A_DISK,                  ///< a chart is not a topological disk
  ERROR_INVALID_UV_MAP,              ///< a UV coordinate is missing or not finite
  ERROR_FLIPPED_UV_TRIANGLE,         ///< the given UV map has a flipped or degenerate triangle
  ERROR_INITIAL_PARAMETERIZATION,    ///< no valid initial map could be computed
  ERROR_LINEAR_SOLVER,               ///< the sparse linear solver failed
  ERROR_WRONG_PARAMETER,             ///< a named parameter has an invalid value
  ERROR_OVERLAPPING_UV_MAP,          ///< `bijective` was asked for, but the given UV map overlaps itself
  WARNING_TIME_LIMIT,                ///< the `time_limit` was reached; best result so far written
  ERROR_DEGENERATE_UV_RESULT         ///< the optimized map has a flipped or (numerically) degenerate triangle: not written
};

/// true when the code means that a result was written
inline bool has_result(Error_code code)
{
  return code == OK || code == WARNING_MAXIMUM_ITERATIONS ||
         code == WARNING_CANCELLED || code == WARNING_BOUND_NOT_MET || code == WARNING_TIME_LIMIT;
}

/// A short English message for `code` (a `switch`, so it cannot go out of sync).
inline const char* get_error_message(Error_code code)
{
  switch(code)
  {
    case OK: return "Success";
    case WARNING_MAXIMUM_ITERATIONS: return "Maximum number of iterations reached";
    case WARNING_CANCELLED: return "Cancelled by the visitor";
    case WARNING_BOUND_NOT_MET: return "The distortion bound could not be met";
    case ERROR_EMPTY_MESH: return "The input mesh is empty";
    case ERROR_NON_TRIANGULAR_MESH: return "The input mesh is not a triangle mesh";
    case ERROR_NON_MANIFOLD_MESH: return "The input mesh is not manifold";
    case ERROR_NON_FINITE_COORDINATES: return "The input mesh has a non-finite coordinate";
    case ERROR_DEGENERATE_TRIANGLE: return "The input mesh has a degenerate (zero-area) triangle";
    case ERROR_NOT_A_DISK: return "A chart is not a topological disk";
    case ERROR_INVALID_UV_MAP: return "The UV map has a missing or non-finite coordinate";
    case ERROR_FLIPPED_UV_TRIANGLE: return "The UV map has a flipped or degenerate triangle";
    case ERROR_INITIAL_PARAMETERIZATION: return "The initial parameterization failed";
    case ERROR_LINEAR_SOLVER: return "The sparse linear solver failed";
    case ERROR_WRONG_PARAMETER: return "A parameter has an invalid value";
    case ERROR_OVERLAPPING_UV_MAP: return "The given UV map overlaps itself (pass bijective(false) to accept it)";
    case WARNING_TIME_LIMIT: return "Time limit reached: best result so far";
    case ERROR_DEGENERATE_UV_RESULT: return "The optimized UV map has a flipped or degenerate triangle";
  }
  return "Unknown error";
}

/// The enumerator's name, e.g. `"ERROR_NOT_A_DISK"` (for reports and logs).
inline const char* get_error_code_name(Error_code code)
{
  switch(code)
  {
    case OK: return "OK";
    case WARNING_MAXIMUM_ITERATIONS: return "WARNING_MAXIMUM_ITERATIONS";
    case WARNING_CANCELLED: return "WARNING_CANCELLED";
    case WARNING_BOUND_NOT_MET: return "WARNING_BOUND_NOT_MET";
    case ERROR_EMPTY_MESH: return "ERROR_EMPTY_MESH";
    case ERROR_NON_TRIANGULAR_MESH: return "ERROR_NON_TRIANGULAR_MESH";
    case ERROR_NON_MANIFOLD_MESH: return "ERROR_NON_MANIFOLD_MESH";
    case ERROR_NON_FINITE_COORDINATES: return "ERROR_NON_FINITE_COORDINATES";
    case ERROR_DEGENERATE_TRIANGLE: return "ERROR_DEGENERATE_TRIANGLE";
    case ERROR_NOT_A_DISK: return "ERROR_NOT_A_DISK";
    case ERROR_INVALID_UV_MAP: return "ERROR_INVALID_UV_MAP";
    case ERROR_FLIPPED_UV_TRIANGLE: return "ERROR_FLIPPED_UV_TRIANGLE";
    case ERROR_INITIAL_PARAMETERIZATION: return "ERROR_INITIAL_PARAMETERIZATION";
    case ERROR_LINEAR_SOLVER: return "ERROR_LINEAR_SOLVER";
    case ERROR_WRONG_PARAMETER: return "ERROR_WRONG_PARAMETER";
    case ERROR_OVERLAPPING_UV_MAP: return "ERROR_OVERLAPPING_UV_MAP";
    case WARNING_TIME_LIMIT: return "WARNING_TIME_LIMIT";
    case ERROR_DEGENERATE_UV_RESULT: return "ERROR_DEGENERATE_UV_RESULT";
  }
  return "ERROR_UNKNOWN";
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ERROR_CODE_H
