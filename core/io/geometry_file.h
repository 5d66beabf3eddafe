// SPDX-License-Identifier: MIT
// Loading a geometry file of any kind: a mesh or a `.pcd` point cloud (through MeshCache), or a
// Klamp't `.geom` text file holding a primitive.
#pragma once

#include <optional>
#include <string>

#include "core/geometry/geometry_desc.h"
#include "core/io/load_context.h"

namespace lamina::core {

/// Fills `out->kind`, `path`, `mesh`, `primitive` or `point_cloud` from file `path` (absolute).
/// Leaves scale, transform and margin alone. Returns false (with diagnostics) on failure.
bool LoadGeometryFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                      GeometryDesc* out);

/// Parses Klamp't `.geom` text ("Primitive" header, then e.g. "Sphere" / "0 0 0  1").
std::optional<Primitive> ParseGeomText(const std::string& text, const std::string& file,
                                       Diagnostics& diagnostics);

/// `.geom` text that ParseGeomText reads back as the same shape (spheres, boxes, cylinders,
/// capsules); std::nullopt for a plane, which the format cannot hold.
std::optional<std::string> WriteGeomText(const Primitive& primitive);

}  // namespace lamina::core
