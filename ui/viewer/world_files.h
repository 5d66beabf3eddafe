// SPDX-License-Identifier: MIT
// The world files the editor's Open-world panel lists: XML files under a directory whose root
// element is <world> (motions, MultiPath files and other XML are left out).
#pragma once

#include <string>
#include <vector>

namespace lamina::ui {

/// True when the file's first element (after the XML declaration, comments and blanks) is
/// <world>; reads at most the first 64 KiB.
bool IsWorldFile(const std::string& path);

/// Every world file under `directory` (recursively), sorted; empty when it is not a directory.
std::vector<std::string> WorldFilesUnder(const std::string& directory);

}  // namespace lamina::ui
