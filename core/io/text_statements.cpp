// SPDX-License-Identifier: MIT
#include "core/io/text_statements.h"

#include <cctype>

#include "core/diagnostics.h"

namespace lamina::core {

namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

// true when only blanks follow position `pos` up to the end of its line
bool BlankToLineEnd(const std::string& text, size_t pos) {
  while (pos < text.size() && IsSpace(text[pos])) ++pos;
  return pos >= text.size() || text[pos] == '\n';
}

// scans one physical line starting at `pos`; appends tokens; returns true when the line
// ends with a continuation backslash. A backslash glued to the last token (`39\`) continues too;
// that token goes to `glued` as well.
bool ScanLine(const std::string& text, size_t& pos, int line, std::vector<Token>& tokens,
              std::vector<Token>* glued) {
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
        if (text[pos] == '\\' && BlankToLineEnd(text, pos + 1)) {
          glued->push_back(token);
          glued->back().text += '\\';
          continued = true;
          tokens.push_back(std::move(token));
          while (pos < text.size() && text[pos] != '\n') ++pos;
          if (pos < text.size()) ++pos;
          return true;
        }
        token.text += text[pos++];
      }
    }
    tokens.push_back(std::move(token));
  }
  if (pos < text.size() && text[pos] == '\n') ++pos;
  return continued;
}

}  // namespace

std::vector<Statement> SplitStatements(const std::string& text, const std::string& file,
                                       Diagnostics* diagnostics) {
  std::vector<Statement> statements;
  std::vector<Token> glued;
  size_t pos = 0;
  int line = 1;
  Statement current;
  while (pos < text.size()) {
    const bool continued = ScanLine(text, pos, line, current.tokens, &glued);
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
  for (const Token& token : glued) {
    if (diagnostics == nullptr) break;
    const std::string value = token.text.substr(0, token.text.size() - 1);
    diagnostics->Warning({file, token.line, token.column},
                         "'" + token.text +
                             "': the line continuation is glued to the value; "
                             "read as '" +
                             value + "', continued on the next line (as Klamp't)");
  }
  return statements;
}

}  // namespace lamina::core
