// SPDX-License-Identifier: MIT
// Scene extraction: a WorldDesc (poses and robot configurations as they are now) plus overlay
// options and contact markers -> a RenderScene. Meshes come from a RenderMeshCache that the
// caller keeps across frames.
#pragma once

#include <vector>

#include "core/model/world_desc.h"
#include "core/render/contact_markers.h"
#include "core/render/overlay_options.h"
#include "core/render/render_mesh_cache.h"
#include "core/render/render_scene.h"

namespace lamina::core {

/// Fills `scene` (cleared first) with every terrain, object and robot link of `world`, drawn
/// with robots at `robot.config` (the links' initial values when config has the wrong size),
/// and the overlays `options` turns on. `contacts` feeds the contact overlays.
void ExtractScene(const WorldDesc& world, const OverlayOptions& options,
                  const std::vector<ContactMarker>& contacts, RenderMeshCache* cache,
                  RenderScene* scene);

/// The configuration drawn for `robot`: its config, or the links' q_initial when the config
/// does not have one entry per link.
VecX DisplayConfiguration(const RobotDesc& robot);

}  // namespace lamina::core
