// SPDX-License-Identifier: MIT
#include "core/io/world_simulation_reader.h"

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

void ReadGeometryParams(const XMLElement& element, const std::string& path,
                        Diagnostics& diagnostics, BodySimParams* params) {
  const XmlElementReader reader(element, path, diagnostics);
  reader.WarnUnknownAttributes(
      {"padding", "preshrink", "kRestitution", "kFriction", "kStiffness", "kDamping"});
  if (const auto padding = reader.Number("padding", false)) {
    if (*padding < 0) {
      reader.Error("padding", "must be >= 0, got '" + *reader.String("padding") + "'");
    } else {
      params->padding = *padding;
    }
  }
  if (const auto preshrink = reader.Integer("preshrink")) {
    if (*preshrink < 0 || *preshrink > 2) {
      reader.Error("preshrink", "must be 0, 1 or 2, got '" + *reader.String("preshrink") + "'");
    } else {
      params->preshrink = static_cast<Preshrink>(*preshrink);
    }
  }
  ReadSurfaceAttributes(reader, &params->surface);
}

class SimulationReader {
 public:
  SimulationReader(const std::string& path, Diagnostics& diagnostics, WorldDesc* world)
      : path_(path), diagnostics_(diagnostics), world_(world) {}

  void Read(const XMLElement& block);

 private:
  XmlElementReader Reader(const XMLElement& e) const { return {e, path_, diagnostics_}; }
  void ReadGlobals(const XMLElement& element);
  void ReadTerrainRef(const XMLElement& element);
  void ReadObjectRef(const XMLElement& element);
  void ReadRobotRef(const XMLElement& element);
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
    } else if (name == "joint" || name == "state") {
      tinyxml2::XMLPrinter printer(nullptr, true);
      e->Accept(&printer);
      world_->preserved_simulation_xml.push_back(printer.CStr());
      Reader(*e).Warning("not simulated yet; kept as is and written back on save");
    } else {
      Reader(*e).Warning("unknown element ignored");
    }
  }
}

void SimulationReader::ReadGlobals(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"timestep", "gravity", "ERP", "CFM", "maxContacts", "boundaryLayer",
                                "adaptiveTimeStepping", "rigidObjectCollisions",
                                "robotSelfCollisions", "robotRobotCollisions"});
  SimSettings& s = world_->settings;
  if (const auto timestep = reader.Number("timestep", false)) {
    if (*timestep <= 0) {
      reader.Error("timestep", "must be > 0, got '" + *reader.String("timestep") + "'");
    } else {
      s.timestep = *timestep;
    }
  }
  if (const auto gravity = reader.Vector3("gravity")) s.gravity = *gravity;
  if (const auto erp = reader.Number("ERP", false)) {
    if (*erp < 0 || *erp > 1) {
      reader.Error("ERP", "must be in [0, 1], got '" + *reader.String("ERP") + "'");
    } else {
      s.erp = *erp;
    }
  }
  if (const auto cfm = reader.Number("CFM", false)) {
    if (*cfm < 0) {
      reader.Error("CFM", "must be >= 0, got '" + *reader.String("CFM") + "'");
    } else {
      s.cfm = *cfm;
    }
  }
  if (const auto max_contacts = reader.Integer("maxContacts")) {
    if (*max_contacts < 1) {
      reader.Error("maxContacts", "must be >= 1, got '" + *reader.String("maxContacts") + "'");
    } else {
      s.max_contacts = *max_contacts;
    }
  }
  if (reader.Has("boundaryLayer")) {
    reader.Warning("'boundaryLayer' has no effect (as in Klamp't); set 'padding' per body");
  }
  if (const auto v = reader.Boolean("adaptiveTimeStepping")) s.adaptive_time_stepping = *v;
  if (const auto v = reader.Boolean("rigidObjectCollisions")) s.rigid_object_collisions = *v;
  if (const auto v = reader.Boolean("robotSelfCollisions")) s.robot_self_collisions = *v;
  if (const auto v = reader.Boolean("robotRobotCollisions")) s.robot_robot_collisions = *v;
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
  for (const XMLElement* g = element.FirstChildElement("geometry"); g;
       g = g->NextSiblingElement("geometry")) {
    ReadGeometryParams(*g, path_, diagnostics_, &world_->terrains[index].sim);
  }
}

void SimulationReader::ReadObjectRef(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"index", "name"});
  WarnUnknownChildren(element, {"geometry", "velocity"});
  const int index = FindBody(reader, world_->objects, "object");
  if (index < 0) return;
  RigidObjectDesc& object = world_->objects[index];
  for (const XMLElement* g = element.FirstChildElement("geometry"); g;
       g = g->NextSiblingElement("geometry")) {
    ReadGeometryParams(*g, path_, diagnostics_, &object.sim);
  }
  if (const XMLElement* v = element.FirstChildElement("velocity")) {
    const XmlElementReader velocity = Reader(*v);
    velocity.WarnUnknownAttributes({"linear", "angular"});
    if (const auto linear = velocity.Vector3("linear")) object.initial_velocity.linear = *linear;
    if (const auto angular = velocity.Vector3("angular")) {
      object.initial_velocity.angular = *angular;
    }
  }
}

void SimulationReader::ReadRobotRef(const XMLElement& element) {
  const XmlElementReader reader = Reader(element);
  reader.WarnUnknownAttributes({"index", "name", "body"});
  WarnUnknownChildren(element, {"geometry", "controller", "sensors"});
  const int index = FindBody(reader, world_->robots, "robot");
  if (index < 0) return;
  RobotDesc& robot = world_->robots[index];
  int body = -1;  // Klamp't requires `body`; a missing one means every link
  if (const auto text = reader.String("body")) {
    body = robot.dof();
    for (int i = 0; i < robot.dof(); ++i) {
      if (robot.links[i].name == *text) body = i;
    }
    if (body == robot.dof()) {
      const auto number = reader.Integer("body");
      if (!number) return;
      body = *number;
    }
    if (body < -1 || body >= robot.dof()) {
      reader.Error("body", "is " + std::to_string(body) + " but robot '" + robot.name + "' has " +
                               std::to_string(robot.dof()) + " links (-1 means all)");
      return;
    }
  }
  for (const XMLElement* g = element.FirstChildElement("geometry"); g;
       g = g->NextSiblingElement("geometry")) {
    for (int link = 0; link < robot.dof(); ++link) {
      if (body >= 0 && link != body) continue;
      ReadGeometryParams(*g, path_, diagnostics_, &robot.links[link].sim);
    }
  }
  for (const char* property : {"controller", "sensors"}) {
    if (const XMLElement* e = element.FirstChildElement(property)) {
      tinyxml2::XMLPrinter printer(nullptr, true);
      e->Accept(&printer);
      robot.properties[property] = printer.CStr();
    }
  }
}

}  // namespace

void ReadSurfaceAttributes(const XmlElementReader& reader, SurfaceDesc* surface) {
  if (const auto e = reader.Number("kRestitution", false)) {
    if (*e < 0 || *e > 1) {
      reader.Error("kRestitution",
                   "must be in [0, 1], got '" + *reader.String("kRestitution") + "'");
    } else {
      surface->restitution = *e;
    }
  }
  if (const auto mu = reader.Number("kFriction")) {
    if (*mu < 0) {
      reader.Error("kFriction", "must be >= 0, got '" + *reader.String("kFriction") + "'");
    } else {
      surface->friction = *mu;
    }
  }
  if (const auto k = reader.Number("kStiffness")) {
    if (*k <= 0) {
      reader.Error("kStiffness", "must be > 0, got '" + *reader.String("kStiffness") + "'");
    } else {
      surface->stiffness = *k;
    }
  }
  if (const auto c = reader.Number("kDamping")) {
    if (*c < 0) {
      reader.Error("kDamping", "must be >= 0, got '" + *reader.String("kDamping") + "'");
    } else {
      surface->damping = *c;
    }
  }
}

void ReadSimulationBlock(const XMLElement& element, const std::string& path,
                         Diagnostics& diagnostics, WorldDesc* world) {
  SimulationReader(path, diagnostics, world).Read(element);
}

}  // namespace lamina::core
