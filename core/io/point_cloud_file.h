// SPDX-License-Identifier: MIT
// Reading PCL's Point Cloud Data files (`.pcd`, format v0.7 and the older headers without
// VERSION), without PCL.
//
// The header is text, one keyword a line (`#` comments): VERSION, FIELDS (COLUMNS in the oldest
// files), SIZE (bytes: 1, 2, 4 or 8), TYPE (F float, I signed, U unsigned), COUNT (values per
// field, default 1), WIDTH, HEIGHT (default 1), VIEWPOINT (7 numbers), POINTS (default WIDTH ×
// HEIGHT; must equal it), and last DATA ascii | binary | binary_compressed. Binary data follows
// the DATA line at once: little-endian, one point after another, each point's fields packed in
// FIELDS order (SIZE × COUNT bytes each). binary_compressed is a little-endian uint32 compressed
// size, a uint32 uncompressed size, then LZF data that decompresses to every point's first field,
// then every point's second field, and so on (PCL's layout).
//
// What is kept: x, y and z (required; COUNT > 1 takes the first value) as doubles whatever
// their TYPE, and `rgb` or `rgba` when present as 4 bytes (a float whose bits are 0x00RRGGBB,
// PCL's packing, or an unsigned 0xAARRGGBB) as the display colour 0xRRGGBB. Every other field is
// read past. Points with a NaN or infinite coordinate (PCL's "no return") are skipped, with a
// note saying how many. The VIEWPOINT is checked and not applied (as PCL and Klamp't do).
//
// Every problem is a `file:line` diagnostic (the header line at fault; the DATA line for binary
// data; the data line for ascii values); nothing throws. Differences from Klamp't's reader:
// binary_compressed, I and U fields of every size, and 8-byte floats are read (Klamp't refuses or
// misreads them); NaN points are dropped (Klamp't keeps them); truncated data, a POINTS that
// disagrees with WIDTH × HEIGHT and a file without x, y or z are errors (Klamp't loads such a
// file partially or with no points); an ascii `rgb` of TYPE F written as an integer (PCL >= 1.8
// does so) is read as that integer, not as a float.
#pragma once

#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/geometry/point_cloud.h"

namespace lamina::core {

/// Parses the bytes of a `.pcd` file; `file` names it in diagnostics. std::nullopt on any error
/// (a cloud with no finite point is an error too).
std::optional<PointCloud> ParsePcd(const std::string& bytes, const std::string& file,
                                   Diagnostics& diagnostics);

/// Loads the `.pcd` file `path`; a missing file is reported at `where` (the reference to it).
std::optional<PointCloud> ReadPointCloudFile(const std::string& path, const SourceLocation& where,
                                             Diagnostics& diagnostics);

/// True for the extensions ReadPointCloudFile reads ("pcd").
bool IsPointCloudExtension(const std::string& lower_extension);

}  // namespace lamina::core
