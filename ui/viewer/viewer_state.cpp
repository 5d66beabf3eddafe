// SPDX-License-Identifier: MIT
#include "ui/viewer/viewer_state.h"

#include <sstream>

namespace lamina::ui {

namespace {

std::string PanelNames() {
  std::string names;
  for (const PanelEntry& panel : kPanels)
    names += std::string(names.empty() ? "" : ", ") + panel.name;
  return names + ", all, none";
}

}  // namespace

bool ParsePanelList(const std::string& text, PanelVisibility* panels, std::string* error) {
  PanelVisibility shown;
  for (const PanelEntry& panel : kPanels) shown.*panel.shown = false;
  std::stringstream list(text);
  for (std::string name; std::getline(list, name, ',');) {
    if (name == "none") continue;
    bool known = false;
    for (const PanelEntry& panel : kPanels) {
      if (name == panel.name || name == "all") {
        shown.*panel.shown = true;
        known = true;
      }
    }
    if (!known) {
      *error = "--panels: no panel is called '" + name + "' (panels: " + PanelNames() + ")";
      return false;
    }
  }
  *panels = shown;
  return true;
}

}  // namespace lamina::ui
