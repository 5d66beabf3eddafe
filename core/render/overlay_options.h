// SPDX-License-Identifier: MIT
// What a renderer draws besides the bodies: the overlays a user switches on, their scales, and
// the selected body. Parsed from a comma list such as "contacts,normals,forces,padding".
#pragma once

#include <string>

namespace lamina::core {

struct OverlayOptions {
  bool contacts = false;  ///< contact points (yellow; red where the geometries interpenetrate)
  bool normals = false;   ///< contact normals, normal_length long
  bool forces = false;    ///< contact forces, force_scale m per N
  bool padding = false;   ///< each body grown by its padding, translucent (the boundary layer)
  bool com = false;       ///< centres of mass of objects and links
  bool frames = false;    ///< object and link frames (x red, y green, z blue)
  bool bbox = false;      ///< oriented bounding boxes of every body
  bool joints = false;    ///< world-level joints: hinge axes, slider directions, fixed links
  bool sensors = false;   ///< robot sensors: laser rays, camera frusta, contact patches, forces

  double normal_length = 0.05;  ///< m (Klamp't SimTest: 0.05)
  double force_scale = 0.01;    ///< m per N (Klamp't SimTest: 0.01)
  /// Klamp't world id of the highlighted body (a robot id highlights the whole robot); -1 none.
  int selected_id = -1;

  bool operator==(const OverlayOptions&) const = default;
};

/// One overlay a user switches: its name (in --overlay lists and on the viewer's panel) and its
/// flag. Every consumer walks this list; none spells the names again.
struct OverlayToggle {
  const char* name;
  bool OverlayOptions::*flag;
  const char* help;
};

inline constexpr OverlayToggle kOverlayToggles[] = {
    {"contacts", &OverlayOptions::contacts,
     "contact points (yellow; red where the geometries interpenetrate)"},
    {"normals", &OverlayOptions::normals, "contact normals"},
    {"forces", &OverlayOptions::forces, "contact forces"},
    {"padding", &OverlayOptions::padding,
     "each body grown by its padding, translucent (the boundary layer)"},
    {"com", &OverlayOptions::com, "centres of mass of objects and links"},
    {"frames", &OverlayOptions::frames, "object and link frames (x red, y green, z blue)"},
    {"bbox", &OverlayOptions::bbox, "oriented bounding boxes of every body"},
    {"joints", &OverlayOptions::joints,
     "world-level joints (orange): hinge axes through their points, slider directions"},
    {"sensors", &OverlayOptions::sensors,
     "robot sensors: laser rays (green hits), camera frusta, contact patches (red in contact), "
     "measured forces, torques and accelerations"},
};

/// The toggles' names as a comma list ("contacts,normals,...").
std::string OverlayNames();

/// Turns on the overlays named in `list` ("contacts,padding"; "all"; "" or "none" for none).
/// False with `error` naming the unknown entry otherwise.
bool ParseOverlayList(const std::string& list, OverlayOptions* options, std::string* error);

}  // namespace lamina::core
