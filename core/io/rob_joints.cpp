// SPDX-License-Identifier: MIT
// `.rob` assembly, second half: joints, drivers and the per-driver servo/friction vectors.
#include <sstream>
#include <string>
#include <vector>

#include "core/io/rob_statements.h"
#include "core/io/text_statements.h"

namespace lamina::core::rob {

namespace {

bool SpansChain(JointType type) {
  return type == JointType::kFloating || type == JointType::kFloatingPlanar ||
         type == JointType::kBallAndSocket;
}

// the links a joint moves, from `link` up to (excluding) `base`; empty after reporting a
// problem
std::vector<int> JointChain(const RobBuild& b, const JointStatement& statement) {
  const JointDesc& joint = statement.joint;
  const int n = b.link_count;
  if (joint.link < 0 || joint.link >= n) {
    b.Error(statement.line, OutOfRangeMessage("joint", joint.link, n));
    return {};
  }
  if (!SpansChain(joint.type)) return {joint.link};
  if (joint.base < -1 || joint.base >= n) {
    b.Error(statement.line, OutOfRangeMessage("joint", joint.base, n));
    return {};
  }
  std::vector<int> chain;
  for (int link = joint.link; link != joint.base; link = b.robot.links[link].parent) {
    if (link < 0) {
      b.Error(statement.line, "joint base " + std::to_string(joint.base) +
                                  " is not an ancestor of link " + std::to_string(joint.link));
      return {};
    }
    chain.push_back(link);
  }
  const size_t expected = joint.type == JointType::kFloating ? 6 : 3;
  const bool bad_count =
      joint.type == JointType::kFloating ? chain.size() > expected : chain.size() != expected;
  if (bad_count) {
    // streamed: GCC 12 at -O3 flags `"'" + std::string` with a false -Wrestrict
    std::ostringstream message;
    message << "'" << JointTypeName(joint.type) << "' joint must span "
            << (joint.type == JointType::kFloating ? "at most " : "") << expected << " links, got "
            << chain.size();
    b.Error(statement.line, message.str());
    return {};
  }
  return chain;
}

std::vector<JointStatement> DefaultJoints(const RobotDesc& robot) {
  std::vector<JointStatement> joints;
  for (int i = 0; i < robot.dof(); ++i) {
    const LinkDesc& link = robot.links[i];
    JointStatement joint;
    joint.joint.link = i;
    const bool fixed_root = link.parent < 0 && link.velocity_min == 0.0 && link.velocity_max == 0.0;
    joint.joint.type = fixed_root ? JointType::kWeld : JointType::kNormal;
    joints.push_back(joint);
  }
  return joints;
}

std::vector<DriverStatement> DefaultDrivers(const RobotDesc& robot) {
  std::vector<DriverStatement> drivers;
  for (const JointDesc& joint : robot.joints) {
    if (joint.type != JointType::kNormal && joint.type != JointType::kSpin) continue;
    DriverStatement driver;
    driver.driver.links = {joint.link};
    drivers.push_back(driver);
  }
  return drivers;
}

// link range and "driven twice" checks; false after reporting a problem
bool CheckDriver(const RobBuild& b, const DriverStatement& statement,
                 std::vector<int>* driven_on_line) {
  const DriverDesc& driver = statement.driver;
  for (int link : driver.links) {
    if (link < 0 || link >= b.link_count) {
      b.Error(statement.line, OutOfRangeMessage("driver", link, b.link_count));
      return false;
    }
  }
  // translation and rotation drivers drive only their first link
  const bool all = driver.type == DriverType::kNormal || driver.type == DriverType::kAffine;
  const size_t driven = all ? driver.links.size() : 1;
  for (size_t i = 0; i < driven; ++i) {
    int& line = (*driven_on_line)[driver.links[i]];
    if (line != 0) {
      b.Error(statement.line, "link " + std::to_string(driver.links[i]) +
                                  " is already driven by the driver on line " +
                                  std::to_string(line));
      return false;
    }
    line = statement.line > 0 ? statement.line : -1;
  }
  return true;
}

// one per-driver vector (the table's row `key`): checked against the driver count and the
// row, then copied when it fits
void ApplyDriverVector(RobBuild& b, const NumberList& list, int driver_count, std::string_view key,
                       double DriverDesc::*field) {
  if (list.empty()) return;
  if (list.size() != driver_count) {
    b.Error(list.line, "'" + list.keyword + "' expects " + CountOf(driver_count, "value") +
                           " (one per driver), got " + std::to_string(list.size()));
    return;
  }
  for (int i = 0; i < list.size(); ++i) {
    b.CheckRow(list.lines[i], "'" + list.keyword + "' of driver " + std::to_string(i), key,
               ElementKind::kDriver, {list.values[i]});
  }
  if (static_cast<int>(b.robot.drivers.size()) != driver_count) return;  // already reported
  for (int i = 0; i < driver_count; ++i) b.robot.drivers[i].*field = list.values[i];
}

// A driver's velocity and torque limits as the table's rows: an affine driver's from its own
// statement, the others' copied from their link (velmin/velmax, +-torquemax).
void CheckDriverLimits(const RobBuild& b, const DriverStatement& statement, int index) {
  const DriverDesc& driver = b.robot.drivers[index];
  const std::string of_driver = " of driver " + std::to_string(index);
  const RobStatements& s = b.statements;
  const int link = driver.links.front();
  const bool affine = driver.type == DriverType::kAffine;
  const auto line = [&](std::initializer_list<const NumberList*> lists) {
    for (const NumberList* list : lists) {
      if (!list->empty()) return list->lines[link];
    }
    return statement.line;
  };
  const std::string velocity_from = affine ? " ('driver affine' vmin vmax)" : " (velmin, velmax)";
  b.CheckRow(affine ? statement.line : line({&s.velocity_min, &s.velocity_max}),
             "velocityLimits" + of_driver + velocity_from, "velocityLimits", ElementKind::kDriver,
             {driver.velocity_min, driver.velocity_max});
  const std::string torque_from = affine ? " ('driver affine' tmin tmax)" : " (+-torquemax)";
  b.CheckRow(affine ? statement.line : line({&s.torque_max}),
             "torqueLimits" + of_driver + torque_from, "torqueLimits", ElementKind::kDriver,
             {driver.torque_min, driver.torque_max});
}

}  // namespace

void CopyLinkLimits(const LinkDesc& link, DriverDesc* driver) {
  driver->q_min = link.q_min;
  driver->q_max = link.q_max;
  driver->velocity_min = link.velocity_min;
  driver->velocity_max = link.velocity_max;
  driver->torque_min = -link.torque_max;
  driver->torque_max = link.torque_max;
  driver->acceleration_min = -link.acceleration_max;
  driver->acceleration_max = link.acceleration_max;
}

void BuildJoints(RobBuild& build) {
  const std::vector<JointStatement> joints =
      build.statements.joints.empty() ? DefaultJoints(build.robot) : build.statements.joints;
  // line of the joint that claimed each link (-1 for a default joint, 0 for none)
  std::vector<int> claimed(build.link_count, 0);
  for (const JointStatement& joint : joints) {
    const std::vector<int> chain = JointChain(build, joint);
    bool ok = !chain.empty();
    for (int link : chain) {
      if (claimed[link] != 0) {
        build.Error(joint.line, "link " + std::to_string(link) +
                                    " is already part of the joint on line " +
                                    std::to_string(claimed[link]));
        ok = false;
        break;
      }
    }
    if (!ok) continue;
    for (int link : chain) claimed[link] = joint.line > 0 ? joint.line : -1;
    build.robot.joints.push_back(joint.joint);
  }
  for (int i = 0; i < build.link_count; ++i) {
    if (claimed[i] == 0)
      build.Warning(0, "link " + std::to_string(i) + " is not part of any joint");
  }
}

void BuildDrivers(RobBuild& build) {
  const RobStatements& s = build.statements;
  const std::vector<DriverStatement> drivers =
      s.drivers.empty() ? DefaultDrivers(build.robot) : s.drivers;
  std::vector<int> driven_on_line(build.link_count, 0);
  for (const DriverStatement& statement : drivers) {
    if (!CheckDriver(build, statement, &driven_on_line)) continue;
    DriverDesc driver = statement.driver;
    const LinkDesc& first = build.robot.links[driver.links.front()];
    if (driver.type != DriverType::kAffine) CopyLinkLimits(first, &driver);
    driver.name = first.name;
    build.robot.drivers.push_back(driver);
    CheckDriverLimits(build, statement, static_cast<int>(build.robot.drivers.size()) - 1);
  }
  const int driver_count = static_cast<int>(drivers.size());
  if (!s.driver_names.empty()) {
    if (s.driver_names.size() != driver_count) {
      build.Error(s.driver_names.line,
                  "'" + s.driver_names.keyword + "' expects " + CountOf(driver_count, "name") +
                      " (one per driver), got " + std::to_string(s.driver_names.size()));
    } else if (static_cast<int>(build.robot.drivers.size()) == driver_count) {
      for (int i = 0; i < driver_count; ++i) {
        build.robot.drivers[i].name = s.driver_names.values[i];
      }
    }
  }
  ApplyDriverVector(build, s.servo_p, driver_count, "servoP", &DriverDesc::servo_p);
  ApplyDriverVector(build, s.servo_i, driver_count, "servoI", &DriverDesc::servo_i);
  ApplyDriverVector(build, s.servo_d, driver_count, "servoD", &DriverDesc::servo_d);
  ApplyDriverVector(build, s.dry_friction, driver_count, "dryFriction", &DriverDesc::dry_friction);
  ApplyDriverVector(build, s.viscous_friction, driver_count, "viscousFriction",
                    &DriverDesc::viscous_friction);
}

}  // namespace lamina::core::rob
