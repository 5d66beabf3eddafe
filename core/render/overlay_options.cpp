// SPDX-License-Identifier: MIT
// Parsing of the overlay list.
#include "core/render/overlay_options.h"

#include <sstream>

namespace lamina::core {

namespace {

bool* OverlayFlag(const std::string& name, OverlayOptions* options) {
  if (name == "contacts") return &options->contacts;
  if (name == "normals") return &options->normals;
  if (name == "forces") return &options->forces;
  if (name == "padding") return &options->padding;
  if (name == "com") return &options->com;
  if (name == "frames") return &options->frames;
  if (name == "bbox") return &options->bbox;
  return nullptr;
}

}  // namespace

bool ParseOverlayList(const std::string& list, OverlayOptions* options, std::string* error) {
  if (list.empty() || list == "none") return true;
  std::istringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "all") {
      std::istringstream all(kOverlayNames);
      while (std::getline(all, name, ',')) *OverlayFlag(name, options) = true;
      continue;
    }
    bool* flag = OverlayFlag(name, options);
    if (flag == nullptr) {
      *error = "unknown overlay '" + name + "' (expected a comma list of " + kOverlayNames +
               ", or all / none)";
      return false;
    }
    *flag = true;
  }
  return true;
}

}  // namespace lamina::core
