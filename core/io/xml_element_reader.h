// SPDX-License-Identifier: MIT
// Typed, located reading of XML attributes for the world loader: every bad value becomes a
// `file:line: error:` naming the element and attribute, every unknown attribute a warning with
// a "did you mean" suggestion.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "core/diagnostics.h"
#include "core/math_types.h"
#include "core/model/params.h"
#include "core/suggest.h"  // SuggestName, used with the readers

namespace lamina::core {

class XmlElementReader {
 public:
  XmlElementReader(const tinyxml2::XMLElement& element, const std::string& file,
                   Diagnostics& diagnostics);

  /// `<tag name="...">` (or index="..." when unnamed, else `<tag>`), for messages.
  const std::string& label() const { return label_; }
  SourceLocation location() const { return {file_, element_.GetLineNum(), 0}; }
  const tinyxml2::XMLElement& element() const { return element_; }

  bool Has(const char* name) const { return element_.Attribute(name) != nullptr; }
  std::optional<std::string> String(const char* name) const;
  /// A finite number, or inf when `allow_infinite`.
  std::optional<double> Number(const char* name, bool allow_infinite = true) const;
  /// Exactly `count` numbers.
  std::optional<std::vector<double>> Numbers(const char* name, int count) const;
  std::optional<Vec3> Vector3(const char* name) const;
  std::optional<int> Integer(const char* name) const;
  /// "0"/"1"/"true"/"false".
  std::optional<bool> Boolean(const char* name) const;
  /// A Klamp't vector "N v1 ... vN": the count must match the values that follow.
  std::optional<VecX> CountedVector(const char* name) const;

  /// Attribute `name` (the row's key when null) as a value of table row `spec` with `size`
  /// components, checked with ParamAccepts. nullopt when absent or refused; a refusal is
  /// reported as "attribute 'kRestitution' must be in [0, 1], got '1.5'".
  std::optional<ParamValue> Param(const ParamSpec& spec, int size,
                                  const char* name = nullptr) const;
  /// Checks a value of row `spec` assembled from attributes `from` (a pose from position and
  /// rotateRPY, ...); a refusal is reported as "'transform' (from position, rotateRPY) must be
  /// ..., got '...'".
  bool CheckAssembled(const ParamSpec& spec, const ParamValue& value, int size,
                      const std::string& from) const;

  /// Reports an error about attribute `name` of this element.
  void Error(const char* name, const std::string& message) const;
  void Error(const std::string& message) const;
  void Warning(const std::string& message) const;

  /// Warns about every attribute not in `known`, suggesting the closest known name.
  void WarnUnknownAttributes(std::initializer_list<const char*> known) const;
  void WarnUnknownAttributes(const std::vector<std::string>& known) const;

 private:
  std::optional<std::vector<double>> AllNumbers(const char* name) const;

  const tinyxml2::XMLElement& element_;
  std::string file_;
  Diagnostics& diagnostics_;
  std::string label_;
};

}  // namespace lamina::core
