// SPDX-License-Identifier: MIT
#include "core/io/world_simulation_reader.h"

#include <utility>
#include <vector>

#include "core/io/param_text.h"

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
    }
  }
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
