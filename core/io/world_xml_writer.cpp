// SPDX-License-Identifier: MIT
// Writing a WorldDesc as Klamp't world XML (plus one `.rob` per robot) such that loading the
// result gives the same description.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include <tinyxml2.h>

#include "core/io/geometry_file.h"
#include "core/io/paths.h"
#include "core/io/robot_file.h"
#include "core/io/text_statements.h"
#include "core/io/world_file.h"
#include "core/io/world_xml_transform.h"

namespace lamina::core {

namespace {

using Attributes = std::vector<std::pair<std::string, std::string>>;

std::string Format3(const Vec3& v) {
  return FormatDoubles(v.data(), 3);
}

std::string FormatMatrixRowMajor(const Mat3& m) {
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> row_major = m;
  return FormatDoubles(row_major.data(), 9);
}

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
  void WriteObject(const RigidObjectDesc& object);
  void WriteRobot(const RobotDesc& robot, std::set<std::string>* used_names);
  RobotDesc WithPrimitiveFiles(const RobotDesc& robot, const std::string& rob_path);
  void WriteSimulation();
  void WriteBodyParams(const char* kind, int index, const BodySimParams& params,
                       const std::string& body = "");
  Attributes GeometryAttributes(const char* file_key, const GeometryDesc& geometry);
  Attributes SurfaceAttributes(const SurfaceDesc& surface);

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
  for (const RigidObjectDesc& object : world_.objects) WriteObject(object);
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

Attributes WorldWriter::SurfaceAttributes(const SurfaceDesc& surface) {
  return {{"kRestitution", FormatDouble(surface.restitution)},
          {"kFriction", FormatDouble(surface.friction)},
          {"kStiffness", FormatDouble(surface.stiffness)},
          {"kDamping", FormatDouble(surface.damping)}};
}

void WorldWriter::WriteTerrain(const TerrainDesc& terrain) {
  Attributes attributes{{"name", terrain.name}};
  const Attributes geometry = GeometryAttributes("file", terrain.geometry);
  attributes.insert(attributes.end(), geometry.begin(), geometry.end());
  Element("terrain", attributes, false);
  WriteDisplay(terrain.display);
  printer_.CloseElement();
}

void WorldWriter::WriteObject(const RigidObjectDesc& object) {
  Attributes attributes{{"name", object.name}};
  const Attributes pose = PoseAttributes(object.pose);
  attributes.insert(attributes.end(), pose.begin(), pose.end());
  Element("rigidObject", attributes, false);
  Element("geometry", GeometryAttributes("mesh", object.geometry));
  Attributes physics{{"mass", FormatDouble(object.mass)},
                     {"com", Format3(object.com)},
                     {"inertia", FormatMatrixRowMajor(object.inertia)}};
  const Attributes surface = SurfaceAttributes(object.sim.surface);
  physics.insert(physics.end(), surface.begin(), surface.end());
  Element("physics", physics);
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
  files_.robot_files.emplace_back(
      rob_path, WriteRob(WithPrimitiveFiles(robot, rob_path), DirectoryOf(rob_path)));
  Attributes attributes{{"name", robot.name}, {"file", relative}};
  if (robot.config.size() == robot.dof()) {
    attributes.emplace_back("config", FormatCountedVector(robot.config));
  }
  Element("robot", attributes, false);
  for (const auto& [link, display] : robot.link_display) WriteDisplay(display, link);
  printer_.CloseElement();
}

void WorldWriter::WriteBodyParams(const char* kind, int index, const BodySimParams& params,
                                  const std::string& body) {
  Attributes reference{{"index", std::to_string(index)}};
  if (!body.empty()) reference.emplace_back("body", body);
  Element(kind, reference, false);
  Attributes geometry{{"padding", FormatDouble(params.padding)},
                      {"preshrink", std::to_string(static_cast<int>(params.preshrink))}};
  const Attributes surface = SurfaceAttributes(params.surface);
  geometry.insert(geometry.end(), surface.begin(), surface.end());
  Element("geometry", geometry);
}

void WorldWriter::WriteSimulation() {
  const SimSettings& s = world_.settings;
  Element("simulation", {}, false);
  Element("globals", {{"timestep", FormatDouble(s.timestep)},
                      {"gravity", Format3(s.gravity)},
                      {"ERP", FormatDouble(s.erp)},
                      {"CFM", FormatDouble(s.cfm)},
                      {"maxContacts", std::to_string(s.max_contacts)},
                      {"adaptiveTimeStepping", s.adaptive_time_stepping ? "1" : "0"},
                      {"rigidObjectCollisions", s.rigid_object_collisions ? "1" : "0"},
                      {"robotSelfCollisions", s.robot_self_collisions ? "1" : "0"},
                      {"robotRobotCollisions", s.robot_robot_collisions ? "1" : "0"}});
  for (size_t i = 0; i < world_.terrains.size(); ++i) {
    WriteBodyParams("terrain", static_cast<int>(i), world_.terrains[i].sim);
    printer_.CloseElement();
  }
  for (size_t i = 0; i < world_.objects.size(); ++i) {
    const RigidObjectDesc& object = world_.objects[i];
    WriteBodyParams("object", static_cast<int>(i), object.sim);
    Element("velocity", {{"linear", Format3(object.initial_velocity.linear)},
                         {"angular", Format3(object.initial_velocity.angular)}});
    printer_.CloseElement();
  }
  for (size_t r = 0; r < world_.robots.size(); ++r) {
    const RobotDesc& robot = world_.robots[r];
    const bool uniform =
        std::all_of(robot.links.begin(), robot.links.end(),
                    [&](const LinkDesc& l) { return l.sim == robot.links.front().sim; });
    for (int link = 0; link < robot.dof(); ++link) {
      if (uniform && link > 0) break;
      WriteBodyParams("robot", static_cast<int>(r), robot.links[link].sim,
                      uniform ? "-1" : std::to_string(link));
      printer_.CloseElement();
    }
  }
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
