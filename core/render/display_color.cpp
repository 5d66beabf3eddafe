// SPDX-License-Identifier: MIT
// Display-colour parsing and the per-kind defaults.
#include "core/render/display_color.h"

#include <sstream>

namespace lamina::core {

std::optional<Rgba> ParseColor(const std::string& text) {
  std::istringstream in(text);
  float values[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  int count = 0;
  float value = 0.0f;
  while (in >> value) {
    if (count == 4 || !(value >= 0.0f && value <= 1.0f)) return std::nullopt;
    values[count++] = value;
  }
  if (!in.eof() || count < 3) return std::nullopt;
  return Rgba(values[0], values[1], values[2], values[3]);
}

std::optional<Rgba> DisplayColor(const DisplayAttributes& display) {
  for (const char* key : {"color", "faceColor"}) {
    const auto found = display.find(key);
    if (found == display.end()) continue;
    if (std::optional<Rgba> color = ParseColor(found->second)) return color;
  }
  return std::nullopt;
}

Rgba DefaultTerrainColor() {
  return Rgba(0.62f, 0.55f, 0.46f, 1.0f);
}
Rgba DefaultObjectColor() {
  return Rgba(0.42f, 0.55f, 0.85f, 1.0f);
}
Rgba DefaultRobotColor() {
  return Rgba(0.55f, 0.56f, 0.58f, 1.0f);
}

Rgba RobotLinkColor(const RobotDesc& robot, int link) {
  Rgba color = DefaultRobotColor();
  const std::string& name = robot.links[link].name;
  for (const auto& [target, attributes] : robot.link_display) {
    if (!target.empty() && target != name) continue;
    if (std::optional<Rgba> parsed = DisplayColor(attributes)) color = *parsed;
  }
  return color;
}

}  // namespace lamina::core
