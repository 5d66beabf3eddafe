// SPDX-License-Identifier: MIT
// "Did you mean": the known name closest to a misspelt one, for the diagnostics of the file
// readers (unknown attributes and keywords) and of access paths (unknown items and element
// names). Below every folder of the core, next to the numbers as text. Klamp't has no
// suggestions; its readers ignore unknown names silently.
#pragma once

#include <string>
#include <vector>

namespace lamina::core {

/// The known name closest to `name` (case-insensitive edit distance <= 2, <= 3 for names of 8
/// characters or more, or `name` with a Klamp't `k` prefix), or "" when none is close.
std::string SuggestName(const std::string& name, const std::vector<std::string>& known);

}  // namespace lamina::core
