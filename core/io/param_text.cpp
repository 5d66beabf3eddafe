// SPDX-License-Identifier: MIT
#include "core/io/param_text.h"

#include <cstdio>
#include <sstream>

#include <Eigen/Core>

#include "core/model/surface_rows.h"
#include "core/number_text.h"

namespace lamina::core {

namespace {

// the value of a single bool or choice word, when it is one
std::optional<double> NamedNumber(const ParamSpec& spec, const std::string& word) {
  const std::string lower = ToLower(word);
  if (spec.type == ParamType::kBool && (lower == "true" || lower == "false")) {
    return lower == "true" ? 1.0 : 0.0;
  }
  if (spec.type != ParamType::kChoice) return std::nullopt;
  for (size_t i = 0; i < spec.choices.size(); ++i) {
    if (lower == spec.choices[i]) return static_cast<double>(i);
  }
  return std::nullopt;
}

}  // namespace

std::vector<const ParamSpec*> SurfaceRows() {
  std::vector<const ParamSpec*> rows;
  for (const SurfaceRow& row : SurfaceMembers()) rows.push_back(row.spec);
  return rows;
}

std::vector<const ParamSpec*> BodyGeometryRows() {
  std::vector<const ParamSpec*> rows = {FindParam("padding", ElementKind::kObject),
                                        FindParam("preshrink", ElementKind::kObject)};
  for (const ParamSpec* spec : SurfaceRows()) rows.push_back(spec);
  return rows;
}

std::vector<std::string> SplitWords(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  std::string word;
  while (in >> word) words.push_back(word);
  return words;
}

std::optional<ParamValue> ParamFromWords(const ParamSpec& spec,
                                         const std::vector<std::string>& words,
                                         std::string* bad_word) {
  if (words.size() == 1) {
    if (const auto named = NamedNumber(spec, words.front())) return ParamValue{*named};
  }
  ParamValue value;
  for (const std::string& word : words) {
    double number = 0.0;
    if (!ParseDouble(word, &number)) {
      *bad_word = word;
      return std::nullopt;
    }
    value.push_back(number);
  }
  return value;
}

std::string ParamWords(const ParamSpec& spec, const ParamValue& value) {
  const bool named_choice = spec.type == ParamType::kChoice && !spec.klampt && value.size() == 1 &&
                            value[0] >= 0 && value[0] < static_cast<double>(spec.choices.size()) &&
                            value[0] == static_cast<double>(static_cast<size_t>(value[0]));
  if (named_choice) return std::string(spec.choices[static_cast<size_t>(value[0])]);
  return FormatDoubles(value.data(), static_cast<int>(value.size()));
}

std::optional<LenientValue> LenientInertia(const ParamSpec& spec, const ParamValue& value) {
  if (spec.type != ParamType::kInertia || value.size() != 9 || ParamAccepts(spec, value, 9)) {
    return std::nullopt;
  }
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> inertia(value.data());
  const double largest = inertia.cwiseAbs().maxCoeff();
  const double asymmetry = (inertia - inertia.transpose()).cwiseAbs().maxCoeff();
  if (!inertia.allFinite() || !(asymmetry <= kInertiaRoundingTolerance * largest)) {
    return std::nullopt;
  }
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> symmetric =
      0.5 * (inertia + inertia.transpose());
  LenientValue lenient{ParamValue(symmetric.data(), symmetric.data() + 9), ""};
  if (!ParamAccepts(spec, lenient.value, 9)) return std::nullopt;
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, "%.2g (%.2g", asymmetry, asymmetry / largest);
  lenient.warning = "is not symmetric: its off-diagonal pairs differ by up to " +
                    std::string(numbers) +
                    " of its largest entry, rounding in the file); (I + I^T)/2 is used";
  return lenient;
}

std::string ParamRefusal(const ParamSpec& spec, const std::string& text) {
  return ParamRule(spec) + ", got '" + text + "'";
}

std::optional<std::string> RefuseRow(std::string_view key, ElementKind kind,
                                     const ParamValue& value) {
  const ParamSpec& spec = *FindParam(key, kind);
  if (ParamAccepts(spec, value, static_cast<int>(value.size()))) return std::nullopt;
  return ParamRefusal(spec, ParamWords(spec, value));
}

}  // namespace lamina::core
