// SPDX-License-Identifier: MIT
// The tinyxml2 pass over a URDF: elements by name for line numbers, the link checks, and
// Klamp't's <klampt> extension.
#include "core/io/urdf_xml.h"

#include <sstream>

#include "core/io/paths.h"
#include "core/io/xml_element_reader.h"

namespace lamina::core::urdf_io {

namespace {

using tinyxml2::XMLElement;

std::vector<std::string> XmlWords(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// tinyxml2's "Error=XML_ERROR_X ErrorID=.. Line number=..: detail" without the repetition
std::string XmlErrorText(const tinyxml2::XMLDocument& document) {
  std::string text = document.ErrorStr();
  const size_t marker = text.find("Line number=");
  if (marker != std::string::npos) {
    const size_t colon = text.find(": ", marker);
    const std::string detail = colon == std::string::npos ? "" : text.substr(colon + 2);
    text = std::string(document.ErrorName()) + (detail.empty() ? "" : ": " + detail);
  }
  return text;
}

bool ReadLinks(const XMLElement& robot, const std::string& path, Diagnostics& diagnostics,
               UrdfXml* out) {
  bool ok = true;
  for (const XMLElement* link = robot.FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    const SourceLocation where{path, link->GetLineNum(), 0};
    const char* name = link->Attribute("name");
    if (!name) {
      diagnostics.Error(where, "<link> has no 'name' attribute");
      ok = false;
    } else if (out->links.count(name) != 0) {
      diagnostics.Error(where, "link '" + std::string(name) + "' is defined twice (first on line " +
                                   std::to_string(out->links[name]->GetLineNum()) + ")");
      ok = false;
    } else {
      out->links[name] = link;
    }
  }
  return ok;
}

bool CheckJointLinks(const XMLElement& joint, const std::string& joint_name,
                     const std::string& path, Diagnostics& diagnostics, const UrdfXml& xml) {
  bool ok = true;
  for (const char* role : {"parent", "child"}) {
    const XMLElement* element = joint.FirstChildElement(role);
    const char* link = element ? element->Attribute("link") : nullptr;
    if (!link) {
      diagnostics.Error({path, joint.GetLineNum(), 0},
                        "joint '" + joint_name + "' has no <" + role + " link=...>");
      ok = false;
    } else if (xml.links.count(link) == 0) {
      diagnostics.Error({path, element->GetLineNum(), 0}, "joint '" + joint_name + "' names " +
                                                              role + " link '" + link +
                                                              "', which is not defined");
      ok = false;
    }
  }
  return ok;
}

bool ReadJoints(const XMLElement& robot, const std::string& path, Diagnostics& diagnostics,
                UrdfXml* out) {
  bool ok = true;
  for (const XMLElement* joint = robot.FirstChildElement("joint"); joint;
       joint = joint->NextSiblingElement("joint")) {
    const char* name = joint->Attribute("name");
    if (!name) {
      diagnostics.Error({path, joint->GetLineNum(), 0}, "<joint> has no 'name' attribute");
      ok = false;
      continue;
    }
    out->joints.emplace(name, joint);
    ok = CheckJointLinks(*joint, name, path, diagnostics, *out) && ok;
  }
  return ok;
}

std::optional<Mat3> DefaultInertia(const XmlElementReader& reader) {
  const auto text = reader.String("default_inertia");
  if (!text) return std::nullopt;
  const size_t count = XmlWords(*text).size();
  if (count == 1) {
    const auto value = reader.Number("default_inertia");
    if (value) return Mat3(Mat3::Identity() * *value);
  } else if (count == 3) {
    const auto values = reader.Vector3("default_inertia");
    if (values) return Mat3(values->asDiagonal());
  } else {
    const auto values = reader.Numbers("default_inertia", 9);
    if (values)
      return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(values->data());
  }
  return std::nullopt;
}

// `sensors` / `controller`: an .xml file named by the attribute, or a child element
void ReadProperty(const XmlElementReader& reader, const char* name, const std::string& path,
                  KlamptExtras* out) {
  if (const auto value = reader.String(name)) {
    const std::string file = ResolvePath(DirectoryOf(path), *value);
    if (!ReadFileText(file, &out->properties[name])) {
      reader.Error(name, "names '" + file + "', which cannot be read");
      out->properties.erase(name);
    }
    if (std::string(name) == "sensors") out->sensors_at = {file, 1, 0};
    return;
  }
  if (const XMLElement* child = reader.element().FirstChildElement(name)) {
    tinyxml2::XMLPrinter printer(nullptr, true);
    child->Accept(&printer);
    out->properties[name] = printer.CStr();
    if (std::string(name) == "sensors") out->sensors_at = {path, child->GetLineNum(), 0};
  }
}

void ReadLinkSettings(const XMLElement& element, const std::string& path, Diagnostics& diagnostics,
                      KlamptExtras* out) {
  const XmlElementReader reader(element, path, diagnostics);
  reader.WarnUnknownAttributes({"name", "physical", "servoP", "servoI", "servoD", "dryFriction",
                                "viscousFriction", "accMax"});
  const auto name = reader.String("name");
  if (!name) {
    reader.Error("has no 'name' attribute");
    return;
  }
  KlamptLinkSettings& settings = out->links[*name];
  settings.line = element.GetLineNum();
  if (const auto physical = reader.Boolean("physical")) settings.physical = *physical;
  settings.servo_p = reader.Number("servoP");
  settings.servo_i = reader.Number("servoI");
  settings.servo_d = reader.Number("servoD");
  settings.dry_friction = reader.Number("dryFriction");
  settings.viscous_friction = reader.Number("viscousFriction");
  settings.acceleration_max = reader.Number("accMax");
}

void ReadPairs(const XMLElement& element, const std::string& path, Diagnostics& diagnostics,
               std::vector<rob::PairStatement>* pairs) {
  const XmlElementReader reader(element, path, diagnostics);
  reader.WarnUnknownAttributes({"pairs", "group1", "group2"});
  const int line = element.GetLineNum();
  if (const auto text = reader.String("pairs")) {
    const std::vector<std::string> names = XmlWords(*text);
    if (names.size() % 2 != 0) {
      reader.Error("pairs",
                   "expects pairs of links, got " + std::to_string(names.size()) + " names");
      return;
    }
    for (size_t i = 0; i < names.size(); i += 2) pairs->push_back({names[i], names[i + 1], line});
  } else if (reader.Has("group1") && reader.Has("group2")) {
    for (const std::string& first : XmlWords(*reader.String("group1"))) {
      for (const std::string& second : XmlWords(*reader.String("group2"))) {
        pairs->push_back({first, second, line});
      }
    }
  } else {
    reader.Error("expects a 'pairs' attribute or both 'group1' and 'group2'");
  }
}

void ReadMount(const XMLElement& element, const std::string& path, Diagnostics& diagnostics,
               std::vector<rob::MountStatement>* mounts) {
  const XmlElementReader reader(element, path, diagnostics);
  reader.WarnUnknownAttributes({"link", "file", "transform", "prefix", "as"});
  rob::MountStatement mount;
  mount.line = element.GetLineNum();
  const auto link = reader.String("link");
  const auto file = reader.String("file");
  if (!link || !file) {
    reader.Error("expects 'link' and 'file' attributes");
    return;
  }
  mount.link = *link;
  mount.file = *file;
  if (reader.Has("transform")) {
    const auto numbers = reader.Numbers("transform", 12);
    if (!numbers) return;
    mount.transform = PoseFromKlamptNumbers(numbers->data());
  }
  mount.prefix = reader.String("as").value_or(reader.String("prefix").value_or(""));
  mounts->push_back(mount);
}

void ReadKlamptAttributes(const XmlElementReader& reader, const std::string& path,
                          KlamptExtras* out) {
  reader.WarnUnknownAttributes({"world_frame", "package_root", "use_vis_geom", "flip_yz",
                                "freeze_root_link", "default_acc_max", "default_mass",
                                "default_inertia", "sensors", "controller"});
  out->world_frame = reader.String("world_frame").value_or(out->world_frame);
  if (const auto root = reader.String("package_root")) {
    out->package_root = ResolvePath(DirectoryOf(path), *root);
  }
  out->use_visual_geometry = reader.Boolean("use_vis_geom").value_or(false);
  out->freeze_root_link = reader.Boolean("freeze_root_link").value_or(false);
  if (reader.Boolean("flip_yz").value_or(false)) {
    reader.Warning("'flip_yz' is not supported; meshes are used as they are");
  }
  out->default_acc_max = reader.Number("default_acc_max").value_or(out->default_acc_max);
  out->default_mass = reader.Number("default_mass");
  out->default_inertia = DefaultInertia(reader);
  for (const char* name : {"sensors", "controller"}) {
    ReadProperty(reader, name, path, out);
  }
}

}  // namespace

int UrdfXml::LinkLine(const std::string& name) const {
  const auto found = links.find(name);
  return found == links.end() ? robot_line : found->second->GetLineNum();
}

int UrdfXml::JointLine(const std::string& name) const {
  const auto found = joints.find(name);
  return found == joints.end() ? robot_line : found->second->GetLineNum();
}

std::vector<int> UrdfXml::GeometryLines(const std::string& name, const char* kind) const {
  std::vector<int> lines;
  const auto found = links.find(name);
  if (found == links.end()) return lines;
  for (const XMLElement* element = found->second->FirstChildElement(kind); element;
       element = element->NextSiblingElement(kind)) {
    const XMLElement* geometry = element->FirstChildElement("geometry");
    const XMLElement* shape = geometry ? geometry->FirstChildElement() : nullptr;
    lines.push_back(shape ? shape->GetLineNum() : element->GetLineNum());
  }
  return lines;
}

bool ReadUrdfXml(const std::string& text, const std::string& path, Diagnostics& diagnostics,
                 UrdfXml* out) {
  tinyxml2::XMLDocument& document = out->document;
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    diagnostics.Error({path, document.ErrorLineNum(), 0}, "XML: " + XmlErrorText(document));
    return false;
  }
  const XMLElement* robot = document.RootElement();
  if (robot == nullptr || std::string(robot->Name()) != "robot") {
    diagnostics.Error(
        {path, robot ? robot->GetLineNum() : 0, 0},
        "expected a <robot> root element, got <" + std::string(robot ? robot->Name() : "") + ">");
    return false;
  }
  out->robot_line = robot->GetLineNum();
  const bool links_ok = ReadLinks(*robot, path, diagnostics, out);
  return ReadJoints(*robot, path, diagnostics, out) && links_ok;
}

void ReadKlamptExtras(const UrdfXml& xml, const std::string& path, Diagnostics& diagnostics,
                      KlamptExtras* out) {
  const XMLElement* klampt = xml.document.RootElement()->FirstChildElement("klampt");
  if (klampt == nullptr) return;
  const XmlElementReader reader(*klampt, path, diagnostics);
  ReadKlamptAttributes(reader, path, out);
  for (const XMLElement* child = klampt->FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    const std::string name = child->Name();
    if (name == "link") {
      ReadLinkSettings(*child, path, diagnostics, out);
    } else if (name == "selfcollision") {
      ReadPairs(*child, path, diagnostics, &out->self_collision);
    } else if (name == "noselfcollision") {
      ReadPairs(*child, path, diagnostics, &out->no_self_collision);
    } else if (name == "mount") {
      ReadMount(*child, path, diagnostics, &out->mounts);
    } else if (name != "sensors" && name != "controller") {
      diagnostics.Warning({path, child->GetLineNum(), 0},
                          "<klampt>: unknown element <" + name + "> ignored");
    }
  }
}

}  // namespace lamina::core::urdf_io
