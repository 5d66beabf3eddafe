// SPDX-License-Identifier: MIT
#include "core/model/world_summary.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/json_values.h"
#include "core/model/element.h"
#include "core/model/params.h"

namespace lamina::core {

namespace {

using nlohmann::ordered_json;

ordered_json JsonLimit(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

// a row's value: a bool, a choice's name, an integer, a number or an array of numbers
ordered_json RowJson(const ParamSpec& spec, const ParamValue& value) {
  if (value.size() != 1 || spec.type == ParamType::kVector) {
    ordered_json array = ordered_json::array();
    for (double x : value) array.push_back(JsonLimit(x));
    return array;
  }
  switch (spec.type) {
    case ParamType::kBool:
      return value[0] != 0.0;
    case ParamType::kChoice:
      return FormatParamValue(spec, value);
    case ParamType::kInteger:
      return static_cast<long long>(value[0]);
    default:
      return JsonLimit(value[0]);
  }
}

// the rows in `rows` of `element`, keyed by the row key
ordered_json RowsJson(const WorldDesc& world, const ElementIndex& element,
                      const std::vector<const ParamSpec*>& rows) {
  ordered_json out = ordered_json::object();
  for (const ParamSpec* spec : rows)
    out[std::string(spec->key)] = RowJson(*spec, spec->get(world, element));
  return out;
}

// the rows of elements of `kind` that are (or are not) a body's padding and surface rows
std::vector<const ParamSpec*> Rows(ElementKind kind, bool body) {
  std::vector<const ParamSpec*> rows;
  for (const ParamSpec* spec : ParamsOf(kind)) {
    if (IsBodyParam(*spec) == body) rows.push_back(spec);
  }
  return rows;
}

ordered_json TerrainJson(const WorldDesc& world, int index) {
  const TerrainDesc& terrain = world.terrains[index];
  return {{"id", world.TerrainId(index)},
          {"name", terrain.name},
          {"file", terrain.geometry.path},
          {"triangles", terrain.geometry.triangle_count()},
          {"points", terrain.geometry.point_count()},
          {"simulation",
           RowsJson(world, ElementIndex::Terrain(index), Rows(ElementKind::kTerrain, true))}};
}

ordered_json ObjectJson(const WorldDesc& world, int index) {
  const RigidObjectDesc& object = world.objects[index];
  const ElementIndex element = ElementIndex::Object(index);
  ordered_json out = {{"id", world.ObjectId(index)},
                      {"name", object.name},
                      {"file", object.geometry.path},
                      {"triangles", object.geometry.triangle_count()},
                      {"points", object.geometry.point_count()},
                      {"position", JsonVector(object.pose.translation())}};
  out.update(RowsJson(world, element, Rows(ElementKind::kObject, false)));
  out["simulation"] = RowsJson(world, element, Rows(ElementKind::kObject, true));
  return out;
}

ordered_json LinksJson(const WorldDesc& world, int index) {
  const RobotDesc& robot = world.robots[index];
  ordered_json links = ordered_json::array();
  for (int i = 0; i < robot.dof(); ++i) {
    const ElementIndex element = ElementIndex::Link(index, i);
    ordered_json link = {{"name", robot.links[i].name}, {"parent", robot.links[i].parent}};
    link.update(RowsJson(world, element, Rows(ElementKind::kLink, false)));
    link["simulation"] = RowsJson(world, element, Rows(ElementKind::kLink, true));
    links.push_back(link);
  }
  return links;
}

ordered_json DriversJson(const WorldDesc& world, int index) {
  const RobotDesc& robot = world.robots[index];
  ordered_json drivers = ordered_json::array();
  for (int i = 0; i < static_cast<int>(robot.drivers.size()); ++i) {
    ordered_json driver = {{"name", robot.drivers[i].name}};
    driver.update(RowsJson(world, ElementIndex::Driver(index, i), ParamsOf(ElementKind::kDriver)));
    drivers.push_back(driver);
  }
  return drivers;
}

ordered_json RobotJson(const WorldDesc& world, int index) {
  const RobotDesc& robot = world.robots[index];
  std::map<std::string, int> joint_counts;
  for (const JointDesc& joint : robot.joints) ++joint_counts[JointTypeName(joint.type)];
  int links_with_geometry = 0;
  for (const LinkDesc& link : robot.links) links_with_geometry += link.has_geometry() ? 1 : 0;
  ordered_json out = {{"id", world.RobotId(index)},
                      {"name", robot.name},
                      {"file", robot.source_path},
                      {"dofs", robot.dof()},
                      {"links", robot.dof()},
                      {"links_with_geometry", links_with_geometry},
                      {"drivers", robot.drivers.size()},
                      {"joints", joint_counts},
                      {"total_mass", robot.TotalMass()},
                      {"triangles", RobotTriangleCount(robot)},
                      {"points", RobotPointCount(robot)},
                      {"self_collision_pairs", robot.SelfCollisionPairs().size()}};
  out.update(RowsJson(world, ElementIndex::Robot(index), ParamsOf(ElementKind::kRobot)));
  out["link_details"] = LinksJson(world, index);
  out["driver_details"] = DriversJson(world, index);
  return out;
}

// six significant digits for people; the JSON keeps full precision
std::string Text(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

// "key value unit": numbers with Text, several as "(a, b, c)", bools and choices by name
std::string RowText(const ParamSpec& spec, const ParamValue& value) {
  std::string text = std::string(spec.key) + " ";
  if (spec.type == ParamType::kBool || spec.type == ParamType::kChoice) {
    return text + FormatParamValue(spec, value);
  }
  for (size_t i = 0; i < value.size(); ++i) {
    text += (i == 0 ? (value.size() > 1 ? "(" : "") : ", ") + Text(value[i]);
  }
  if (value.size() > 1) text += ")";
  return spec.unit.empty() ? text : text + " " + std::string(spec.unit);
}

std::string RowsText(const WorldDesc& world, const ElementIndex& element,
                     const std::vector<const ParamSpec*>& rows) {
  std::string text;
  for (const ParamSpec* spec : rows) {
    text += (text.empty() ? "" : ", ") + RowText(*spec, spec->get(world, element));
  }
  return text;
}

// "12 triangles", or "1000 points" for a point cloud
std::string ShapeText(const GeometryDesc& geometry) {
  if (geometry.kind == GeometryKind::kPointCloud) {
    return std::to_string(geometry.point_count()) + " points";
  }
  return std::to_string(geometry.triangle_count()) + " triangles";
}

std::string RobotText(const WorldDesc& world, int index) {
  const RobotDesc& r = world.robots[index];
  std::ostringstream out;
  out << "robot " << world.RobotId(index) << " '" << r.name << "': " << r.dof() << " DOFs ("
      << r.dof() << " links), " << r.drivers.size() << " drivers, total mass "
      << Text(r.TotalMass()) << " kg, " << RobotTriangleCount(r) << " triangles"
      << (RobotPointCount(r) > 0 ? ", " + std::to_string(RobotPointCount(r)) + " points" : "")
      << "\n";
  if (r.dof() > 0) {
    out << "  link 0: "
        << RowsText(world, ElementIndex::Link(index, 0), Rows(ElementKind::kLink, true)) << "\n";
  }
  for (int i = 0; i < static_cast<int>(r.drivers.size()); ++i) {
    out << "  driver " << i << " '" << r.drivers[i].name
        << "': " << RowsText(world, ElementIndex::Driver(index, i), ParamsOf(ElementKind::kDriver))
        << "\n";
  }
  return out.str();
}

}  // namespace

int RobotPointCount(const RobotDesc& robot) {
  int points = 0;
  for (const LinkDesc& link : robot.links) {
    for (const GeometryDesc& geometry : link.geometry) points += geometry.point_count();
  }
  return points;
}

int RobotTriangleCount(const RobotDesc& robot) {
  int triangles = 0;
  for (const LinkDesc& link : robot.links) {
    for (const GeometryDesc& geometry : link.geometry) triangles += geometry.triangle_count();
  }
  return triangles;
}

// "object 2 'drawer'", "link 3 of robot 'cabinet'", "terrain 0 'floor'"
std::string JointBodyText(const WorldDesc& world, const WorldJointBody& body) {
  switch (body.kind) {
    case WorldId::Kind::kTerrain:
      return "terrain " + std::to_string(world.TerrainId(body.index)) + " '" +
             world.terrains[body.index].name + "'";
    case WorldId::Kind::kRigidObject:
      return "object " + std::to_string(world.ObjectId(body.index)) + " '" +
             world.objects[body.index].name + "'";
    case WorldId::Kind::kRobotLink:
      return "link " + std::to_string(body.link) + " '" +
             world.robots[body.index].links[body.link].name + "' of robot '" +
             world.robots[body.index].name + "'";
    default:
      return "?";
  }
}

ordered_json JointJson(const WorldDesc& world, const WorldJointDesc& joint) {
  ordered_json out = {{"type", WorldJointTypeName(joint.type)}};
  out["bodies"] = ordered_json::array();
  for (const WorldJointBody& body : joint.bodies)
    out["bodies"].push_back(JointBodyText(world, body));
  if (joint.type == WorldJointType::kHinge) out["point"] = JsonVector(joint.point);
  if (joint.type != WorldJointType::kFixed) out["axis"] = JsonVector(joint.axis);
  out["min"] = JsonLimit(joint.min);
  out["max"] = JsonLimit(joint.max);
  out["friction"] = JsonLimit(joint.friction);
  return out;
}

std::string JointText(const WorldDesc& world, int index) {
  const WorldJointDesc& joint = world.joints[index];
  std::string text =
      "joint " + std::to_string(index) + " (" + WorldJointTypeName(joint.type) +
      "): " + JointBodyText(world, joint.bodies[0]) + " to " +
      (joint.bodies.size() > 1 ? JointBodyText(world, joint.bodies[1]) : "the world");
  const auto vec = [](const Vec3& v) {
    return "(" + Text(v.x()) + ", " + Text(v.y()) + ", " + Text(v.z()) + ")";
  };
  if (joint.type == WorldJointType::kHinge) text += ", through " + vec(joint.point);
  if (joint.type != WorldJointType::kFixed) {
    const char* unit = joint.type == WorldJointType::kHinge ? " rad" : " m";
    text += ", axis " + vec(joint.axis) + ", limits " + Text(joint.min) + " .. " + Text(joint.max) +
            unit + ", friction " + Text(joint.friction) +
            (joint.type == WorldJointType::kHinge ? " N·m" : " N");
  }
  return text + "\n";
}

std::string ParamsJson(const WorldDesc& world, const ElementIndex& element) {
  return RowsJson(world, element, ParamsOf(element.kind)).dump();
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
  out["joints"] = ordered_json::array();
  for (const WorldJointDesc& joint : world.joints) out["joints"].push_back(JointJson(world, joint));
  out["simulation"] = RowsJson(world, ElementIndex::Settings(), ParamsOf(ElementKind::kSettings));
  return out.dump(2) + "\n";
}

std::string WorldSummaryText(const WorldDesc& world) {
  std::ostringstream out;
  out << "world " << world.name << " (" << world.source_path << ")\n";
  for (int i = 0; i < static_cast<int>(world.terrains.size()); ++i) {
    const TerrainDesc& t = world.terrains[i];
    out << "terrain " << world.TerrainId(i) << " '" << t.name << "': " << ShapeText(t.geometry)
        << "\n  " << RowsText(world, ElementIndex::Terrain(i), Rows(ElementKind::kTerrain, true))
        << "\n";
  }
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    const RigidObjectDesc& o = world.objects[i];
    const Vec3 p = o.pose.translation();
    out << "object " << world.ObjectId(i) << " '" << o.name << "': mass " << Text(o.mass) << " kg, "
        << ShapeText(o.geometry) << ", at (" << Text(p.x()) << ", " << Text(p.y()) << ", "
        << Text(p.z()) << ")\n  "
        << RowsText(world, ElementIndex::Object(i), Rows(ElementKind::kObject, true)) << "\n";
  }
  for (int i = 0; i < static_cast<int>(world.robots.size()); ++i) out << RobotText(world, i);
  for (int i = 0; i < static_cast<int>(world.joints.size()); ++i) out << JointText(world, i);
  out << "simulation: "
      << RowsText(world, ElementIndex::Settings(), ParamsOf(ElementKind::kSettings)) << "\n";
  return out.str();
}

}  // namespace lamina::core
