// SPDX-License-Identifier: MIT
#include "core/io/world_simulation_reader.h"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/io/param_text.h"
#include "core/number_text.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::core {

namespace {

using tinyxml2::XMLElement;

// finds the body an element refers to by `index` or `name`; -1 (with an error) if none
template <typename Body>
int FindBody(const XmlElementReader& reader, const std::vector<Body>& bodies, const char* kind) {
  if (const auto index = reader.Integer("index")) {
    if (*index < 0 || *index >= static_cast<int>(bodies.size())) {
      reader.Error("index", "is " + std::to_string(*index) + " but the world has " +
                                std::to_string(bodies.size()) + " " + kind + "s");
      return -1;
    }
    return *index;
  }
  if (const auto name = reader.String("name")) {
    for (size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].name == *name) return static_cast<int>(i);
    }
    reader.Error("name", "is '" + *name + "' but no " + kind + " has that name");
    return -1;
  }
  if (!reader.Has("index")) reader.Error("needs an 'index' or a 'name' attribute");
  return -1;
}

using RowValues = std::vector<std::pair<const ParamSpec*, ParamValue>>;

// the attributes of `rows` that the element has and the table accepts (sizes as on `element`)
RowValues ReadRows(const XmlElementReader& reader, const std::vector<const ParamSpec*>& rows,
                   const WorldDesc& world, const ElementIndex& element) {
  RowValues values;
  for (const ParamSpec* spec : rows) {
    if (auto value = reader.Param(*spec, ParamSize(*spec, world, element))) {
      values.emplace_back(spec, std::move(*value));
    }
  }
  return values;
}

std::vector<std::string> KeysOf(const std::vector<const ParamSpec*>& rows) {
  std::vector<std::string> keys;
  for (const ParamSpec* spec : rows) keys.emplace_back(spec->key);
  return keys;
}

class SimulationReader {
 public:
  SimulationReader(const std::string& path, Diagnostics& diagnostics, WorldDesc* world)
      : path_(path), diagnostics_(diagnostics), world_(world) {}

  void Read(const XMLElement& block);

 private:
  XmlElementReader Reader(const XMLElement& e) const { return {e, path_, diagnostics_}; }
  void ReadGlobals(const XMLElement& element);
  // `<geometry>` children of a body reference, applied to each of `elements`
  void ReadGeometryChildren(const XMLElement& element, const std::vector<ElementIndex>& elements);
  void ReadVelocity(const XMLElement& element, int object);
  void ReadTerrainRef(const XMLElement& element);
  void ReadObjectRef(const XMLElement& element);
  void ReadRobotRef(const XMLElement& element);
  // `body` of a robot reference: a link name or number, -1 (all links) when `all` allows it;
  // nullopt (reported) when it names no link
  std::optional<int> RobotBody(const XmlElementReader& reader, const RobotDesc& robot,
                               bool all) const;
  void ReadJoint(const XMLElement& element);
  std::optional<WorldJointBody> ReadJointBody(const XMLElement& element) const;
  // the joint's type, axis, point, limits and friction; false (reported) when one is wrong
  bool ReadJointShape(const XmlElementReader& reader, WorldJointDesc* joint) const;
  void WarnUnknownChildren(const XMLElement& element, std::initializer_list<const char*> known);

  std::string path_;
  Diagnostics& diagnostics_;
  WorldDesc* world_;
};

void SimulationReader::Read(const XMLElement& block) {
  Reader(block).WarnUnknownAttributes({});
  for (const XMLElement* e = block.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "globals") {
      ReadGlobals(*e);
    } else if (name == "terrain") {
      ReadTerrainRef(*e);
    } else if (name == "object" || name == "rigidObject") {
      ReadObjectRef(*e);
    } else if (name == "robot") {
      ReadRobotRef(*e);
    } else if (name == "joint") {
      ReadJoint(*e);
    } else if (name == "state") {
      tinyxml2::XMLPrinter printer(nullptr, true);
      e->Accept(&printer);
      world_->preserved_simulation_xml.push_back(printer.CStr());
      Reader(*e).Warning(
          "Klamp't's saved simulator state is not read; kept as is and written "
          "back on save");
    } else {
      Reader(*e).Warning("unknown element ignored");
    }
  }
}

void SimulationReader::ReadGlobals(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  const std::vector<const ParamSpec*> rows = ParamsOf(ElementKind::kSettings);
  std::vector<std::string> known = KeysOf(rows);
  known.emplace_back("boundaryLayer");
  reader.WarnUnknownAttributes(known);
  if (reader.Has("boundaryLayer")) {
    reader.Warning("'boundaryLayer' has no effect (as in Klamp't); set 'padding' per body");
  }
  ReadParamAttributes(reader, rows, world_, ElementIndex::Settings());
}

void SimulationReader::ReadGeometryChildren(const XMLElement& element,
                                            const std::vector<ElementIndex>& elements) {
  const std::vector<const ParamSpec*> rows = BodyGeometryRows();
  for (const XMLElement* g = element.FirstChildElement("geometry"); g;
       g = g->NextSiblingElement("geometry")) {
    const XmlElementReader reader = Reader(*g);
    reader.WarnUnknownAttributes(KeysOf(rows));
    if (elements.empty()) continue;
    for (const auto& [spec, value] : ReadRows(reader, rows, *world_, elements.front())) {
      for (const ElementIndex& body : elements) spec->set(world_, body, value);
    }
  }
}

void SimulationReader::ReadVelocity(const XMLElement& element, int object) {
  const XmlElementReader velocity = Reader(element);
  velocity.WarnUnknownAttributes({"linear", "angular"});
  const ParamSpec& spec = *FindParam("velocity", ElementKind::kObject);
  const ElementIndex index = ElementIndex::Object(object);
  Twist twist = ValueToTwist(spec.get(*world_, index));
  if (const auto linear = velocity.Vector3("linear")) twist.linear = *linear;
  if (const auto angular = velocity.Vector3("angular")) twist.angular = *angular;
  const ParamValue value = TwistToValue(twist);
  if (velocity.CheckAssembled(spec, value, 6, "linear, angular")) spec.set(world_, index, value);
}

void SimulationReader::WarnUnknownChildren(const XMLElement& element,
                                           std::initializer_list<const char*> known) {
  for (const XMLElement* e = element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    bool is_known = false;
    for (const char* name : known) is_known = is_known || std::string(name) == e->Name();
    if (!is_known) Reader(*e).Warning("unknown element ignored");
  }
}

void SimulationReader::ReadTerrainRef(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"index", "name"});
  WarnUnknownChildren(element, {"geometry"});
  const int index = FindBody(reader, world_->terrains, "terrain");
  if (index < 0) return;
  ReadGeometryChildren(element, {ElementIndex::Terrain(index)});
}

void SimulationReader::ReadObjectRef(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"index", "name"});
  WarnUnknownChildren(element, {"geometry", "velocity"});
  const int index = FindBody(reader, world_->objects, "object");
  if (index < 0) return;
  ReadGeometryChildren(element, {ElementIndex::Object(index)});
  if (const XMLElement* v = element.FirstChildElement("velocity")) ReadVelocity(*v, index);
}

void SimulationReader::ReadRobotRef(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"index", "name", "body"});
  WarnUnknownChildren(element, {"geometry", "controller", "sensors"});
  const int index = FindBody(reader, world_->robots, "robot");
  if (index < 0) return;
  RobotDesc& robot = world_->robots[index];
  const std::optional<int> found = RobotBody(reader, robot, true);
  if (!found) return;
  const int body = *found;
  std::vector<ElementIndex> links;
  for (int link = 0; link < robot.dof(); ++link) {
    if (body < 0 || link == body) links.push_back(ElementIndex::Link(index, link));
  }
  ReadGeometryChildren(element, links);
  for (const char* property : {"controller", "sensors"}) {
    if (const XMLElement* e = element.FirstChildElement(property)) {
      tinyxml2::XMLPrinter printer(nullptr, true);
      e->Accept(&printer);
      robot.properties[property] = printer.CStr();
      if (std::string(property) == "sensors") {
        ParseSensorsElement(*e, robot, path_, 0, &diagnostics_);
      }
    }
  }
}

std::optional<int> SimulationReader::RobotBody(const XmlElementReader& reader,
                                               const RobotDesc& robot, bool all) const {
  const auto text = reader.String("body");
  if (!text && all) return -1;  // Klamp't requires `body`; a missing one means every link
  if (!text) {
    reader.Error("needs a 'body' attribute: the link's name or number");
    return std::nullopt;
  }
  for (int i = 0; i < robot.dof(); ++i) {
    if (robot.links[i].name == *text) return i;
  }
  const auto number = reader.Integer("body");
  if (!number) return std::nullopt;
  if (*number < (all ? -1 : 0) || *number >= robot.dof()) {
    reader.Error("body", "is " + std::to_string(*number) + " but robot '" + robot.name + "' has " +
                             std::to_string(robot.dof()) + " links" +
                             (all ? " (-1 means all)" : ""));
    return std::nullopt;
  }
  return *number;
}

std::optional<WorldJointBody> SimulationReader::ReadJointBody(const XMLElement& element) const {
  const XmlElementReader reader = Reader(element);
  const std::string name = element.Name();
  if (name == "terrain" || name == "object" || name == "rigidObject") {
    reader.WarnUnknownAttributes({"index", "name"});
    const bool terrain = name == "terrain";
    const int index = terrain ? FindBody(reader, world_->terrains, "terrain")
                              : FindBody(reader, world_->objects, "object");
    if (index < 0) return std::nullopt;
    return WorldJointBody{terrain ? WorldId::Kind::kTerrain : WorldId::Kind::kRigidObject, index,
                          -1};
  }
  if (name == "robot") {
    reader.WarnUnknownAttributes({"index", "name", "body"});
    const int index = FindBody(reader, world_->robots, "robot");
    if (index < 0) return std::nullopt;
    const std::optional<int> link = RobotBody(reader, world_->robots[index], false);
    if (!link) return std::nullopt;
    return WorldJointBody{WorldId::Kind::kRobotLink, index, *link};
  }
  reader.Error("is not a body a joint can hold: <rigidObject>, <robot body=...> or <terrain>");
  return std::nullopt;
}

bool SimulationReader::ReadJointShape(const XmlElementReader& reader, WorldJointDesc* joint) const {
  const std::optional<std::string> type = reader.String("type");
  if (!type) {
    reader.Error("needs a 'type' attribute: fixed, hinge or slider");
    return false;
  }
  bool ok = true;
  if (*type == "hinge" || *type == "slider") {
    joint->type = *type == "hinge" ? WorldJointType::kHinge : WorldJointType::kSlider;
    const std::optional<Vec3> axis = reader.Vector3("axis");
    if (!reader.Has("axis")) reader.Error("(" + *type + ") needs an 'axis' attribute");
    if (axis && !(axis->norm() > 0.0)) reader.Error("axis", "must not be zero");
    ok = axis && axis->norm() > 0.0;
    if (ok) joint->axis = axis->normalized();
  } else if (*type != "fixed") {
    reader.Error("type", "is '" + *type + "'; expected fixed, hinge or slider");
    return false;
  }
  if (joint->type == WorldJointType::kHinge) {
    const std::optional<Vec3> point = reader.Vector3("point");
    if (!reader.Has("point")) reader.Error("(hinge) needs a 'point' attribute on its axis");
    ok = ok && point.has_value();
    if (point) joint->point = *point;
  }
  return ok;
}

void SimulationReader::ReadJoint(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes(
      {"type", "point", "axis", "min", "minimum", "max", "maximum", "minimax", "friction"});
  WorldJointDesc joint;
  bool ok = ReadJointShape(reader, &joint);
  for (const XMLElement* e = element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::optional<WorldJointBody> body = ReadJointBody(*e);
    ok = ok && body.has_value();
    if (body) joint.bodies.push_back(*body);
  }
  if (joint.bodies.empty() || joint.bodies.size() > 2) {
    reader.Error("holds " + std::to_string(joint.bodies.size()) +
                 " bodies; it needs one or two (<rigidObject>, <robot body=...>, <terrain>)");
    return;
  }
  if (joint.bodies.size() == 2 && joint.bodies[0] == joint.bodies[1]) {
    reader.Error("holds the same body twice");
    return;
  }
  const char* min_name = reader.Has("minimum") ? "minimum" : "min";
  // Klamp't's reader takes the upper limit from "minimax" (a typo): its files may use it
  const char* max_name = reader.Has("maximum") ? "maximum" : reader.Has("max") ? "max" : "minimax";
  if (reader.Has("minimax")) {
    reader.Warning(std::string("'minimax' is read as the upper limit, as Klamp't reads it") +
                   (std::string(max_name) == "minimax"
                        ? ""
                        : "; '" + std::string(max_name) + "' is given too and wins"));
  }
  if (const auto min = reader.Number(min_name)) joint.min = *min;
  if (const auto max = reader.Number(max_name)) joint.max = *max;
  if (const auto friction = reader.Number("friction", false)) joint.friction = *friction;
  if (!(joint.min <= joint.max)) {
    reader.Error("limits " + FormatDouble(joint.min) + " .. " + FormatDouble(joint.max) +
                 " must be ordered (min <= max)");
    return;
  }
  const bool hinge = joint.type == WorldJointType::kHinge;
  if (hinge && ((std::isfinite(joint.min) && joint.min < -kPi) ||
                (std::isfinite(joint.max) && joint.max > kPi))) {
    reader.Error("a hinge's limits must lie in [-pi, pi] rad (ODE's hinge angle), got " +
                 FormatDouble(joint.min) + " .. " + FormatDouble(joint.max));
    return;
  }
  if (!(joint.friction >= 0.0)) {
    reader.Error("friction", "must be >= 0, got " + FormatDouble(joint.friction));
    return;
  }
  if (ok) world_->joints.push_back(std::move(joint));
}

}  // namespace

void ReadParamAttributes(const XmlElementReader& reader, const std::vector<const ParamSpec*>& rows,
                         WorldDesc* world, const ElementIndex& element) {
  for (const auto& [spec, value] : ReadRows(reader, rows, *world, element)) {
    spec->set(world, element, value);
  }
}

void ReadSimulationBlock(const XMLElement& element, const std::string& path,
                         Diagnostics& diagnostics, WorldDesc* world) {
  SimulationReader(path, diagnostics, world).Read(element);
}

}  // namespace lamina::core
