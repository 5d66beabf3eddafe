// SPDX-License-Identifier: MIT
// Numbers as text, below every other part of the core: the exact parsing and the shortest
// round-trip formatting of doubles that the file formats, the world comparison, the parameter
// table, access paths and the logs share.
#pragma once

#include <string>

namespace lamina::core {

/// Parses a whole token as a double: decimal or exponent notation, "inf", "+inf", "-inf" (any
/// case). NaN, hex and trailing garbage are rejected.
bool ParseDouble(const std::string& text, double* value);
/// Parses a whole token as a (decimal, optionally signed) int.
bool ParseInt(const std::string& text, int* value);
/// Shortest text that ParseDouble reads back to exactly `value` ("0.1", "1e-06", "inf").
std::string FormatDouble(double value);
/// Values separated by single spaces, each with FormatDouble.
std::string FormatDoubles(const double* values, int count);
/// Lower-case copy.
std::string ToLower(std::string text);

}  // namespace lamina::core
