// SPDX-License-Identifier: MIT
// File-path helpers shared by the loaders and writers.
#pragma once

#include <string>

namespace lamina::core {

/// `reference` resolved against directory `base_dir` (unless absolute), made absolute and
/// lexically normalized ("a/./b/../c" -> "a/c"). Symlinks are not followed.
std::string ResolvePath(const std::string& base_dir, const std::string& reference);
/// The directory part of `path` ("" -> ".").
std::string DirectoryOf(const std::string& path);
/// `path` relative to directory `from_dir` ("../objects/cube.off"); both absolute.
std::string RelativePath(const std::string& path, const std::string& from_dir);
/// Lower-case extension without the dot ("OFF" -> "off"; "" when none).
std::string LowerExtension(const std::string& path);
/// The file name without directory and extension.
std::string StemOf(const std::string& path);
/// Whole file contents; false if it cannot be read.
bool ReadFileText(const std::string& path, std::string* text);
/// Writes `text` to `path` atomically: a temporary file in the same directory, then rename.
/// On failure returns false with a reason in `error`, and `path` is left untouched.
bool WriteFileAtomically(const std::string& path, const std::string& text, std::string* error);

}  // namespace lamina::core
