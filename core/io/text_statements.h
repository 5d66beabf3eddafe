// SPDX-License-Identifier: MIT
// The one tokenizer behind every Klamp't text format (.rob, .obj, .env, .geom, .config, .path,
// .milestones): whitespace-separated tokens with line and column, `#` comments, `"quoted"`
// tokens, and a trailing backslash that continues a statement on the next line.
#pragma once

#include <string>
#include <vector>

#include "core/number_text.h"  // ParseDouble, FormatDouble, ... (used with the tokens)

namespace lamina::core {

class Diagnostics;

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

/// Splits `text` into non-empty statements. A continuation backslash glued to the last value of
/// a line (`39\`, which Klamp't reads as 39 and continues) is accepted with a warning at `file`
/// and the token's line and column when `diagnostics` is given.
std::vector<Statement> SplitStatements(const std::string& text, const std::string& file = "",
                                       Diagnostics* diagnostics = nullptr);

}  // namespace lamina::core
