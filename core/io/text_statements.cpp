// SPDX-License-Identifier: MIT
#include "core/io/text_statements.h"

#include <cctype>

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

}  // namespace lamina::core
