// SPDX-License-Identifier: MIT
// The one tokenizer behind every Klamp't text format (.rob, .obj, .env, .geom, .config, .path,
// .milestones): whitespace-separated tokens with line and column, `#` comments, `"quoted"`
// tokens, and a trailing backslash that continues a statement on the next line.
#pragma once

#include <string>
#include <vector>

namespace lamina::core {

struct Token {
  std::string text;  ///< without quotes for quoted tokens
  int line = 0;      ///< 1-based
  int column = 0;    ///< 1-based
  bool quoted = false;
};

/// One logical line: the tokens of a physical line plus any continuation lines.
struct Statement {
  std::vector<Token> tokens;
  int line = 0;  ///< line of the first token
};

/// Splits `text` into non-empty statements.
std::vector<Statement> SplitStatements(const std::string& text);

/// Parses a whole token as a double: decimal or exponent notation, "inf", "+inf", "-inf"
/// (any case). NaN, hex and trailing garbage are rejected.
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
