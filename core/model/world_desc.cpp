// SPDX-License-Identifier: MIT
#include "core/model/world_desc.h"

#include <algorithm>
#include <set>

namespace lamina::core {

bool LinkDesc::has_geometry() const {
  return std::any_of(geometry.begin(), geometry.end(),
                     [](const GeometryDesc& g) { return !g.empty(); });
}

double RobotDesc::TotalMass() const {
  double total = 0.0;
  for (const LinkDesc& link : links) total += link.mass;
  return total;
}

VecX RobotDesc::InitialConfig() const {
  if (config.size() == dof() && config.allFinite()) return config;
  return VecX::Zero(dof());
}

VecX RobotDesc::InitialVelocity() const {
  if (velocity.size() == dof() && velocity.allFinite()) return velocity;
  return VecX::Zero(dof());
}

std::vector<std::pair<int, int>> RobotDesc::SelfCollisionPairs() const {
  const auto ordered = [](std::pair<int, int> p) {
    return p.first < p.second ? p : std::make_pair(p.second, p.first);
  };
  std::set<std::pair<int, int>> pairs;
  if (!self_collision.empty()) {
    for (const auto& p : self_collision) {
      if (p.first != p.second) pairs.insert(ordered(p));
    }
  } else {
    const int n = dof();
    for (int i = 0; i < n; ++i) {
      if (!links[i].has_geometry()) continue;
      for (int j = i + 1; j < n; ++j) {
        if (!links[j].has_geometry()) continue;
        if (links[j].parent == i || links[i].parent == j) continue;
        pairs.insert({i, j});
      }
    }
  }
  for (const auto& p : no_self_collision) pairs.erase(ordered(p));
  return {pairs.begin(), pairs.end()};
}

int WorldDesc::TerrainId(int terrain) const {
  return terrain;
}

int WorldDesc::ObjectId(int object) const {
  return static_cast<int>(terrains.size()) + object;
}

int WorldDesc::RobotId(int robot) const {
  int id = static_cast<int>(terrains.size() + objects.size());
  for (int r = 0; r < robot; ++r) id += robots[r].dof() + 1;
  return id;
}

int WorldDesc::RobotLinkId(int robot, int link) const {
  return RobotId(robot) + 1 + link;
}

int WorldDesc::IdCount() const {
  return RobotId(static_cast<int>(robots.size()));
}

WorldId WorldDesc::Resolve(int id) const {
  WorldId out;
  if (id < 0) return out;
  const int terrain_count = static_cast<int>(terrains.size());
  const int object_count = static_cast<int>(objects.size());
  if (id < terrain_count) return {WorldId::Kind::kTerrain, id, -1};
  if (id < terrain_count + object_count) {
    return {WorldId::Kind::kRigidObject, id - terrain_count, -1};
  }
  int next = terrain_count + object_count;
  for (int r = 0; r < static_cast<int>(robots.size()); ++r) {
    if (id == next) return {WorldId::Kind::kRobot, r, -1};
    const int links = robots[r].dof();
    if (id <= next + links) return {WorldId::Kind::kRobotLink, r, id - next - 1};
    next += links + 1;
  }
  return out;
}

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kNormal:
      return "normal";
    case JointType::kSpin:
      return "spin";
    case JointType::kWeld:
      return "weld";
    case JointType::kFloating:
      return "floating";
    case JointType::kFloatingPlanar:
      return "floatingplanar";
    case JointType::kBallAndSocket:
      return "ballandsocket";
  }
  return "normal";
}

const char* PreshrinkName(Preshrink preshrink) {
  switch (preshrink) {
    case Preshrink::kNone:
      return "none";
    case Preshrink::kCopy:
      return "copy";
    case Preshrink::kInPlace:
      return "in-place";
  }
  return "none";
}

BodySimParams DefaultTerrainSimParams() {
  BodySimParams params;
  params.padding = 0.0;
  params.surface = {0.1, 0.5, kInf, kInf};
  return params;
}

BodySimParams DefaultObjectSimParams() {
  BodySimParams params;
  params.surface = {0.5, 0.5, kInf, kInf};
  return params;
}

BodySimParams DefaultLinkSimParams() {
  BodySimParams params;
  params.surface = {0.1, 1.0, kInf, kInf};
  return params;
}

const char* WorldJointTypeName(WorldJointType type) {
  switch (type) {
    case WorldJointType::kFixed:
      return "fixed";
    case WorldJointType::kHinge:
      return "hinge";
    case WorldJointType::kSlider:
      return "slider";
  }
  return "?";
}

int JointHoldingObject(const WorldDesc& world, int object) {
  for (size_t j = 0; j < world.joints.size(); ++j) {
    for (const WorldJointBody& body : world.joints[j].bodies) {
      if (body.kind == WorldId::Kind::kRigidObject && body.index == object) {
        return static_cast<int>(j);
      }
    }
  }
  return -1;
}

void RenumberJointObjects(WorldDesc* world, const std::vector<int>& new_index) {
  for (WorldJointDesc& joint : world->joints) {
    for (WorldJointBody& body : joint.bodies) {
      if (body.kind == WorldId::Kind::kRigidObject) body.index = new_index.at(body.index);
    }
  }
}

}  // namespace lamina::core
