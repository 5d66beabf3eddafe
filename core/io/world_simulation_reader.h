// SPDX-License-Identifier: MIT
// The `<simulation>` block of a world file: `<globals>` and per-body `<terrain|object|robot>`
// parameters (padding, preshrink, surface, initial velocity). Every tunable is a row of the
// parameter table (core/model/params.h): its attribute is the row's key, its rule the row's.
#pragma once

#include <string>
#include <vector>

#include <tinyxml2.h>

#include "core/diagnostics.h"
#include "core/io/xml_element_reader.h"
#include "core/model/element.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Reads `<simulation>` into world->settings and the bodies' `sim` parameters. Bodies are
/// referred to by `index` or `name`; they must already be in `world`.
void ReadSimulationBlock(const tinyxml2::XMLElement& element, const std::string& path,
                         Diagnostics& diagnostics, WorldDesc* world);

/// Reads the attribute of each row in `rows` (named by the row's key) that the element has,
/// checks it against the table and sets it on `element` of `world`; refusals are reported and
/// leave the element's value as it was.
void ReadParamAttributes(const XmlElementReader& reader, const std::vector<const ParamSpec*>& rows,
                         WorldDesc* world, const ElementIndex& element);

}  // namespace lamina::core
