// SPDX-License-Identifier: MIT
// Parsing of the overlay list.
#include "core/render/overlay_options.h"

#include <sstream>

namespace lamina::core {

namespace {

bool* OverlayFlag(const std::string& name, OverlayOptions* options) {
  for (const OverlayToggle& toggle : kOverlayToggles) {
    if (name == toggle.name) return &(options->*toggle.flag);
  }
  return nullptr;
}

}  // namespace

std::string OverlayNames() {
  std::string names;
  for (const OverlayToggle& toggle : kOverlayToggles) {
    if (!names.empty()) names += ',';
    names += toggle.name;
  }
  return names;
}

bool ParseOverlayList(const std::string& list, OverlayOptions* options, std::string* error) {
  if (list.empty() || list == "none") return true;
  std::istringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "all") {
      for (const OverlayToggle& toggle : kOverlayToggles) options->*toggle.flag = true;
      continue;
    }
    bool* flag = OverlayFlag(name, options);
    if (flag == nullptr) {
      *error = "unknown overlay '" + name + "' (expected a comma list of " + OverlayNames() +
               ", or all / none)";
      return false;
    }
    *flag = true;
  }
  return true;
}

}  // namespace lamina::core
