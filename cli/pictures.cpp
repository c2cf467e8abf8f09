// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The pictures of optimize_seams for its mesh types (see pictures.h).

#include "pictures.h"

#include "render_png.h"
#include "uv_layout_svg.h"

namespace optimize_seams_cli {

bool png_supported() { return png_available; }

bool write_uv_layout_svg_file(const std::string& path, const Mesh& mesh, UV_map uvmap, Seam_map seams,
                              const Picture_caption& caption)
{
  return write_uv_layout_svg(path, mesh, uvmap, seams, caption);
}

bool render_png_file(const std::string& path, const Mesh& mesh, UV_map uvmap, Seam_map seams,
                     std::string& error)
{
  return render_png(path, mesh, uvmap, seams, Png_render_options(), error);
}

} // namespace optimize_seams_cli
