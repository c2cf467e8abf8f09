// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The two pictures of the command-line program, compiled apart in
// pictures.cpp (uv_layout_svg.h, render_png.h).

#ifndef SMSO_CLI_PICTURES_H
#define SMSO_CLI_PICTURES_H

#include "picture_common.h"
#include "run_optimization.h"

#include <string>

namespace optimize_seams_cli {

// Whether --png can work (the program was built with libpng).
bool png_supported();

// --svg: the UV layout. False if the file cannot be written.
bool write_uv_layout_svg_file(const std::string& path, const Mesh& mesh, UV_map uvmap, Seam_map seams,
                              const Picture_caption& caption);

// --png: the textured 3D model. False with `error` set on failure.
bool render_png_file(const std::string& path, const Mesh& mesh, UV_map uvmap, Seam_map seams,
                     std::string& error);

} // namespace optimize_seams_cli

#endif // SMSO_CLI_PICTURES_H
