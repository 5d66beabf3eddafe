// SPDX-License-Identifier: MIT
#include "core/suggest.h"

#include <algorithm>

#include "core/number_text.h"

namespace lamina::core {

namespace {

// Levenshtein distance: insertions, deletions and substitutions of single characters
int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace

std::string SuggestName(const std::string& name, const std::vector<std::string>& known) {
  const std::string lower = ToLower(name);
  std::string best;
  // long names tolerate one more edit ("translate" -> "translation")
  int best_distance = lower.size() >= 8 ? 4 : 3;
  for (const std::string& candidate : known) {
    const std::string candidate_lower = ToLower(candidate);
    if (candidate_lower == "k" + lower) return candidate;
    const int distance = EditDistance(lower, candidate_lower);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

}  // namespace lamina::core
