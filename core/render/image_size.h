// SPDX-License-Identifier: MIT
// Image sizes as the command lines write them: "WIDTHxHEIGHT".
#pragma once

#include <string>

namespace lamina::core {

/// Largest width or height accepted, pixels.
inline constexpr int kMaxImageSide = 16384;

/// Parses "WIDTHxHEIGHT" with 1..kMaxImageSide pixels per side; false (outputs unspecified) for
/// anything else.
bool ParseImageSize(const std::string& text, int* width, int* height);

}  // namespace lamina::core
