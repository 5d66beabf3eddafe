// SPDX-License-Identifier: MIT
// The `<simulation>` block of a world file: `<globals>` and per-body `<terrain|object|robot>`
// parameters (padding, preshrink, surface, initial velocity).
#pragma once

#include <string>

#include <tinyxml2.h>

#include "core/diagnostics.h"
#include "core/io/xml_element_reader.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Reads `<simulation>` into world->settings and the bodies' `sim` parameters. Bodies are
/// referred to by `index` or `name`; they must already be in `world`.
void ReadSimulationBlock(const tinyxml2::XMLElement& element, const std::string& path,
                         Diagnostics& diagnostics, WorldDesc* world);

/// Reads kRestitution, kFriction, kStiffness and kDamping, checking their ranges.
void ReadSurfaceAttributes(const XmlElementReader& reader, SurfaceDesc* surface);

}  // namespace lamina::core
