// SPDX-License-Identifier: MIT
// Addressing the elements of a WorldDesc by position: the global settings, a terrain, a rigid
// object, a robot, one of its links or one of its drivers. Indices are what the description holds
// now; references that survive reordering and renaming are core/edit's ElementRef (an element's
// uid plus a link or driver index).
#pragma once

#include <optional>
#include <string>

#include "core/model/world_desc.h"

namespace lamina::core {

enum class ElementKind { kSettings, kTerrain, kObject, kRobot, kLink, kDriver };

/// Bit of `kind` in ParamSpec::kinds.
constexpr unsigned KindBit(ElementKind kind) {
  return 1u << static_cast<unsigned>(kind);
}

/// An element of a WorldDesc by index.
struct ElementIndex {
  ElementKind kind = ElementKind::kSettings;
  int index = -1;  ///< terrain, object or robot index (settings: -1)
  int sub = -1;    ///< link or driver index within robot `index`

  static ElementIndex Settings() { return {}; }
  static ElementIndex Terrain(int i) { return {ElementKind::kTerrain, i, -1}; }
  static ElementIndex Object(int i) { return {ElementKind::kObject, i, -1}; }
  static ElementIndex Robot(int r) { return {ElementKind::kRobot, r, -1}; }
  static ElementIndex Link(int r, int link) { return {ElementKind::kLink, r, link}; }
  static ElementIndex Driver(int r, int driver) { return {ElementKind::kDriver, r, driver}; }
  bool operator==(const ElementIndex&) const = default;
};

/// "settings", "terrains[0]", "objects[1]", "robots[0]", "robots[0].links[3]",
/// "robots[0].drivers[2]": the access path of the element (by index).
std::string ElementPath(const ElementIndex& element);

/// None when `element` exists in `world`; otherwise what is wrong, naming the path
/// ("robots[3]: the world has 1 robot").
std::optional<std::string> CheckElement(const WorldDesc& world, const ElementIndex& element);

/// The element of a Klamp't world id: a terrain, object, robot or robot link; nullopt for an id
/// out of range.
std::optional<ElementIndex> ElementOfWorldId(const WorldDesc& world, int id);
/// The world id of a terrain, object, robot or link element; -1 for settings and drivers.
int WorldIdOfElement(const WorldDesc& world, const ElementIndex& element);

/// The simulation parameters (padding, preshrink, surface) of a terrain, object or link; null
/// for other kinds or a missing element.
const BodySimParams* BodyParamsOf(const WorldDesc& world, const ElementIndex& element);
BodySimParams* BodyParamsOf(WorldDesc* world, const ElementIndex& element);

}  // namespace lamina::core
