// SPDX-License-Identifier: MIT
// URDF robots: parsed by urdfdom, converted the way Klamp't's Robot::LoadURDF does it
// (links in depth-first order, a root link that is not the world frame gets a 6-DOF floating
// base, one normal driver per moving joint with Klamp't's import gains), with the `<klampt>`
// extension and located diagnostics from a tinyxml2 pass over the same text.
#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "core/io/geometry_file.h"
#include "core/io/param_text.h"
#include "core/io/paths.h"
#include "core/io/rob_statements.h"
#include "core/io/robot_file.h"
#include "core/io/text_statements.h"
#include "core/io/urdf_xml.h"
#include "core/sensors/robot_sensors.h"

namespace lamina::core {

namespace rob {

namespace {

// Klamp't's floating-base convention: x, y, z translations, then yaw, pitch and roll
const std::vector<std::pair<LinkJointAxis, Vec3>>& FloatingBaseAxes() {
  static const std::vector<std::pair<LinkJointAxis, Vec3>> axes = {
      {LinkJointAxis::kPrismatic, Vec3::UnitX()}, {LinkJointAxis::kPrismatic, Vec3::UnitY()},
      {LinkJointAxis::kPrismatic, Vec3::UnitZ()}, {LinkJointAxis::kRevolute, Vec3::UnitZ()},
      {LinkJointAxis::kRevolute, Vec3::UnitY()},  {LinkJointAxis::kRevolute, Vec3::UnitX()}};
  return axes;
}

using urdf_io::KlamptExtras;
using urdf_io::KlamptLinkSettings;
using urdf_io::UrdfXml;

// Klamp't's URDF import gains (Robot::LoadURDF: driver.servoP = 100, servoI = 0, servoD = 10)
constexpr double kDefaultServoP = 100.0;
constexpr double kDefaultServoI = 0.0;
constexpr double kDefaultServoD = 10.0;

// collects urdfdom's console_bridge messages while it parses (console_bridge's handler is
// process-wide: parse one URDF at a time)
class CapturedLog : public console_bridge::OutputHandler {
 public:
  CapturedLog() { console_bridge::useOutputHandler(this); }
  ~CapturedLog() override { console_bridge::restorePreviousOutputHandler(); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    messages.emplace_back(level, text);
  }
  std::vector<std::pair<console_bridge::LogLevel, std::string>> messages;
};

std::string Trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

urdf::ModelInterfaceSharedPtr ParseWithUrdfdom(const std::string& text, const std::string& path,
                                               int robot_line, Diagnostics& diagnostics) {
  const int errors_before = diagnostics.error_count();
  urdf::ModelInterfaceSharedPtr model;
  CapturedLog log;
  model = urdf::parseURDF(text);
  for (const auto& [level, message] : log.messages) {
    const SourceLocation where{path, robot_line, 0};
    if (level == console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      diagnostics.Error(where, "urdfdom: " + Trimmed(message));
    } else if (level == console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      diagnostics.Warning(where, "urdfdom: " + Trimmed(message));
    }
  }
  if (!model && diagnostics.error_count() == errors_before) {
    diagnostics.Error({path, robot_line, 0}, "urdfdom could not read the robot");
  }
  return model;
}

Vec3 ToVec3(const urdf::Vector3& v) {
  return {v.x, v.y, v.z};
}

Pose ToPose(const urdf::Pose& pose) {
  Pose out = Pose::Identity();
  out.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  out.translation() = ToVec3(pose.position);
  return out;
}

// two unit vectors spanning the plane normal to `normal`
std::pair<Vec3, Vec3> PlaneAxes(const Vec3& normal) {
  const Vec3 n = normal.normalized();
  const Vec3 seed = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = (seed - seed.dot(n) * n).normalized();
  return {u, n.cross(u)};
}

class UrdfConverter {
 public:
  UrdfConverter(const UrdfXml& xml, const KlamptExtras& extras, const std::string& path,
                LoadContext& context, RobotDesc* robot)
      : xml_(xml), extras_(extras), path_(path), context_(context), robot_(*robot) {}

  void Convert(const urdf::ModelInterface& model);
  void ApplyMimicJoints(const urdf::ModelInterface& model);
  void WarnUnknownLinkSettings() const;

 private:
  void Error(int line, const std::string& message) const {
    context_.diagnostics.Error({path_, line, 0}, message);
  }
  // the table's row `key` of `kind` checks `value`; a refusal is reported at `line`
  bool CheckRow(int line, const std::string& what, std::string_view key, ElementKind kind,
                const ParamValue& value) const {
    const std::optional<std::string> refusal = RefuseRow(key, kind, value);
    if (refusal) Error(line, what + " " + *refusal);
    return !refusal;
  }
  void CheckJointLimits(const urdf::Joint& joint, const LinkDesc& link) const;
  void CheckDriver(const DriverDesc& driver, const std::string& link_name, int joint_line) const;
  const KlamptLinkSettings* Settings(const std::string& name) const {
    const auto found = extras_.links.find(name);
    return found == extras_.links.end() ? nullptr : &found->second;
  }
  void AddTree(const urdf::Link& link, int parent);
  int AddJointLinks(const urdf::Link& link, const urdf::Joint& joint, int parent);
  int AddVirtualChain(const std::string& name, int parent, const Pose& origin,
                      const std::vector<std::pair<LinkJointAxis, Vec3>>& axes, JointType joint_type,
                      LinkDesc* last);
  int AddLink(LinkDesc link);
  LinkDesc MakeLink(const urdf::Link& link) const;
  void SetMass(const urdf::Link& link, LinkDesc* out) const;
  void LoadGeometry(const urdf::Link& link, LinkDesc* out) const;
  GeometryDesc ConvertGeometry(const urdf::Geometry& geometry, int line) const;
  void AddDriver(int index, const urdf::Joint& joint, const std::string& link_name);

  const UrdfXml& xml_;
  const KlamptExtras& extras_;
  const std::string& path_;
  LoadContext& context_;
  RobotDesc& robot_;
  std::map<std::string, int> link_index_;  // URDF link name -> robot link
};

int UrdfConverter::AddLink(LinkDesc link) {
  link.sim = DefaultLinkSimParams();
  robot_.links.push_back(std::move(link));
  return robot_.dof() - 1;
}

LinkDesc UrdfConverter::MakeLink(const urdf::Link& link) const {
  LinkDesc out;
  out.name = link.name;
  SetMass(link, &out);
  LoadGeometry(link, &out);
  return out;
}

void UrdfConverter::SetMass(const urdf::Link& link, LinkDesc* out) const {
  const KlamptLinkSettings* settings = Settings(link.name);
  out->com = Vec3::Zero();
  if (settings != nullptr && !settings->physical) {  // Klamp't's virtual link
    out->mass = 0.0;
    out->inertia.setZero();
  } else if (link.inertial) {
    const urdf::Inertial& inertial = *link.inertial;
    out->mass = inertial.mass;
    out->com = ToVec3(inertial.origin.position);
    Mat3 tensor;
    tensor << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
        inertial.ixz, inertial.iyz, inertial.izz;
    // the tensor is given in the inertial frame; rotate it into the link frame
    const Mat3 rotation = ToPose(inertial.origin).linear();
    out->inertia = rotation * tensor * rotation.transpose();
    const int line = xml_.LinkLine(link.name);
    const std::string of_link = " of link '" + link.name + "'";
    CheckRow(line, "mass" + of_link, "mass", ElementKind::kLink, {out->mass});
    CheckRow(line, "inertia" + of_link + " (<inertia>)", "inertia", ElementKind::kLink,
             {inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
              inertial.ixz, inertial.iyz, inertial.izz});
  } else {
    out->mass = extras_.default_mass.value_or(0.0);
    out->inertia = extras_.default_inertia.value_or(Mat3::Zero());
  }
}

GeometryDesc UrdfConverter::ConvertGeometry(const urdf::Geometry& geometry, int line) const {
  GeometryDesc out;
  switch (geometry.type) {
    case urdf::Geometry::SPHERE:
      out.kind = GeometryKind::kPrimitive;
      out.primitive = Primitive::Sphere(static_cast<const urdf::Sphere&>(geometry).radius);
      break;
    case urdf::Geometry::BOX:
      out.kind = GeometryKind::kPrimitive;
      out.primitive = Primitive::Box(ToVec3(static_cast<const urdf::Box&>(geometry).dim));
      break;
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      out.kind = GeometryKind::kPrimitive;
      out.primitive = Primitive::Cylinder(cylinder.radius, cylinder.length);
      break;
    }
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      std::string error;
      const std::string file =
          urdf_io::ResolveMeshFile(mesh.filename, DirectoryOf(path_), extras_.package_root, &error);
      if (file.empty()) {
        Error(line, error);
      } else if (LoadGeometryFile(file, {path_, line, 0}, context_, &out)) {
        out.scale = ToVec3(mesh.scale);
      }
      break;
    }
  }
  return out;
}

void UrdfConverter::LoadGeometry(const urdf::Link& link, LinkDesc* out) const {
  std::vector<std::pair<urdf::GeometrySharedPtr, urdf::Pose>> shapes;
  for (const urdf::CollisionSharedPtr& collision : link.collision_array) {
    if (collision && collision->geometry)
      shapes.emplace_back(collision->geometry, collision->origin);
  }
  const char* kind = "collision";
  if (extras_.use_visual_geometry || shapes.empty()) {
    if (shapes.empty() && !link.visual_array.empty() && !extras_.use_visual_geometry) {
      context_.diagnostics.Note(
          {path_, xml_.LinkLine(link.name), 0},
          "link '" + link.name + "' has no <collision>; its <visual> geometry is used");
    }
    shapes.clear();
    kind = "visual";
    for (const urdf::VisualSharedPtr& visual : link.visual_array) {
      if (visual && visual->geometry) shapes.emplace_back(visual->geometry, visual->origin);
    }
  }
  const std::vector<int> lines = xml_.GeometryLines(link.name, kind);
  for (size_t i = 0; i < shapes.size(); ++i) {
    const int line = i < lines.size() ? lines[i] : xml_.LinkLine(link.name);
    GeometryDesc geometry = ConvertGeometry(*shapes[i].first, line);
    geometry.transform = Affine(ToPose(shapes[i].second).matrix());
    out->geometry.push_back(std::move(geometry));
  }
}

int UrdfConverter::AddVirtualChain(const std::string& name, int parent, const Pose& origin,
                                   const std::vector<std::pair<LinkJointAxis, Vec3>>& axes,
                                   JointType joint_type, LinkDesc* last) {
  // virtual links (no mass, no geometry, no actuation); `last` is the real link at the end
  const int base = parent;
  for (size_t i = 0; i + 1 < axes.size(); ++i) {
    LinkDesc virtual_link;
    virtual_link.name = name + std::to_string(i);
    virtual_link.parent = parent;
    virtual_link.parent_transform = i == 0 ? origin : Pose::Identity();
    virtual_link.axis_type = axes[i].first;
    virtual_link.axis = axes[i].second;
    virtual_link.mass = 0.0;
    virtual_link.inertia.setZero();
    virtual_link.torque_max = 0.0;
    parent = AddLink(virtual_link);
  }
  last->parent = parent;
  last->parent_transform = Pose::Identity();
  last->axis_type = axes.back().first;
  last->axis = axes.back().second;
  last->torque_max = 0.0;
  last->power_max = 0.0;
  const int index = AddLink(*last);
  JointDesc joint;
  joint.type = joint_type;
  joint.link = index;
  joint.base = base;
  robot_.joints.push_back(joint);
  return index;
}

int UrdfConverter::AddJointLinks(const urdf::Link& link, const urdf::Joint& joint, int parent) {
  LinkDesc out = MakeLink(link);
  const Pose origin = ToPose(joint.parent_to_joint_origin_transform);
  const Vec3 axis = ToVec3(joint.axis).norm() > 0.0 ? ToVec3(joint.axis) : Vec3::UnitZ();
  if (joint.type == urdf::Joint::FLOATING) {
    return AddVirtualChain(joint.name + "_base", parent, origin, FloatingBaseAxes(),
                           JointType::kFloating, &out);
  }
  if (joint.type == urdf::Joint::PLANAR) {
    const auto [u, v] = PlaneAxes(axis);
    return AddVirtualChain(joint.name + "_base", parent, origin,
                           {{LinkJointAxis::kPrismatic, u},
                            {LinkJointAxis::kPrismatic, v},
                            {LinkJointAxis::kRevolute, axis.normalized()}},
                           JointType::kFloatingPlanar, &out);
  }
  out.parent = parent;
  out.parent_transform = origin;
  out.axis = axis;
  const KlamptLinkSettings* settings = Settings(link.name);
  out.acceleration_max = settings && settings->acceleration_max ? *settings->acceleration_max
                                                                : extras_.default_acc_max;
  if (joint.limits) {
    out.q_min = joint.limits->lower;
    out.q_max = joint.limits->upper;
    out.velocity_min = -joint.limits->velocity;
    out.velocity_max = joint.limits->velocity;
    out.torque_max = joint.limits->effort;
  }
  JointDesc robot_joint;
  robot_joint.type = JointType::kNormal;
  if (joint.type == urdf::Joint::PRISMATIC) out.axis_type = LinkJointAxis::kPrismatic;
  if (joint.type == urdf::Joint::CONTINUOUS) {
    robot_joint.type = JointType::kSpin;
    out.q_min = -kInf;
    out.q_max = kInf;
  }
  if (joint.type == urdf::Joint::FIXED || joint.type == urdf::Joint::UNKNOWN) {
    robot_joint.type = JointType::kWeld;
    out.q_min = out.q_max = 0.0;
    out.velocity_min = out.velocity_max = 0.0;
    out.acceleration_max = 0.0;
  }
  if (joint.limits && robot_joint.type == JointType::kNormal) CheckJointLimits(joint, out);
  robot_joint.link = AddLink(std::move(out));
  robot_.joints.push_back(robot_joint);
  if (robot_joint.type != JointType::kWeld) AddDriver(robot_joint.link, joint, link.name);
  return robot_joint.link;
}

// <limit lower upper velocity effort> as the rows jointLimits, velocityLimits and torqueLimits
void UrdfConverter::CheckJointLimits(const urdf::Joint& joint, const LinkDesc& link) const {
  const int line = xml_.JointLine(joint.name);
  const std::string of_joint = " of joint '" + joint.name + "'";
  CheckRow(line, "jointLimits" + of_joint + " (<limit lower upper>)", "jointLimits",
           ElementKind::kLink, {link.q_min, link.q_max});
  CheckRow(line, "velocityLimits" + of_joint + " (<limit velocity>)", "velocityLimits",
           ElementKind::kDriver, {link.velocity_min, link.velocity_max});
  CheckRow(line, "torqueLimits" + of_joint + " (<limit effort>)", "torqueLimits",
           ElementKind::kDriver, {-link.torque_max, link.torque_max});
}

// gains (Klamp't's <klampt><link servoP ...>) and friction (<dynamics>) as the driver rows
void UrdfConverter::CheckDriver(const DriverDesc& driver, const std::string& link_name,
                                int joint_line) const {
  const KlamptLinkSettings* settings = Settings(link_name);
  const int line = settings ? settings->line : joint_line;
  const std::string of = " of link '" + link_name + "'";
  const std::pair<std::string_view, double> rows[] = {{"servoP", driver.servo_p},
                                                      {"servoI", driver.servo_i},
                                                      {"servoD", driver.servo_d},
                                                      {"dryFriction", driver.dry_friction},
                                                      {"viscousFriction", driver.viscous_friction}};
  for (const auto& [key, value] : rows) {
    std::string what = "'";
    what.append(key).append("'").append(of);
    CheckRow(line, what, key, ElementKind::kDriver, {value});
  }
}

void UrdfConverter::AddDriver(int index, const urdf::Joint& joint, const std::string& link_name) {
  DriverDesc driver;
  driver.name = link_name;
  driver.links = {index};
  CopyLinkLimits(robot_.links[index], &driver);
  driver.servo_p = kDefaultServoP;
  driver.servo_i = kDefaultServoI;
  driver.servo_d = kDefaultServoD;
  if (joint.dynamics) {
    driver.dry_friction = joint.dynamics->friction;
    driver.viscous_friction = joint.dynamics->damping;
  }
  if (const KlamptLinkSettings* settings = Settings(link_name)) {
    driver.servo_p = settings->servo_p.value_or(driver.servo_p);
    driver.servo_i = settings->servo_i.value_or(driver.servo_i);
    driver.servo_d = settings->servo_d.value_or(driver.servo_d);
    driver.dry_friction = settings->dry_friction.value_or(driver.dry_friction);
    driver.viscous_friction = settings->viscous_friction.value_or(driver.viscous_friction);
  }
  CheckDriver(driver, link_name, xml_.JointLine(joint.name));
  robot_.drivers.push_back(std::move(driver));
}

void UrdfConverter::AddTree(const urdf::Link& link, int parent) {
  const int index = AddJointLinks(link, *link.parent_joint, parent);
  link_index_[link.name] = index;
  for (const urdf::LinkSharedPtr& child : link.child_links) AddTree(*child, index);
}

void UrdfConverter::Convert(const urdf::ModelInterface& model) {
  const urdf::LinkConstSharedPtr root = model.getRoot();
  if (root->name == extras_.world_frame) {
    // a fixed base: the world link is dropped and its children are the roots
    if (root->inertial || !root->collision_array.empty() || !root->visual_array.empty()) {
      context_.diagnostics.Warning({path_, xml_.LinkLine(root->name), 0},
                                   "link '" + root->name +
                                       "' is the fixed world frame; its inertial and geometry "
                                       "are ignored");
    }
    for (const urdf::LinkSharedPtr& child : root->child_links) AddTree(*child, -1);
    if (robot_.links.empty()) {
      Error(xml_.LinkLine(root->name),
            "the robot has no links besides the world frame '" + root->name + "'");
    }
    return;
  }
  // a floating base: Klamp't's virtual links x, y, z, yaw, pitch with the root link as roll
  LinkDesc base = MakeLink(*root);
  const int index = AddVirtualChain("base", -1, Pose::Identity(), FloatingBaseAxes(),
                                    JointType::kFloating, &base);
  if (extras_.freeze_root_link) {
    robot_.joints.pop_back();
    for (int i = 0; i <= index; ++i) robot_.joints.push_back({JointType::kWeld, i, -1});
  }
  link_index_[root->name] = index;
  for (const urdf::LinkSharedPtr& child : root->child_links) AddTree(*child, index);
}

// A joint that mimics another (q = multiplier * q_other + offset) loses its driver and joins
// the driver of the joint at the end of its mimic chain, which becomes affine (as Klamp't).
void UrdfConverter::ApplyMimicJoints(const urdf::ModelInterface& model) {
  const auto driver_of = [this](const std::string& link) {
    const auto index = link_index_.find(link);
    return std::find_if(robot_.drivers.begin(), robot_.drivers.end(), [&](const DriverDesc& d) {
      return index != link_index_.end() && d.links.front() == index->second;
    });
  };
  for (const auto& [name, joint] : model.joints_) {
    if (!joint->mimic) continue;
    // q = scale * q_target + offset, following mimics of mimics (a loop stops the walk)
    double scale = 1.0, offset = 0.0;
    urdf::JointConstSharedPtr target = joint;
    for (size_t step = 0; target && target->mimic && step <= model.joints_.size(); ++step) {
      offset += scale * target->mimic->offset;
      scale *= target->mimic->multiplier;
      target = model.getJoint(target->mimic->joint_name);
    }
    const auto own = driver_of(joint->child_link_name);
    const auto other =
        target && !target->mimic ? driver_of(target->child_link_name) : robot_.drivers.end();
    if (own == robot_.drivers.end() || other == robot_.drivers.end()) {
      context_.diagnostics.Warning({path_, xml_.JointLine(name), 0},
                                   "joint '" + name + "' mimics '" + joint->mimic->joint_name +
                                       "', which has no driver; it keeps its own driver");
      continue;
    }
    if (other->type != DriverType::kAffine) {
      other->type = DriverType::kAffine;
      other->affine_scale = {1.0};
      other->affine_offset = {0.0};
      // affine drivers carry no acceleration limit (as in Klamp't and the .rob format)
      other->acceleration_min = -kInf;
      other->acceleration_max = kInf;
    }
    other->links.push_back(own->links.front());
    other->affine_scale.push_back(scale);
    other->affine_offset.push_back(offset);
    robot_.drivers.erase(own);
  }
}

void UrdfConverter::WarnUnknownLinkSettings() const {
  for (const auto& [name, settings] : extras_.links) {
    if (link_index_.count(name) == 0) {
      context_.diagnostics.Warning({path_, settings.line, 0},
                                   "<klampt><link name=\"" + name + "\">: no such link");
    }
  }
}

// <klampt><mount>: a geometry file onto a link, or a .rob/.urdf robot below it
void MountAll(const KlamptExtras& extras, const std::string& path, LoadContext& context,
              RobotFileStack& stack, RobotDesc* robot) {
  for (const MountStatement& mount : extras.mounts) {
    const SourceLocation where{path, mount.line, 0};
    int link = -1;
    if (!FindLink(*robot, mount.link, &link) || link < -1 || link >= robot->dof()) {
      context.diagnostics.Error(where, "'mount' link '" + mount.link + "' is not a link");
      continue;
    }
    const std::string file = ResolvePath(DirectoryOf(path), mount.file);
    const std::string extension = LowerExtension(file);
    if (extension == "rob" || extension == "urdf") {
      RobotDesc sub;
      if (std::find(stack.begin(), stack.end(), file) != stack.end()) {
        context.diagnostics.Error(where,
                                  "'mount' of '" + file + "' would mount a robot inside itself");
      } else if (LoadRobotFileNested(file, where, context, stack, &sub)) {
        MountSubRobot(sub, link, mount.transform, mount.prefix, robot);
      }
      continue;
    }
    GeometryDesc geometry;
    if (link < 0 || !LoadGeometryFile(file, where, context, &geometry)) continue;
    geometry.transform = Affine(mount.transform.matrix());
    std::vector<GeometryDesc>& list = robot->links[link].geometry;
    if (list.empty()) list.emplace_back();
    list.push_back(std::move(geometry));
  }
}

}  // namespace

bool ParseUrdfNested(const std::string& text, const std::string& path, LoadContext& context,
                     RobotFileStack& stack, RobotDesc* out) {
  Diagnostics& diagnostics = context.diagnostics;
  const int errors_before = diagnostics.error_count();
  RobotDesc robot;
  robot.name = StemOf(path);
  robot.source_path = path;
  UrdfXml xml;
  urdf::ModelInterfaceSharedPtr model;
  if (ReadUrdfXml(text, path, diagnostics, &xml)) {
    model = ParseWithUrdfdom(text, path, xml.robot_line, diagnostics);
  }
  if (model) {
    KlamptExtras extras;
    ReadKlamptExtras(xml, path, diagnostics, &extras);
    UrdfConverter converter(xml, extras, path, context, &robot);
    converter.Convert(*model);
    converter.ApplyMimicJoints(*model);
    converter.WarnUnknownLinkSettings();
    robot.config = VecX::Zero(robot.dof());
    robot.velocity = VecX::Zero(robot.dof());
    robot.properties = extras.properties;
    const auto self = ResolvePairs(robot, extras.self_collision, "selfcollision", false, path,
                                   diagnostics, &robot.self_collision);
    const auto no_self = ResolvePairs(robot, extras.no_self_collision, "noselfcollision", false,
                                      path, diagnostics, &robot.no_self_collision);
    stack.push_back(ResolvePath("", path));
    MountAll(extras, path, context, stack, &robot);
    stack.pop_back();
    ResolvePairs(robot, self, "selfcollision", true, path, diagnostics, &robot.self_collision);
    ResolvePairs(robot, no_self, "noselfcollision", true, path, diagnostics,
                 &robot.no_self_collision);
    if (const auto sensors = robot.properties.find("sensors"); sensors != robot.properties.end()) {
      ParseSensorsXml(sensors->second, robot, extras.sensors_at, &diagnostics);
    }
  }
  *out = std::move(robot);
  return diagnostics.error_count() == errors_before;
}

}  // namespace rob

bool ParseUrdf(const std::string& text, const std::string& path, LoadContext& context,
               RobotDesc* out) {
  rob::RobotFileStack stack;
  return rob::ParseUrdfNested(text, path, context, stack, out);
}

}  // namespace lamina::core
