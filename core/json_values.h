// SPDX-License-Identifier: MIT
// JSON values the reports and summaries share (run --json, world summaries, the accuracy and
// stress reports): a number that may not be finite, and a vector as an array of three numbers.
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/math_types.h"

namespace lamina::core {

/// The number, or null when it is inf or NaN (JSON numbers cannot be either).
inline nlohmann::json FiniteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

/// [x, y, z].
inline nlohmann::ordered_json JsonVector(const Vec3& v) {
  return nlohmann::ordered_json::array({v.x(), v.y(), v.z()});
}

}  // namespace lamina::core
