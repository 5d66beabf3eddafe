// SPDX-License-Identifier: MIT
#include "core/number_text.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace lamina::core {

bool ParseDouble(const std::string& text, double* value) {
  if (text.empty()) return false;
  const std::string lower = ToLower(text);
  if (lower == "inf" || lower == "+inf" || lower == "infinity") {
    *value = HUGE_VAL;
    return true;
  }
  if (lower == "-inf" || lower == "-infinity") {
    *value = -HUGE_VAL;
    return true;
  }
  if (lower.find_first_of("xnp") != std::string::npos) return false;  // hex, nan, inf-like
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(parsed)) {
    return false;
  }
  *value = parsed;
  return true;
}

bool ParseInt(const std::string& text, int* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (end != text.c_str() + text.size() || errno == ERANGE || parsed < -2147483647L ||
      parsed > 2147483647L) {
    return false;
  }
  *value = static_cast<int>(parsed);
  return true;
}

std::string FormatDouble(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  if (value == 0.0) return "0";  // also turns -0 into 0
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string FormatDoubles(const double* values, int count) {
  std::string out;
  for (int i = 0; i < count; ++i) {
    if (i > 0) out += ' ';
    out += FormatDouble(values[i]);
  }
  return out;
}

std::string ToLower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace lamina::core
