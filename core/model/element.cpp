// SPDX-License-Identifier: MIT
#include "core/model/element.h"

namespace lamina::core {

namespace {

std::string Count(size_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

std::optional<std::string> CheckIndex(const std::string& path, int index, size_t count,
                                      const char* what, const char* singular, const char* plural) {
  if (index >= 0 && static_cast<size_t>(index) < count) return std::nullopt;
  return path + ": " + what + " has " + Count(count, singular, plural);
}

}  // namespace

std::string ElementPath(const ElementIndex& element) {
  const std::string index = "[" + std::to_string(element.index) + "]";
  const std::string sub = "[" + std::to_string(element.sub) + "]";
  switch (element.kind) {
    case ElementKind::kSettings:
      return "settings";
    case ElementKind::kTerrain:
      return "terrains" + index;
    case ElementKind::kObject:
      return "objects" + index;
    case ElementKind::kRobot:
      return "robots" + index;
    case ElementKind::kLink:
      return "robots" + index + ".links" + sub;
    case ElementKind::kDriver:
      return "robots" + index + ".drivers" + sub;
  }
  return "settings";
}

std::optional<std::string> CheckElement(const WorldDesc& world, const ElementIndex& element) {
  const std::string path = ElementPath(element);
  switch (element.kind) {
    case ElementKind::kSettings:
      return std::nullopt;
    case ElementKind::kTerrain:
      return CheckIndex(path, element.index, world.terrains.size(), "the world", "terrain",
                        "terrains");
    case ElementKind::kObject:
      return CheckIndex(path, element.index, world.objects.size(), "the world", "object",
                        "objects");
    default:
      break;
  }
  const std::string robot_path = "robots[" + std::to_string(element.index) + "]";
  if (auto error = CheckIndex(robot_path, element.index, world.robots.size(), "the world", "robot",
                              "robots")) {
    return error;
  }
  const RobotDesc& robot = world.robots[element.index];
  const std::string robot_name = "robot '" + robot.name + "'";
  if (element.kind == ElementKind::kLink) {
    return CheckIndex(path, element.sub, robot.links.size(), robot_name.c_str(), "link", "links");
  }
  if (element.kind == ElementKind::kDriver) {
    return CheckIndex(path, element.sub, robot.drivers.size(), robot_name.c_str(), "driver",
                      "drivers");
  }
  return std::nullopt;
}

std::optional<ElementIndex> ElementOfWorldId(const WorldDesc& world, int id) {
  const WorldId resolved = world.Resolve(id);
  switch (resolved.kind) {
    case WorldId::Kind::kTerrain:
      return ElementIndex::Terrain(resolved.index);
    case WorldId::Kind::kRigidObject:
      return ElementIndex::Object(resolved.index);
    case WorldId::Kind::kRobot:
      return ElementIndex::Robot(resolved.index);
    case WorldId::Kind::kRobotLink:
      return ElementIndex::Link(resolved.index, resolved.link);
    case WorldId::Kind::kInvalid:
      break;
  }
  return std::nullopt;
}

int WorldIdOfElement(const WorldDesc& world, const ElementIndex& element) {
  switch (element.kind) {
    case ElementKind::kTerrain:
      return world.TerrainId(element.index);
    case ElementKind::kObject:
      return world.ObjectId(element.index);
    case ElementKind::kRobot:
      return world.RobotId(element.index);
    case ElementKind::kLink:
      return world.RobotLinkId(element.index, element.sub);
    default:
      return -1;
  }
}

const BodySimParams* BodyParamsOf(const WorldDesc& world, const ElementIndex& element) {
  return BodyParamsOf(const_cast<WorldDesc*>(&world), element);
}

BodySimParams* BodyParamsOf(WorldDesc* world, const ElementIndex& element) {
  if (CheckElement(*world, element)) return nullptr;
  switch (element.kind) {
    case ElementKind::kTerrain:
      return &world->terrains[element.index].sim;
    case ElementKind::kObject:
      return &world->objects[element.index].sim;
    case ElementKind::kLink:
      return &world->robots[element.index].links[element.sub].sim;
    default:
      return nullptr;
  }
}

}  // namespace lamina::core
