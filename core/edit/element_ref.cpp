// SPDX-License-Identifier: MIT
#include "core/edit/element_ref.h"

#include <atomic>

namespace lamina::core {

std::string RefName(const ElementRef& ref) {
  const std::string uid = " #" + std::to_string(ref.uid);
  const std::string sub = " " + std::to_string(ref.sub);
  switch (ref.kind) {
    case ElementKind::kSettings:
      return "settings";
    case ElementKind::kTerrain:
      return "terrain" + uid;
    case ElementKind::kObject:
      return "object" + uid;
    case ElementKind::kRobot:
      return "robot" + uid;
    case ElementKind::kLink:
      return "robot" + uid + " link" + sub;
    case ElementKind::kDriver:
      return "robot" + uid + " driver" + sub;
  }
  return "settings";
}

ElementUid NewElementUid() {
  static std::atomic<ElementUid> next{1};
  return next.fetch_add(1);
}

}  // namespace lamina::core
