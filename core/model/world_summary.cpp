// SPDX-License-Identifier: MIT
#include "core/model/world_summary.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace lamina::core {

namespace {

using nlohmann::ordered_json;

ordered_json Number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

ordered_json Vector(const Vec3& v) {
  return ordered_json::array({v.x(), v.y(), v.z()});
}

ordered_json SimParamsJson(const BodySimParams& params) {
  return {{"padding", params.padding},
          {"preshrink", PreshrinkName(params.preshrink)},
          {"kRestitution", Number(params.surface.restitution)},
          {"kFriction", Number(params.surface.friction)},
          {"kStiffness", Number(params.surface.stiffness)},
          {"kDamping", Number(params.surface.damping)}};
}

ordered_json TerrainJson(const WorldDesc& world, int index) {
  const TerrainDesc& terrain = world.terrains[index];
  return {{"id", world.TerrainId(index)},
          {"name", terrain.name},
          {"file", terrain.geometry.path},
          {"triangles", terrain.geometry.triangle_count()},
          {"simulation", SimParamsJson(terrain.sim)}};
}

ordered_json ObjectJson(const WorldDesc& world, int index) {
  const RigidObjectDesc& object = world.objects[index];
  return {{"id", world.ObjectId(index)},
          {"name", object.name},
          {"file", object.geometry.path},
          {"triangles", object.geometry.triangle_count()},
          {"mass", object.mass},
          {"com", Vector(object.com)},
          {"inertia_diagonal", Vector(object.inertia.diagonal())},
          {"position", Vector(object.pose.translation())},
          {"simulation", SimParamsJson(object.sim)},
          {"initial_velocity",
           {{"linear", Vector(object.initial_velocity.linear)},
            {"angular", Vector(object.initial_velocity.angular)}}}};
}

ordered_json RobotJson(const WorldDesc& world, int index) {
  const RobotDesc& robot = world.robots[index];
  std::map<std::string, int> joint_counts;
  for (const JointDesc& joint : robot.joints) ++joint_counts[JointTypeName(joint.type)];
  int links_with_geometry = 0;
  for (const LinkDesc& link : robot.links) links_with_geometry += link.has_geometry() ? 1 : 0;
  ordered_json links = ordered_json::array();
  for (const LinkDesc& link : robot.links) {
    links.push_back({{"name", link.name},
                     {"parent", link.parent},
                     {"mass", link.mass},
                     {"simulation", SimParamsJson(link.sim)}});
  }
  return {{"id", world.RobotId(index)},
          {"name", robot.name},
          {"file", robot.source_path},
          {"dofs", robot.dof()},
          {"links", robot.dof()},
          {"links_with_geometry", links_with_geometry},
          {"drivers", robot.drivers.size()},
          {"joints", joint_counts},
          {"total_mass", robot.TotalMass()},
          {"triangles", RobotTriangleCount(robot)},
          {"self_collision_pairs", robot.SelfCollisionPairs().size()},
          {"link_details", links}};
}

ordered_json SettingsJson(const SimSettings& s) {
  return {{"timestep", s.timestep},
          {"gravity", Vector(s.gravity)},
          {"ERP", s.erp},
          {"CFM", s.cfm},
          {"maxContacts", s.max_contacts},
          {"adaptiveTimeStepping", s.adaptive_time_stepping},
          {"rigidObjectCollisions", s.rigid_object_collisions},
          {"robotSelfCollisions", s.robot_self_collisions},
          {"robotRobotCollisions", s.robot_robot_collisions}};
}

// six significant digits for people; the JSON keeps full precision
std::string Text(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

std::string SimParamsText(const BodySimParams& p) {
  return "padding " + Text(p.padding) + " m, preshrink " + PreshrinkName(p.preshrink) +
         ", kRestitution " + Text(p.surface.restitution) + ", kFriction " +
         Text(p.surface.friction) + ", kStiffness " + Text(p.surface.stiffness) + ", kDamping " +
         Text(p.surface.damping);
}

}  // namespace

int RobotTriangleCount(const RobotDesc& robot) {
  int triangles = 0;
  for (const LinkDesc& link : robot.links) {
    for (const GeometryDesc& geometry : link.geometry) triangles += geometry.triangle_count();
  }
  return triangles;
}

std::string WorldSummaryJson(const WorldDesc& world) {
  ordered_json out = {{"name", world.name}, {"file", world.source_path}};
  out["terrains"] = ordered_json::array();
  for (int i = 0; i < static_cast<int>(world.terrains.size()); ++i) {
    out["terrains"].push_back(TerrainJson(world, i));
  }
  out["objects"] = ordered_json::array();
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    out["objects"].push_back(ObjectJson(world, i));
  }
  out["robots"] = ordered_json::array();
  for (int i = 0; i < static_cast<int>(world.robots.size()); ++i) {
    out["robots"].push_back(RobotJson(world, i));
  }
  out["simulation"] = SettingsJson(world.settings);
  return out.dump(2) + "\n";
}

std::string WorldSummaryText(const WorldDesc& world) {
  std::ostringstream out;
  out << "world " << world.name << " (" << world.source_path << ")\n";
  for (int i = 0; i < static_cast<int>(world.terrains.size()); ++i) {
    const TerrainDesc& t = world.terrains[i];
    out << "terrain " << world.TerrainId(i) << " '" << t.name
        << "': " << t.geometry.triangle_count() << " triangles\n  " << SimParamsText(t.sim) << "\n";
  }
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    const RigidObjectDesc& o = world.objects[i];
    const Vec3 p = o.pose.translation();
    out << "object " << world.ObjectId(i) << " '" << o.name << "': mass " << Text(o.mass) << " kg, "
        << o.geometry.triangle_count() << " triangles, at (" << Text(p.x()) << ", " << Text(p.y())
        << ", " << Text(p.z()) << ")\n  " << SimParamsText(o.sim) << "\n";
  }
  for (int i = 0; i < static_cast<int>(world.robots.size()); ++i) {
    const RobotDesc& r = world.robots[i];
    out << "robot " << world.RobotId(i) << " '" << r.name << "': " << r.dof() << " DOFs ("
        << r.dof() << " links), " << r.drivers.size() << " drivers, total mass "
        << Text(r.TotalMass()) << " kg, " << RobotTriangleCount(r) << " triangles\n";
    if (r.dof() > 0) out << "  link 0: " << SimParamsText(r.links[0].sim) << "\n";
  }
  const SimSettings& s = world.settings;
  out << "simulation: timestep " << Text(s.timestep) << " s, gravity (" << Text(s.gravity.x())
      << ", " << Text(s.gravity.y()) << ", " << Text(s.gravity.z()) << "), ERP " << Text(s.erp)
      << ", CFM " << Text(s.cfm) << ", maxContacts " << s.max_contacts << ", adaptive "
      << (s.adaptive_time_stepping ? "on" : "off") << ", object collisions "
      << (s.rigid_object_collisions ? "on" : "off") << ", self collisions "
      << (s.robot_self_collisions ? "on" : "off") << ", robot-robot collisions "
      << (s.robot_robot_collisions ? "on" : "off") << "\n";
  return out.str();
}

}  // namespace lamina::core
