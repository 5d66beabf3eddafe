// SPDX-License-Identifier: MIT
// Body colours: the `color` / `faceColor` display attributes of a world file ("r g b [a]" in
// [0, 1]) and Lamina's default colour for each kind of body when none is given.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/model/world_desc.h"

namespace lamina::core {

using Rgba = Eigen::Vector4f;

/// "r g b" or "r g b a" with components in [0, 1]; nullopt for anything else.
std::optional<Rgba> ParseColor(const std::string& text);

/// The colour that `display` asks for (`color`, else `faceColor`); nullopt when neither is
/// present or parseable. Other attributes are ignored here (they stay in the WorldDesc).
std::optional<Rgba> DisplayColor(const DisplayAttributes& display);

/// Default colours when a world file gives none (Klamp't: brownish terrain, grey robots).
Rgba DefaultTerrainColor();
Rgba DefaultObjectColor();
Rgba DefaultRobotColor();

/// Colour of `link` of `robot`: the last `<display>` entry naming the link (or "" for every
/// link) that has a colour, else the default robot colour.
Rgba RobotLinkColor(const RobotDesc& robot, int link);

}  // namespace lamina::core
