// SPDX-License-Identifier: MIT
// Klamp't `.rob` robot files: the reading pipeline (statements -> links -> geometry -> joints ->
// drivers -> mounts -> automass -> self-collision -> properties) and loading robots by
// extension.
#include <string>
#include <utility>
#include <vector>

#include "core/io/paths.h"
#include "core/io/rob_statements.h"
#include "core/io/robot_file.h"
#include "core/io/text_statements.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::core {

namespace rob {

namespace {

// robots mounted in robots mounted in ...; deeper means a loop (e.g. through symlinks)
constexpr size_t kMaxMountDepth = 16;

// the link of each `mount`, or -2 after reporting a bad reference
std::vector<int> ResolveMountLinks(const RobBuild& build) {
  std::vector<int> links;
  for (const MountStatement& mount : build.statements.mounts) {
    int link = -2;
    if (!FindLink(build.robot, mount.link, &link)) {
      build.Error(mount.line, "'mount' link '" + mount.link + "' is not a link name or index");
      link = -2;
    } else if (link < -1 || link >= build.link_count) {
      build.Error(mount.line, OutOfRangeMessage("mount", link, build.link_count));
      link = -2;
    }
    links.push_back(link);
  }
  return links;
}

// `property` lines; `controller` and `sensors` naming an .xml file hold that file's text; the
// sensors are checked now, so that their problems are reported at their file:line
void ApplyProperties(const RobBuild& build) {
  for (const PropertyStatement& property : build.statements.properties) {
    std::string value = property.value;
    SourceLocation where = build.At(property.line);
    const bool may_be_file = property.name == "controller" || property.name == "sensors";
    if (may_be_file && LowerExtension(value) == "xml" && value.find('<') == std::string::npos) {
      const std::string file = ResolvePath(DirectoryOf(build.path), value);
      if (!ReadFileText(file, &value)) {
        build.Error(property.line, "cannot read '" + property.name + "' file '" + file + "'");
        continue;
      }
      where = {file, 1, 0};
    }
    build.robot.properties[property.name] = value;
    if (property.name == "sensors") {
      ParseSensorsXml(value, build.robot, where, &build.context.diagnostics);
    }
  }
}

void AssembleRobot(RobBuild& build) {
  const RobStatements& s = build.statements;
  BuildLinks(build);
  RobotDesc& robot = build.robot;
  robot.config = VecX::Zero(build.link_count);
  for (int i = 0; i < build.link_count; ++i) robot.config[i] = robot.links[i].q_initial;
  robot.velocity = VecX::Zero(build.link_count);
  LoadLinkGeometry(build);
  ApplyAutotorque(build);
  BuildJoints(build);
  BuildDrivers(build);
  const std::vector<int> mount_links = ResolveMountLinks(build);
  MountGeometry(build, mount_links);
  ApplyAutomass(build);
  // pairs among this file's own links first, then the ones naming mounted links
  Diagnostics& diagnostics = build.context.diagnostics;
  const auto self = ResolvePairs(robot, s.self_collision, "selfcollision", false, build.path,
                                 diagnostics, &robot.self_collision);
  const auto no_self = ResolvePairs(robot, s.no_self_collision, "noselfcollision", false,
                                    build.path, diagnostics, &robot.no_self_collision);
  MountRobots(build, mount_links);
  ResolvePairs(robot, self, "selfcollision", true, build.path, diagnostics, &robot.self_collision);
  ResolvePairs(robot, no_self, "noselfcollision", true, build.path, diagnostics,
               &robot.no_self_collision);
  ApplyProperties(build);
}

}  // namespace

bool ParseRobNested(const std::string& text, const std::string& path, LoadContext& context,
                    RobotFileStack& stack, RobotDesc* out) {
  const int errors_before = context.diagnostics.error_count();
  RobStatements statements;
  ReadRobStatements(text, path, context.diagnostics, &statements);
  RobotDesc robot;
  robot.name = StemOf(path);
  robot.source_path = path;
  const int link_count = VoteLinkCount(statements, path, context.diagnostics);
  if (link_count > 0) {
    stack.push_back(ResolvePath("", path));
    RobBuild build{statements, path, context, stack, robot, link_count};
    AssembleRobot(build);
    stack.pop_back();
  }
  *out = std::move(robot);
  return context.diagnostics.error_count() == errors_before;
}

bool LoadRobotFileNested(const std::string& path, const SourceLocation& given_where,
                         LoadContext& context, RobotFileStack& stack, RobotDesc* out) {
  const SourceLocation where = given_where.file.empty() ? SourceLocation{path, 0, 0} : given_where;
  const std::string extension = LowerExtension(path);
  if (stack.size() >= kMaxMountDepth) {
    context.diagnostics.Error(where, "robot mounts nest more than " +
                                         std::to_string(kMaxMountDepth) + " deep at '" + path +
                                         "'");
    return false;
  }
  if (extension != "rob" && extension != "urdf") {
    context.diagnostics.Error(
        where, "unsupported robot file '" + path + "': expected a .rob or .urdf file");
    return false;
  }
  std::string text;
  if (!ReadFileText(path, &text)) {
    context.diagnostics.Error(where, "cannot open robot file '" + path + "'");
    return false;
  }
  if (extension == "urdf") return ParseUrdfNested(text, path, context, stack, out);
  return ParseRobNested(text, path, context, stack, out);
}

}  // namespace rob

bool LoadRobotFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                   RobotDesc* out) {
  rob::RobotFileStack stack;
  return rob::LoadRobotFileNested(path, where, context, stack, out);
}

bool ParseRob(const std::string& text, const std::string& path, LoadContext& context,
              RobotDesc* out) {
  rob::RobotFileStack stack;
  return rob::ParseRobNested(text, path, context, stack, out);
}

}  // namespace lamina::core
