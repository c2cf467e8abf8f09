// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Must NOT compile: a flag parameter takes a bool, and the error says so
// (test `compile_fail_bijective_takes_a_bool`, see expect_compile_error.cmake).

#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

int main()
{
  namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;
  const auto np = NP::distortion_bound(4.1).bijective("no");
  (void)np;
  return 0;
}
