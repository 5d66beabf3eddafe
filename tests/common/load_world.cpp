// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "core/io/robot_file.h"
#include "core/io/world_file.h"
#include "tests/common/test_support.h"

namespace lamina::test {

void LoadWorld(const std::string& path, LoadedWorld* out) {
  core::LoadContext context{out->diagnostics, out->meshes};
  out->ok = core::LoadWorldFile(path, context, &out->world);
}

core::WorldDesc LoadShippedWorld(const std::string& relative) {
  LoadedWorld loaded;
  LoadWorld(WorldsPath(relative), &loaded);
  EXPECT_TRUE(loaded.ok) << relative << ": " << loaded.diagnostics.FormatAll();
  return loaded.world;
}

std::unique_ptr<LoadedRobot> LoadRobot(const std::string& path) {
  auto loaded = std::make_unique<LoadedRobot>();
  loaded->ok = core::LoadRobotFile(path, {}, loaded->context, &loaded->robot);
  return loaded;
}

}  // namespace lamina::test
