// SPDX-License-Identifier: MIT
#include "core/diagnostics.h"

#include <utility>

namespace lamina::core {

namespace {

const char* SeverityName(Severity severity) {
  switch (severity) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "error";
}

}  // namespace

std::string Diagnostic::Format() const {
  // appended piece by piece: GCC 12 at -O3 flags `":" + std::to_string(...)` with a false
  // -Wrestrict warning
  std::string out = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) {
    out += ':';
    out += std::to_string(where.line);
    if (where.column > 0) {
      out += ':';
      out += std::to_string(where.column);
    }
  }
  out += ": ";
  out += SeverityName(severity);
  out += ": ";
  out += message;
  return out;
}

void Diagnostics::Error(const SourceLocation& where, std::string message) {
  entries_.push_back({Severity::kError, where, std::move(message)});
  ++error_count_;
}

void Diagnostics::Warning(const SourceLocation& where, std::string message) {
  entries_.push_back({Severity::kWarning, where, std::move(message)});
  ++warning_count_;
}

void Diagnostics::Note(const SourceLocation& where, std::string message) {
  entries_.push_back({Severity::kNote, where, std::move(message)});
}

std::string Diagnostics::FormatAll() const {
  std::string out;
  for (const Diagnostic& entry : entries_) {
    out += entry.Format();
    out += '\n';
  }
  return out;
}

std::vector<std::string> Diagnostics::Messages(Severity severity) const {
  std::vector<std::string> out;
  for (const Diagnostic& entry : entries_) {
    if (entry.severity == severity) out.push_back(entry.Format());
  }
  return out;
}

void Diagnostics::Clear() {
  entries_.clear();
  error_count_ = 0;
  warning_count_ = 0;
}

}  // namespace lamina::core
