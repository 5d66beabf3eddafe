// SPDX-License-Identifier: MIT
// ElementRef: a reference to an element of a world document that survives renaming and
// reordering — the uid of a terrain, object or robot (WorldDesc's `uid`) plus a link or driver
// index for links and drivers. ElementIndex (core/model/element.h) is the position the element
// has now; a WorldDocument turns one into the other (Resolve, RefOf), and resolving a reference
// whose element was removed fails with a message instead of naming another element. Box2D gets
// the same safety from generation-checked ids; Klamp't has none (world ids shift when an object
// is added or removed). Uids are process-wide counters, never saved; a loaded world gets new ones.
#pragma once

#include <string>

#include "core/model/element.h"
#include "core/model/world_desc.h"

namespace lamina::core {

struct ElementRef {
  ElementKind kind = ElementKind::kSettings;
  ElementUid uid = 0;  ///< terrain, object or robot (links and drivers: their robot); settings: 0
  int sub = -1;        ///< link or driver index (kLink, kDriver)

  static ElementRef Settings() { return {}; }
  static ElementRef Terrain(ElementUid uid) { return {ElementKind::kTerrain, uid, -1}; }
  static ElementRef Object(ElementUid uid) { return {ElementKind::kObject, uid, -1}; }
  static ElementRef Robot(ElementUid uid) { return {ElementKind::kRobot, uid, -1}; }
  static ElementRef Link(ElementUid robot, int link) { return {ElementKind::kLink, robot, link}; }
  static ElementRef Driver(ElementUid robot, int driver) {
    return {ElementKind::kDriver, robot, driver};
  }
  bool operator==(const ElementRef&) const = default;
};

/// "settings", "object #12", "robot #3 link 4", "robot #3 driver 1": for messages.
std::string RefName(const ElementRef& ref);

/// A uid no element of this process has had (1, 2, 3, ...; never 0). Thread-safe.
ElementUid NewElementUid();

}  // namespace lamina::core
