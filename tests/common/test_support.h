// SPDX-License-Identifier: MIT
// Helpers shared by the tests: data paths, scratch files, loading with collected diagnostics.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/io/load_context.h"
#include "core/model/world_desc.h"

namespace lamina::test {

// Names several test files share. Each test area compiles in unity batches (several files as one
// translation unit, LAMINA_UNITY_TESTS), so a name at a test file's namespace scope, anonymous
// namespace included, is defined in one file only; what more than one file needs lives here.

/// The gravity of the scene tests' worlds, m/s² (downwards along z).
inline constexpr double kGravity = 9.8;
/// Side of the scene tests' 1 kg boxes, m.
inline constexpr double kBoxSide = 0.1;
/// `position` with `rotation`, as a pose.
core::Pose PoseAt(const core::Vec3& position, const core::Mat3& rotation = core::Mat3::Identity());
/// The vector of `values`.
core::VecX Vec(std::initializer_list<double> values);
/// The volume a closed mesh encloses, positive when its triangles wind outwards, m³.
double SignedVolume(const core::TriangleMesh& mesh);

/// Absolute path of `relative` under tests/data.
std::string DataPath(const std::string& relative);
/// Absolute path of `relative` under worlds/.
std::string WorldsPath(const std::string& relative);
/// This test's own directory under the system temp, emptied at its first use in the test.
std::string ScratchDir();
/// The bytes of the file at `path` ("" when it cannot be read).
std::string ReadFile(const std::string& path);
/// Writes `text` to `name` inside ScratchDir() (subdirectories created) and returns its path.
std::string WriteScratchFile(const std::string& name, const std::string& text);

/// A world loaded with its diagnostics kept for assertions.
struct LoadedWorld {
  core::WorldDesc world;
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  bool ok = false;
};
/// Loads the world file at `path` (absolute).
void LoadWorld(const std::string& path, LoadedWorld* out);
/// The world file `relative` under worlds/ (e.g. "accuracy/chain.xml"); a test failure with the
/// diagnostics when it does not load.
core::WorldDesc LoadShippedWorld(const std::string& relative);

/// A robot loaded with its diagnostics kept for assertions.
struct LoadedRobot {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::RobotDesc robot;
  bool ok = false;
};
/// Loads the robot file at `path` (.rob or .urdf).
std::unique_ptr<LoadedRobot> LoadRobot(const std::string& path);

/// Every undirected edge used by exactly two triangles, once in each direction (a closed,
/// consistently oriented mesh).
bool IsClosedAndConsistent(const core::TriangleMesh& mesh);
/// The robot's link names and parent indices, in link order.
std::vector<std::string> LinkNames(const core::RobotDesc& robot);
std::vector<int> Parents(const core::RobotDesc& robot);

/// What a run of `lamina-headless` printed and returned.
struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};
/// Runs the built `lamina-headless` with `arguments` (a shell word list).
CommandResult RunHeadless(const std::string& arguments);

/// The same description, field for field (CompareWorlds at tolerance 0), and the same uids of
/// terrains, objects and robots in the same places.
void ExpectSameWorld(const core::WorldDesc& a, const core::WorldDesc& b);

}  // namespace lamina::test
