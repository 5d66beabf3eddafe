// SPDX-License-Identifier: MIT
// Reading Klamp't world XML into a WorldDesc: `<robot>`, `<rigidObject>`, `<terrain>` and
// `<display>` here, the `<simulation>` block in world_simulation_reader.cpp.
#include <optional>
#include <utility>
#include <vector>

#include <tinyxml2.h>

#include "core/geometry/mass_properties.h"
#include "core/io/geometry_file.h"
#include "core/io/object_file.h"
#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/robot_file.h"
#include "core/io/trajectory_file.h"
#include "core/io/world_file.h"
#include "core/io/world_simulation_reader.h"
#include "core/io/world_xml_transform.h"
#include "core/io/xml_element_reader.h"
#include "core/model/params.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::core {

namespace {

using tinyxml2::XMLElement;

// Klamp't's default `automassSurfaceFraction` for world XML objects
constexpr double kWorldSurfaceFraction = 1.0;

// Reads `rows` from the element onto `object`, which is not in the world yet: the table's rows
// address elements of a world, so it is lent to a world of its own meanwhile.
void ReadObjectParams(const XmlElementReader& reader, const std::vector<const ParamSpec*>& rows,
                      RigidObjectDesc* object) {
  WorldDesc lent;
  lent.objects.push_back(std::move(*object));
  ReadParamAttributes(reader, rows, &lent, ElementIndex::Object(0));
  *object = std::move(lent.objects.front());
}

// the surface rows a `<terrain>` element may carry: Klamp't's kFriction and Lamina's rolling and
// spinning friction (the other rows live in `<simulation><terrain><geometry>` only)
std::vector<const ParamSpec*> TerrainSurfaceRows() {
  std::vector<const ParamSpec*> rows;
  for (const char* key : {"kFriction", "kRollingFriction", "kSpinningFriction"}) {
    rows.push_back(FindParam(key, ElementKind::kTerrain));
  }
  return rows;
}

DisplayAttributes ReadDisplay(const XMLElement& element) {
  DisplayAttributes display;
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    display[a->Name()] = a->Value();
  }
  return display;
}

class WorldReader {
 public:
  WorldReader(const std::string& path, LoadContext& context, WorldDesc* world)
      : path_(path), dir_(DirectoryOf(path)), context_(context), world_(world) {}

  void ReadWorld(const XMLElement& root);

 private:
  XmlElementReader Reader(const XMLElement& e) const {
    return XmlElementReader(e, path_, context_.diagnostics);
  }
  void ReadRobot(const XMLElement& element);
  void ReadRobotChildren(const XMLElement& element, RobotDesc* robot);
  void ReadSensors(const XMLElement& element, RobotDesc* robot);
  void ReadRobotConfig(const XmlElementReader& reader, RobotDesc* robot);
  void ReadRobotVelocity(const XmlElementReader& reader, RobotDesc* robot);
  void ReadObject(const XMLElement& element);
  void ReadObjectGeometry(const XMLElement& element, RigidObjectDesc* object);
  void ReadObjectPhysics(const XMLElement& element, RigidObjectDesc* object);
  void ReadTerrain(const XMLElement& element);

  std::string path_;
  std::string dir_;
  LoadContext& context_;
  WorldDesc* world_;
};

void WorldReader::ReadWorld(const XMLElement& root) {
  // Klamp't reads robots, then objects, then terrains, whatever the order in the file
  for (const char* kind : {"robot", "rigidObject", "terrain"}) {
    for (const XMLElement* e = root.FirstChildElement(kind); e; e = e->NextSiblingElement(kind)) {
      if (std::string(kind) == "robot") ReadRobot(*e);
      if (std::string(kind) == "rigidObject") ReadObject(*e);
      if (std::string(kind) == "terrain") ReadTerrain(*e);
    }
  }
  for (const XMLElement* e = root.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "robot" || name == "rigidObject" || name == "terrain") continue;
    if (name == "simulation") {
      ReadSimulationBlock(*e, path_, context_.diagnostics, world_);
    } else if (name == "display" || name == "appearance" || name == "goal") {
      // viewer settings of Klamp't's own GUI; nothing in the world depends on them
      Reader(*e).Warning("element ignored (viewer setting)");
    } else {
      Reader(*e).Warning("unknown element ignored");
    }
  }
}

void WorldReader::ReadRobot(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"name", "file", "config", "configfile", "velocity", "translation",
                                "position", "rotateRPY", "rotateMoment", "rotateX", "rotateY",
                                "rotateZ"});
  const auto file = reader.String("file");
  if (!file) {
    reader.Error("missing attribute 'file'");
    return;
  }
  RobotDesc robot;
  if (!LoadRobotFile(ResolvePath(dir_, *file), reader.location(), context_, &robot)) return;
  robot.name = reader.String("name").value_or("Robot");
  ReadRobotConfig(reader, &robot);
  ReadRobotVelocity(reader, &robot);
  Pose pose;
  if (ReadPose(reader, &pose)) {
    for (LinkDesc& link : robot.links) {
      if (link.parent < 0) link.parent_transform = pose * link.parent_transform;
    }
  }
  ReadRobotChildren(element, &robot);
  world_->robots.push_back(std::move(robot));
}

void WorldReader::ReadRobotConfig(const XmlElementReader& reader, RobotDesc* robot) {
  std::optional<VecX> config = reader.CountedVector("config");
  if (const auto file = reader.String("configfile")) {
    config = ReadConfigFile(ResolvePath(dir_, *file), context_.diagnostics);
  }
  if (!config) return;
  if (config->size() != robot->dof()) {
    reader.Error("configuration has " + std::to_string(config->size()) + " values but robot '" +
                 robot->name + "' has " + std::to_string(robot->dof()) + " links");
    return;
  }
  const ParamValue value(config->data(), config->data() + config->size());
  const char* from = reader.Has("configfile") ? "configfile" : "config";
  if (reader.CheckAssembled(*FindParam("config", ElementKind::kRobot), value, robot->dof(), from)) {
    robot->config = *config;
  }
}

// Lamina's `velocity="N v1 ... vN"`: the initial joint rates (Klamp't has no attribute for them)
void WorldReader::ReadRobotVelocity(const XmlElementReader& reader, RobotDesc* robot) {
  const std::optional<VecX> velocity = reader.CountedVector("velocity");
  if (!velocity) return;
  if (velocity->size() != robot->dof()) {
    reader.Error("velocity", "has " + std::to_string(velocity->size()) + " values but robot '" +
                                 robot->name + "' has " + std::to_string(robot->dof()) + " links");
    return;
  }
  const ParamValue value(velocity->data(), velocity->data() + velocity->size());
  if (reader.CheckAssembled(*FindParam("velocity", ElementKind::kRobot), value, robot->dof(),
                            "velocity")) {
    robot->velocity = *velocity;
  }
}

void WorldReader::ReadRobotChildren(const XMLElement& element, RobotDesc* robot) {
  for (const XMLElement* e = element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "display") {
      DisplayAttributes display = ReadDisplay(*e);
      const std::string link = display.count("link") ? display["link"] : "";
      display.erase("link");
      robot->link_display.emplace_back(link, std::move(display));
    } else if (name == "sensors") {
      ReadSensors(*e, robot);
    } else {
      Reader(*e).Warning("unknown element ignored");
    }
  }
}

// `<sensors>` inline or `file=` (read now, relative to the world file): the robot's `sensors`
// property holds the XML text; the sensors are checked here to report at their file:line
void WorldReader::ReadSensors(const XMLElement& element, RobotDesc* robot) {
  if (const char* file = element.Attribute("file")) {
    const std::string path = ResolvePath(dir_, file);
    std::string text;
    if (!ReadFileText(path, &text)) {
      Reader(element).Error("cannot read sensors file '" + path + "'");
      return;
    }
    robot->properties["sensors"] = text;
    ParseSensorsXml(text, *robot, {path, 1, 0}, &context_.diagnostics);
    return;
  }
  tinyxml2::XMLPrinter printer(nullptr, true);
  element.Accept(&printer);
  robot->properties["sensors"] = printer.CStr();
  ParseSensorsElement(element, *robot, path_, 0, &context_.diagnostics);
}

void WorldReader::ReadObject(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"name", "file", "translation", "position", "rotateRPY",
                                "rotateMoment", "rotateX", "rotateY", "rotateZ"});
  RigidObjectDesc object;
  object.inertia = Mat3::Zero();
  object.sim = DefaultObjectSimParams();
  if (const auto file = reader.String("file")) {
    if (!LoadRigidObjectFile(ResolvePath(dir_, *file), reader.location(), context_, &object)) {
      return;
    }
  }
  object.name = reader.String("name").value_or("Object");
  if (const XMLElement* geometry = element.FirstChildElement("geometry")) {
    ReadObjectGeometry(*geometry, &object);
  }
  if (object.geometry.empty()) {
    reader.Error("has no geometry (give 'file' or a <geometry mesh=...> child)");
    return;
  }
  Pose pose;
  if (ReadPose(reader, &pose) &&
      reader.CheckAssembled(*FindParam("transform", ElementKind::kObject), PoseToValue(pose), 12,
                            "the transform attributes")) {
    object.pose = pose;
  }
  if (const XMLElement* physics = element.FirstChildElement("physics")) {
    ReadObjectPhysics(*physics, &object);
  }
  if (object.inertia.isZero(0.0) && object.mass > 0.0) {
    reader.Warning("no inertia given; computed from the geometry (Klamp't would leave it zero)");
    const MassProperties mass =
        ComputeMassProperties(object.geometry, object.mass, kWorldSurfaceFraction);
    if (mass.valid) object.inertia = mass.inertia;
  }
  for (const XMLElement* e = element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "display") {
      object.display = ReadDisplay(*e);
    } else if (name != "geometry" && name != "physics") {
      Reader(*e).Warning("unknown element ignored");
    }
  }
  world_->objects.push_back(std::move(object));
}

void WorldReader::ReadObjectGeometry(const XMLElement& element, RigidObjectDesc* object) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"mesh", "file", "scale", "margin", "translation", "position",
                                "rotateRPY", "rotateMoment", "rotateX", "rotateY", "rotateZ"});
  auto file = reader.String("mesh");
  if (!file) file = reader.String("file");
  if (file) {
    GeometryDesc geometry;
    if (!LoadGeometryFile(ResolvePath(dir_, *file), reader.location(), context_, &geometry)) {
      return;
    }
    object->geometry = std::move(geometry);
  }
  ApplyGeometryTransform(reader, &object->geometry);
  if (const auto margin = reader.Number("margin", false)) {
    if (*margin < 0) {
      reader.Error("margin", "must be >= 0, got '" + *reader.String("margin") + "'");
    } else {
      object->geometry.margin = *margin;
    }
  }
}

void WorldReader::ReadObjectPhysics(const XMLElement& element, RigidObjectDesc* object) {
  const XmlElementReader reader = Reader(element);
  std::vector<std::string> known = {"mass", "com", "inertia", "automass",
                                    "automassSurfaceFraction"};
  for (const ParamSpec* spec : SurfaceRows()) known.emplace_back(spec->key);
  reader.WarnUnknownAttributes(known);
  std::vector<const ParamSpec*> mass_rows;
  for (const char* key : {"mass", "com", "inertia"}) {
    mass_rows.push_back(FindParam(key, ElementKind::kObject));
  }
  ReadObjectParams(reader, mass_rows, object);
  double fraction = kWorldSurfaceFraction;
  if (const auto value = reader.Number("automassSurfaceFraction", false)) {
    if (*value < 0 || *value > 1) {
      reader.Error("automassSurfaceFraction",
                   "must be in [0, 1], got '" + *reader.String("automassSurfaceFraction") + "'");
    } else {
      fraction = *value;
    }
  }
  if (reader.Boolean("automass").value_or(false)) {
    const MassProperties mass = ComputeMassProperties(object->geometry, object->mass, fraction);
    if (mass.valid) {
      object->com = mass.com;
      object->inertia = mass.inertia;
    } else {
      reader.Error("automass: cannot compute mass properties from degenerate geometry");
    }
  }
  ReadObjectParams(reader, SurfaceRows(), object);
}

void WorldReader::ReadTerrain(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  const std::vector<const ParamSpec*> surface_rows = TerrainSurfaceRows();
  std::vector<std::string> known = {"name",        "file",     "margin",    "scale",
                                    "translation", "position", "rotateRPY", "rotateMoment",
                                    "rotateX",     "rotateY",  "rotateZ"};
  for (const ParamSpec* spec : surface_rows) known.emplace_back(spec->key);
  reader.WarnUnknownAttributes(known);
  const auto file = reader.String("file");
  if (!file) {
    reader.Error("missing attribute 'file'");
    return;
  }
  TerrainDesc terrain;
  if (!LoadTerrainFile(ResolvePath(dir_, *file), reader.location(), context_, &terrain)) return;
  terrain.name =
      reader.String("name").value_or("Terrain" + std::to_string(world_->terrains.size()));
  ApplyGeometryTransform(reader, &terrain.geometry);
  if (const auto margin = reader.Number("margin", false)) terrain.geometry.margin = *margin;
  WorldDesc lent;  // the terrain in a world of its own, where the table's rows address it
  lent.terrains.push_back(std::move(terrain));
  ReadParamAttributes(reader, surface_rows, &lent, ElementIndex::Terrain(0));
  terrain = std::move(lent.terrains.front());
  for (const XMLElement* e = element.FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (std::string(e->Name()) == "display") {
      terrain.display = ReadDisplay(*e);
    } else {
      Reader(*e).Warning("unknown element ignored");
    }
  }
  world_->terrains.push_back(std::move(terrain));
}

}  // namespace

bool ParseWorldXml(const std::string& text, const std::string& path, LoadContext& context,
                   WorldDesc* out) {
  const int errors_before = context.diagnostics.error_count();
  *out = WorldDesc();
  out->name = StemOf(path);
  out->source_path = path;
  tinyxml2::XMLDocument document;
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    context.diagnostics.Error(
        {path, document.ErrorLineNum(), 0},
        std::string("malformed XML: ") + tinyxml2::XMLDocument::ErrorIDToName(document.ErrorID()));
    return false;
  }
  const XMLElement* root = document.RootElement();
  if (!root || std::string(root->Name()) != "world") {
    context.diagnostics.Error(
        {path, root ? root->GetLineNum() : 1, 0},
        "root element must be <world>, got <" + std::string(root ? root->Name() : "") + ">");
    return false;
  }
  WorldReader(path, context, out).ReadWorld(*root);
  return context.diagnostics.error_count() == errors_before;
}

}  // namespace lamina::core
