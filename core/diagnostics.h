// SPDX-License-Identifier: MIT
// Diagnostics: located messages about bad input, collected so one run reports every problem.
// Format follows the compiler convention `file:line: severity: message` (column when known).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace lamina::core {

enum class Severity { kNote, kWarning, kError };

/// Stores `message` in `*error` unless `error` is null, and returns false: the failure path of
/// the functions that report through an optional error string.
inline bool FailWith(std::string* error, std::string message) {
  if (error) *error = std::move(message);
  return false;
}

/// Where a piece of input came from. line/column are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

struct Diagnostic {
  Severity severity = Severity::kError;
  SourceLocation where;
  std::string message;

  /// `file:line:col: error: message`; line and column are left out when unknown.
  std::string Format() const;
};

/// A sink that collects diagnostics from loaders. Never throws, never aborts.
class Diagnostics {
 public:
  void Error(const SourceLocation& where, std::string message);
  void Warning(const SourceLocation& where, std::string message);
  void Note(const SourceLocation& where, std::string message);

  bool HasErrors() const { return error_count_ > 0; }
  int error_count() const { return error_count_; }
  int warning_count() const { return warning_count_; }
  const std::vector<Diagnostic>& entries() const { return entries_; }

  /// Every diagnostic formatted, one per line.
  std::string FormatAll() const;
  /// The formatted messages of one severity, in order.
  std::vector<std::string> Messages(Severity severity) const;
  void Clear();

 private:
  std::vector<Diagnostic> entries_;
  int error_count_ = 0;
  int warning_count_ = 0;
};

}  // namespace lamina::core
