// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The optimizers instantiated for Conformal_energy (see run_optimization.h).

#include "run_optimization_impl.h"

#include <CGAL/Surface_mesh_seam_optimization/Conformal_energy.h>

namespace optimize_seams_cli {

SMSO::Optimization_result run_mips(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                   const Optimization_request& request)
{
  return run_with_energy(mesh, uvmap, seams, request, SMSO::Conformal_energy(request.area_weight));
}

} // namespace optimize_seams_cli
