// SPDX-License-Identifier: MIT
// Scene extraction: a WorldDesc (what the bodies are) drawn at a WorldPoses (where they are now)
// plus overlay options and contact markers -> a RenderScene. The description's own poses and
// configurations are not read (unless `poses` lacks an entry); every pose-dependent thing (draw
// items, bounds and so camera framing and picking, padding shells, frames, centres of mass,
// boxes) follows `poses`. Meshes come from a RenderMeshCache that the caller keeps across frames.
#pragma once

#include <vector>

#include "core/model/world_desc.h"
#include "core/render/contact_markers.h"
#include "core/render/overlay_options.h"
#include "core/render/render_mesh_cache.h"
#include "core/render/render_scene.h"
#include "core/render/world_poses.h"

namespace lamina::core {

/// Fills `scene` (cleared first) with every terrain, object and robot link of `world`, objects
/// at `poses.objects` and robots at the forward kinematics of `poses.robots`, and the overlays
/// `options` turns on. `contacts` feeds the contact overlays. An object without an entry in
/// `poses` (an element added since the poses were taken) is drawn at its description pose, a
/// robot whose configuration is missing or has the wrong size at its DisplayConfiguration.
void ExtractScene(const WorldDesc& world, const WorldPoses& poses, const OverlayOptions& options,
                  const std::vector<ContactMarker>& contacts, RenderMeshCache* cache,
                  RenderScene* scene);

}  // namespace lamina::core
