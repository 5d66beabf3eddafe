// SPDX-License-Identifier: MIT
// Shared pieces of the edit tests: the document they edit and a parameter edit that must exist.
#pragma once

#include <string_view>

#include "core/edit/document.h"
#include "core/edit/edit.h"
#include "core/model/element.h"

namespace lamina::test {

/// tests/data/edit/arm_and_blocks.xml loaded into a document (a PID-driven arm, two stacked
/// blocks at rest and a block falling onto the plane); a load failure fails the test.
core::WorldDocument ArmAndBlocksDocument();

/// The edit setting row `key` of `element` to `after`; a missing element or row throws
/// (GoogleTest reports it as a failure of the test).
core::ParamEdit ParamEditOf(const core::WorldDocument& document, const core::ElementIndex& element,
                            std::string_view key, core::ParamValue after);

}  // namespace lamina::test
