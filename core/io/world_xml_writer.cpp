// SPDX-License-Identifier: MIT
// Writing a WorldDesc as Klamp't world XML (plus one `.rob` per robot) such that loading the
// result gives the same description.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <vector>

#include <tinyxml2.h>

#include "core/io/geometry_file.h"
#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/robot_file.h"
#include "core/io/text_statements.h"
#include "core/io/world_file.h"
#include "core/io/world_xml_transform.h"
#include "core/model/element.h"
#include "core/model/params.h"

namespace lamina::core {

namespace {

using Attributes = std::vector<std::pair<std::string, std::string>>;

std::string FormatCountedVector(const VecX& v) {
  return std::to_string(v.size()) + (v.size() ? "  " + FormatDoubles(v.data(), v.size()) : "");
}

// a file name made of the robot name's safe characters, unique within `used`
std::string RobotFileName(const std::string& name, std::set<std::string>* used) {
  std::string stem;
  for (char c : name) stem += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '_';
  if (stem.empty()) stem = "robot";
  std::string candidate = stem + ".rob";
  for (int i = 2; used->count(candidate); ++i) candidate = stem + "_" + std::to_string(i) + ".rob";
  used->insert(candidate);
  return candidate;
}

class WorldWriter {
 public:
  WorldWriter(const WorldDesc& world, const std::string& path)
      : world_(world), dir_(DirectoryOf(path)), robots_dir_name_(StemOf(path) + "_robots") {}

  WorldFileSet Write();

 private:
  void Element(const char* name, const Attributes& attributes, bool close = true) {
    printer_.OpenElement(name);
    for (const auto& [key, value] : attributes) printer_.PushAttribute(key.c_str(), value.c_str());
    if (close) printer_.CloseElement();
  }
  void WriteDisplay(const DisplayAttributes& display, const std::string& link = "");
  void WriteTerrain(const TerrainDesc& terrain);
  void WriteObject(const RigidObjectDesc& object, int index);
  void WriteRobot(const RobotDesc& robot, std::set<std::string>* used_names);
  RobotDesc WithPrimitiveFiles(const RobotDesc& robot, const std::string& rob_path);
  void WriteSimulation();
  void WriteJoint(const WorldJointDesc& joint);
  void WriteBodyParams(const char* kind, const ElementIndex& element, const std::string& body = "");
  Attributes GeometryAttributes(const char* file_key, const GeometryDesc& geometry);
  // each row's key and value on `element`, in ParamWords
  Attributes RowAttributes(const std::vector<const ParamSpec*>& rows,
                           const ElementIndex& element) const;
  Attributes GlobalsAttributes() const;
  // a body's rows without Lamina's that are off (rolling and spinning friction at 0)
  std::vector<const ParamSpec*> BodyRows(std::vector<const ParamSpec*> rows,
                                         const ElementIndex& element) const;

  const WorldDesc& world_;
  std::string dir_;
  std::string robots_dir_name_;
  tinyxml2::XMLPrinter printer_;
  WorldFileSet files_;
};

WorldFileSet WorldWriter::Write() {
  printer_.PushDeclaration("xml version=\"1.0\" encoding=\"UTF-8\"");
  Element("world", {}, false);
  for (const TerrainDesc& terrain : world_.terrains) WriteTerrain(terrain);
  for (size_t i = 0; i < world_.objects.size(); ++i) {
    WriteObject(world_.objects[i], static_cast<int>(i));
  }
  std::set<std::string> used_names;
  for (const RobotDesc& robot : world_.robots) WriteRobot(robot, &used_names);
  WriteSimulation();
  printer_.CloseElement();
  files_.world_xml = printer_.CStr();
  return files_;
}

void WorldWriter::WriteDisplay(const DisplayAttributes& display, const std::string& link) {
  if (display.empty() && link.empty()) return;
  Attributes attributes;
  if (!link.empty()) attributes.emplace_back("link", link);
  attributes.insert(attributes.end(), display.begin(), display.end());
  Element("display", attributes);
}

Attributes WorldWriter::GeometryAttributes(const char* file_key, const GeometryDesc& geometry) {
  Attributes attributes{{file_key, RelativePath(geometry.path, dir_)}};
  Attributes placement;
  if (!GeometryTransformAttributes(geometry, &placement)) {
    files_.errors.push_back("geometry '" + geometry.path +
                            "' has a sheared placement that world XML cannot express");
  }
  attributes.insert(attributes.end(), placement.begin(), placement.end());
  if (geometry.margin != 0.0) attributes.emplace_back("margin", FormatDouble(geometry.margin));
  return attributes;
}

Attributes WorldWriter::RowAttributes(const std::vector<const ParamSpec*>& rows,
                                      const ElementIndex& element) const {
  Attributes attributes;
  for (const ParamSpec* spec : rows) {
    attributes.emplace_back(spec->key, ParamWords(*spec, spec->get(world_, element)));
  }
  return attributes;
}

// Klamp't's rows always; Lamina's only when they differ from SimSettings{}, so that a saved
// world stays a Klamp't world unless it uses Lamina's settings
Attributes WorldWriter::GlobalsAttributes() const {
  const WorldDesc defaults;
  std::vector<const ParamSpec*> rows;
  for (const ParamSpec* spec : ParamsOf(ElementKind::kSettings)) {
    const ElementIndex settings = ElementIndex::Settings();
    if (spec->klampt || spec->get(world_, settings) != spec->get(defaults, settings)) {
      rows.push_back(spec);
    }
  }
  return RowAttributes(rows, ElementIndex::Settings());
}

// Klamp't's rows always; Lamina's body rows (kRollingFriction, kSpinningFriction) only when on,
// so that a world without them is written exactly as before and stays a Klamp't world
std::vector<const ParamSpec*> WorldWriter::BodyRows(std::vector<const ParamSpec*> rows,
                                                    const ElementIndex& element) const {
  std::erase_if(rows, [&](const ParamSpec* spec) {
    return !spec->klampt && spec->get(world_, element) == ParamValue{0.0};
  });
  return rows;
}

void WorldWriter::WriteTerrain(const TerrainDesc& terrain) {
  Attributes attributes{{"name", terrain.name}};
  const Attributes geometry = GeometryAttributes("file", terrain.geometry);
  attributes.insert(attributes.end(), geometry.begin(), geometry.end());
  Element("terrain", attributes, false);
  WriteDisplay(terrain.display);
  printer_.CloseElement();
}

void WorldWriter::WriteObject(const RigidObjectDesc& object, int index) {
  Attributes attributes{{"name", object.name}};
  if (!IsRotation(object.pose.linear())) {
    files_.errors.push_back("objects[" + std::to_string(index) +
                            "].transform: the rotation is not a rotation matrix, which world XML "
                            "(rotateMoment) cannot hold");
  }
  const Attributes pose = PoseAttributes(object.pose);
  attributes.insert(attributes.end(), pose.begin(), pose.end());
  Element("rigidObject", attributes, false);
  Element("geometry", GeometryAttributes("mesh", object.geometry));
  std::vector<const ParamSpec*> rows;
  for (const char* key : {"mass", "com", "inertia"}) {
    rows.push_back(FindParam(key, ElementKind::kObject));
  }
  for (const ParamSpec* spec : SurfaceRows()) rows.push_back(spec);
  const ElementIndex element = ElementIndex::Object(index);
  Element("physics", RowAttributes(BodyRows(rows, element), element));
  WriteDisplay(object.display);
  printer_.CloseElement();
}

// gives every primitive without a file its own `.geom` file beside the robot file
RobotDesc WorldWriter::WithPrimitiveFiles(const RobotDesc& robot, const std::string& rob_path) {
  RobotDesc copy = robot;
  for (size_t link = 0; link < copy.links.size(); ++link) {
    std::vector<GeometryDesc>& pieces = copy.links[link].geometry;
    for (size_t k = 0; k < pieces.size(); ++k) {
      if (pieces[k].kind != GeometryKind::kPrimitive || !pieces[k].path.empty()) continue;
      const auto text = WriteGeomText(pieces[k].primitive);
      if (!text) {
        files_.errors.push_back("robot '" + robot.name + "' link " + std::to_string(link) + ": a " +
                                pieces[k].primitive.TypeName() +
                                " cannot be written as a .geom file");
        continue;
      }
      pieces[k].path = rob_path.substr(0, rob_path.size() - 4) + "_link" + std::to_string(link) +
                       "_" + std::to_string(k) + ".geom";
      files_.geometry_files.emplace_back(pieces[k].path, *text);
    }
  }
  return copy;
}

void WorldWriter::WriteRobot(const RobotDesc& robot, std::set<std::string>* used_names) {
  const std::string relative = robots_dir_name_ + "/" + RobotFileName(robot.name, used_names);
  const std::string rob_path = ResolvePath(dir_, relative);
  std::vector<std::string> errors;
  files_.robot_files.emplace_back(
      rob_path, WriteRob(WithPrimitiveFiles(robot, rob_path), DirectoryOf(rob_path), &errors));
  const std::string path = "robots[" + std::to_string(files_.robot_files.size() - 1) + "].";
  for (const std::string& error : errors) files_.errors.push_back(path + error);
  Attributes attributes{{"name", robot.name}, {"file", relative}};
  // as held (a config of the wrong size is written too, and the reader reports it)
  if (robot.config.size() > 0) attributes.emplace_back("config", FormatCountedVector(robot.config));
  // Lamina's attribute, only when a robot starts moving (or holds a velocity of another size,
  // which the reader then reports)
  if (!robot.velocity.isZero(0.0) ||
      (robot.velocity.size() > 0 && robot.velocity.size() != robot.dof())) {
    attributes.emplace_back("velocity", FormatCountedVector(robot.velocity));
  }
  Element("robot", attributes, false);
  for (const auto& [link, display] : robot.link_display) WriteDisplay(display, link);
  printer_.CloseElement();
}

void WorldWriter::WriteBodyParams(const char* kind, const ElementIndex& element,
                                  const std::string& body) {
  Attributes reference{{"index", std::to_string(element.index)}};
  if (!body.empty()) reference.emplace_back("body", body);
  Element(kind, reference, false);
  Element("geometry", RowAttributes(BodyRows(BodyGeometryRows(), element), element));
}

// `<joint>` with the bodies it holds as references by index, as the reader reads them back
void WorldWriter::WriteJoint(const WorldJointDesc& joint) {
  Attributes attributes{{"type", WorldJointTypeName(joint.type)}};
  if (joint.type == WorldJointType::kHinge) {
    attributes.emplace_back("point", FormatDoubles(joint.point.data(), 3));
  }
  if (joint.type != WorldJointType::kFixed) {
    attributes.emplace_back("axis", FormatDoubles(joint.axis.data(), 3));
  }
  if (joint.min != -kInf) attributes.emplace_back("min", FormatDouble(joint.min));
  if (joint.max != kInf) attributes.emplace_back("max", FormatDouble(joint.max));
  if (joint.friction != 0.0) attributes.emplace_back("friction", FormatDouble(joint.friction));
  Element("joint", attributes, false);
  for (const WorldJointBody& body : joint.bodies) {
    Attributes reference{{"index", std::to_string(body.index)}};
    if (body.kind == WorldId::Kind::kRobotLink) {
      reference.emplace_back("body", std::to_string(body.link));
    }
    const bool terrain = body.kind == WorldId::Kind::kTerrain;
    const bool object = body.kind == WorldId::Kind::kRigidObject;
    Element(terrain ? "terrain" : object ? "rigidObject" : "robot", reference);
  }
  printer_.CloseElement();
}

void WorldWriter::WriteSimulation() {
  Element("simulation", {}, false);
  Element("globals", GlobalsAttributes());
  for (size_t i = 0; i < world_.terrains.size(); ++i) {
    WriteBodyParams("terrain", ElementIndex::Terrain(static_cast<int>(i)));
    printer_.CloseElement();
  }
  const ParamSpec& velocity = *FindParam("velocity", ElementKind::kObject);
  for (size_t i = 0; i < world_.objects.size(); ++i) {
    const ElementIndex object = ElementIndex::Object(static_cast<int>(i));
    WriteBodyParams("object", object);
    const ParamValue twist = velocity.get(world_, object);  // angular, then linear
    Element("velocity", {{"linear", FormatDoubles(twist.data() + 3, 3)},
                         {"angular", FormatDoubles(twist.data(), 3)}});
    printer_.CloseElement();
  }
  for (size_t r = 0; r < world_.robots.size(); ++r) {
    const RobotDesc& robot = world_.robots[r];
    const bool uniform =
        std::all_of(robot.links.begin(), robot.links.end(),
                    [&](const LinkDesc& l) { return l.sim == robot.links.front().sim; });
    for (int link = 0; link < robot.dof(); ++link) {
      if (uniform && link > 0) break;
      WriteBodyParams("robot", ElementIndex::Link(static_cast<int>(r), link),
                      uniform ? "-1" : std::to_string(link));
      printer_.CloseElement();
    }
  }
  for (const WorldJointDesc& joint : world_.joints) WriteJoint(joint);
  for (const std::string& xml : world_.preserved_simulation_xml) {
    tinyxml2::XMLDocument fragment;
    if (fragment.Parse(xml.c_str()) == tinyxml2::XML_SUCCESS && fragment.RootElement()) {
      fragment.RootElement()->Accept(&printer_);
    }
  }
  printer_.CloseElement();
}

}  // namespace

WorldFileSet WriteWorld(const WorldDesc& world, const std::string& path) {
  return WorldWriter(world, path).Write();
}

bool SaveWorldFile(const WorldDesc& world, const std::string& path, Diagnostics& diagnostics) {
  const std::string absolute = ResolvePath(".", path);
  const WorldFileSet files = WriteWorld(world, absolute);
  for (const std::string& error : files.errors) diagnostics.Error({absolute, 0, 0}, error);
  if (!files.errors.empty()) return false;
  if (!std::filesystem::is_directory(DirectoryOf(absolute))) {
    diagnostics.Error({absolute, 0, 0},
                      "cannot save: directory '" + DirectoryOf(absolute) + "' does not exist");
    return false;
  }
  std::string error;
  for (const auto* group : {&files.geometry_files, &files.robot_files}) {
    for (const auto& [file_path, text] : *group) {
      std::error_code ignored;
      std::filesystem::create_directories(DirectoryOf(file_path), ignored);
      if (!WriteFileAtomically(file_path, text, &error)) {
        diagnostics.Error({file_path, 0, 0}, error);
        return false;
      }
    }
  }
  if (!WriteFileAtomically(absolute, files.world_xml, &error)) {
    diagnostics.Error({absolute, 0, 0}, error);
    return false;
  }
  return true;
}

}  // namespace lamina::core
