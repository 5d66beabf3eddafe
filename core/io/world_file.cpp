// SPDX-License-Identifier: MIT
// Loading a world from any file a user may open: world XML, or a single robot, object or
// terrain file wrapped into a world.
#include "core/io/world_file.h"

#include "core/io/mesh_file.h"
#include "core/io/object_file.h"
#include "core/io/paths.h"
#include "core/io/point_cloud_file.h"
#include "core/io/robot_file.h"

namespace lamina::core {

namespace {

bool LoadSingleElement(const std::string& path, const std::string& extension, LoadContext& context,
                       WorldDesc* out) {
  const SourceLocation where{path, 0, 0};
  if (extension == "rob" || extension == "urdf") {
    RobotDesc robot;
    if (!LoadRobotFile(path, where, context, &robot)) return false;
    out->robots.push_back(std::move(robot));
    return true;
  }
  if (extension == "obj") {
    RigidObjectDesc object;
    if (!LoadRigidObjectFile(path, where, context, &object)) return false;
    out->objects.push_back(std::move(object));
    return true;
  }
  if (extension == "env" || IsMeshExtension(extension) || IsPointCloudExtension(extension)) {
    TerrainDesc terrain;
    if (!LoadTerrainFile(path, where, context, &terrain)) return false;
    out->terrains.push_back(std::move(terrain));
    return true;
  }
  context.diagnostics.Error(where,
                            "unsupported file type '." + extension +
                                "' (expected a world .xml, .rob, .urdf, .obj, .env, mesh or .pcd)");
  return false;
}

}  // namespace

bool LoadWorldFile(const std::string& path, LoadContext& context, WorldDesc* out) {
  const std::string absolute = ResolvePath(".", path);
  const std::string extension = LowerExtension(absolute);
  if (extension != "xml") {
    *out = WorldDesc();
    out->name = StemOf(absolute);
    out->source_path = absolute;
    return LoadSingleElement(absolute, extension, context, out);
  }
  std::string text;
  if (!ReadFileText(absolute, &text)) {
    context.diagnostics.Error({absolute, 0, 0}, "cannot open world file '" + absolute + "'");
    return false;
  }
  return ParseWorldXml(text, absolute, context, out);
}

}  // namespace lamina::core
