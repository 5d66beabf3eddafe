// SPDX-License-Identifier: MIT
#include "core/io/text_statements.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace lamina::core {

namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// scans one physical line starting at `pos`; appends tokens; returns true when the line
// ends with a continuation backslash
bool ScanLine(const std::string& text, size_t& pos, int line, std::vector<Token>& tokens) {
  const size_t line_start = pos;
  bool continued = false;
  while (pos < text.size() && text[pos] != '\n') {
    const char c = text[pos];
    if (IsSpace(c)) {
      ++pos;
      continue;
    }
    if (c == '#') {
      while (pos < text.size() && text[pos] != '\n') ++pos;
      break;
    }
    if (c == '\\') {
      // a backslash followed only by blanks up to the end of line continues the statement
      size_t look = pos + 1;
      while (look < text.size() && IsSpace(text[look])) ++look;
      if (look >= text.size() || text[look] == '\n') {
        continued = true;
        pos = look;
        break;
      }
    }
    Token token;
    token.line = line;
    token.column = static_cast<int>(pos - line_start) + 1;
    if (c == '"') {
      token.quoted = true;
      ++pos;
      while (pos < text.size() && text[pos] != '"' && text[pos] != '\n') token.text += text[pos++];
      if (pos < text.size() && text[pos] == '"') ++pos;
    } else {
      while (pos < text.size() && !IsSpace(text[pos]) && text[pos] != '\n' && text[pos] != '#') {
        token.text += text[pos++];
      }
    }
    tokens.push_back(std::move(token));
  }
  if (pos < text.size() && text[pos] == '\n') ++pos;
  return continued;
}

}  // namespace

std::vector<Statement> SplitStatements(const std::string& text) {
  std::vector<Statement> statements;
  size_t pos = 0;
  int line = 1;
  Statement current;
  while (pos < text.size()) {
    const bool continued = ScanLine(text, pos, line, current.tokens);
    ++line;
    if (continued) continue;
    if (!current.tokens.empty()) {
      current.line = current.tokens.front().line;
      statements.push_back(std::move(current));
    }
    current = Statement();
  }
  if (!current.tokens.empty()) {
    current.line = current.tokens.front().line;
    statements.push_back(std::move(current));
  }
  return statements;
}

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
