// SPDX-License-Identifier: MIT
#include "core/io/xml_element_reader.h"

#include <algorithm>
#include <cmath>

#include "core/io/param_text.h"
#include "core/io/text_statements.h"

namespace lamina::core {

namespace {

std::string MakeLabel(const tinyxml2::XMLElement& element) {
  // appended piece by piece: GCC 12 at -O3 flags `"<" + std::string` with a false -Wrestrict
  std::string label = "<";
  label += element.Name();
  for (const char* key : {"name", "index"}) {
    if (const char* value = element.Attribute(key)) {
      label += ' ';
      label += key;
      label += "=\"";
      label += value;
      label += '"';
      break;
    }
  }
  label += '>';
  return label;
}

}  // namespace

XmlElementReader::XmlElementReader(const tinyxml2::XMLElement& element, const std::string& file,
                                   Diagnostics& diagnostics)
    : element_(element), file_(file), diagnostics_(diagnostics), label_(MakeLabel(element)) {}

std::optional<std::string> XmlElementReader::String(const char* name) const {
  const char* value = element_.Attribute(name);
  if (!value) return std::nullopt;
  return std::string(value);
}

std::optional<std::vector<double>> XmlElementReader::AllNumbers(const char* name) const {
  const char* value = element_.Attribute(name);
  if (!value) return std::nullopt;
  std::vector<double> numbers;
  for (const std::string& word : SplitWords(value)) {
    double number = 0.0;
    if (!ParseDouble(word, &number)) {
      Error(name, "has '" + word + "', which is not a number");
      return std::nullopt;
    }
    numbers.push_back(number);
  }
  return numbers;
}

std::optional<double> XmlElementReader::Number(const char* name, bool allow_infinite) const {
  const auto numbers = AllNumbers(name);
  if (!numbers) return std::nullopt;
  if (numbers->size() != 1) {
    Error(name, "expects 1 number, got '" + std::string(element_.Attribute(name)) + "'");
    return std::nullopt;
  }
  if (!allow_infinite && std::isinf(numbers->front())) {
    Error(name, "must be finite, got '" + std::string(element_.Attribute(name)) + "'");
    return std::nullopt;
  }
  return numbers->front();
}

std::optional<std::vector<double>> XmlElementReader::Numbers(const char* name, int count) const {
  auto numbers = AllNumbers(name);
  if (!numbers) return std::nullopt;
  if (static_cast<int>(numbers->size()) != count) {
    Error(name, "expects " + std::to_string(count) + " numbers, got '" +
                    std::string(element_.Attribute(name)) + "'");
    return std::nullopt;
  }
  for (double number : *numbers) {
    if (std::isinf(number)) {
      Error(name, "must be finite, got '" + std::string(element_.Attribute(name)) + "'");
      return std::nullopt;
    }
  }
  return numbers;
}

std::optional<Vec3> XmlElementReader::Vector3(const char* name) const {
  const auto numbers = Numbers(name, 3);
  if (!numbers) return std::nullopt;
  return Vec3((*numbers)[0], (*numbers)[1], (*numbers)[2]);
}

std::optional<int> XmlElementReader::Integer(const char* name) const {
  const char* value = element_.Attribute(name);
  if (!value) return std::nullopt;
  const std::vector<std::string> words = SplitWords(value);
  int number = 0;
  if (words.size() != 1 || !ParseInt(words[0], &number)) {
    Error(name, "expects an integer, got '" + std::string(value) + "'");
    return std::nullopt;
  }
  return number;
}

std::optional<bool> XmlElementReader::Boolean(const char* name) const {
  const char* value = element_.Attribute(name);
  if (!value) return std::nullopt;
  const std::string word = ToLower(value);
  if (word == "1" || word == "true") return true;
  if (word == "0" || word == "false") return false;
  Error(name, "expects 0 or 1, got '" + std::string(value) + "'");
  return std::nullopt;
}

std::optional<VecX> XmlElementReader::CountedVector(const char* name) const {
  const auto numbers = AllNumbers(name);
  if (!numbers) return std::nullopt;
  const int declared = numbers->empty() ? -1 : static_cast<int>(numbers->front());
  const int given = static_cast<int>(numbers->size()) - 1;
  if (numbers->empty() || numbers->front() != declared || declared != given) {
    Error(name, "declares " + std::to_string(std::max(declared, 0)) + " values but gives " +
                    std::to_string(std::max(given, 0)));
    return std::nullopt;
  }
  VecX vector(given);
  for (int i = 0; i < given; ++i) vector[i] = (*numbers)[i + 1];
  return vector;
}

std::optional<ParamValue> XmlElementReader::Param(const ParamSpec& spec, int size,
                                                  const char* name) const {
  const std::string attribute = name ? std::string(name) : std::string(spec.key);
  const char* text = element_.Attribute(attribute.c_str());
  if (!text) return std::nullopt;
  std::string bad_word;
  const auto value = ParamFromWords(spec, SplitWords(text), &bad_word);
  const bool named = spec.type == ParamType::kBool || spec.type == ParamType::kChoice;
  if (!value && !named) {
    Error(attribute.c_str(), "has '" + bad_word + "', which is not a number");
    return std::nullopt;
  }
  if (value && static_cast<int>(value->size()) != size) {
    const std::string count = size == 1 ? "1 number" : std::to_string(size) + " numbers";
    Error(attribute.c_str(), "expects " + count + ", got '" + text + "'");
    return std::nullopt;
  }
  if (value && !ParamAccepts(spec, *value, size)) {
    if (const auto lenient = LenientInertia(spec, *value)) {
      Warning("attribute '" + attribute + "' " + lenient->warning);
      return lenient->value;
    }
  }
  if (!value || !ParamAccepts(spec, *value, size)) {
    Error(attribute.c_str(), ParamRefusal(spec, text));
    return std::nullopt;
  }
  return value;
}

bool XmlElementReader::CheckAssembled(const ParamSpec& spec, const ParamValue& value, int size,
                                      const std::string& from) const {
  if (ParamAccepts(spec, value, size)) return true;
  Error("'" + std::string(spec.key) + "' (from " + from + ") " +
        ParamRefusal(spec, ParamWords(spec, value)));
  return false;
}

void XmlElementReader::Error(const char* name, const std::string& message) const {
  diagnostics_.Error(location(), label_ + ": attribute '" + name + "' " + message);
}

void XmlElementReader::Error(const std::string& message) const {
  diagnostics_.Error(location(), label_ + ": " + message);
}

void XmlElementReader::Warning(const std::string& message) const {
  diagnostics_.Warning(location(), label_ + ": " + message);
}

void XmlElementReader::WarnUnknownAttributes(std::initializer_list<const char*> known) const {
  WarnUnknownAttributes(std::vector<std::string>(known.begin(), known.end()));
}

void XmlElementReader::WarnUnknownAttributes(const std::vector<std::string>& names) const {
  for (const tinyxml2::XMLAttribute* attribute = element_.FirstAttribute(); attribute;
       attribute = attribute->Next()) {
    const std::string name = attribute->Name();
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::string message = "unknown attribute '" + name + "' ignored";
    const std::string suggestion = SuggestName(name, names);
    if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
    Warning(message);
  }
}

}  // namespace lamina::core
