// SPDX-License-Identifier: MIT
#include "core/sensors/link_motion.h"

#include <stdexcept>
#include <string>

#include "core/robot/kinematics.h"

namespace lamina::core {

namespace {

void RequireSize(const VecX& v, int size, const char* what) {
  if (v.size() != size) {
    throw std::invalid_argument(std::string("ComputeLinkMotion: ") + what + " has " +
                                std::to_string(v.size()) + " entries, the robot " +
                                std::to_string(size) + " links");
  }
}

// the parent's motion carried to link i's origin (what link i does when its joint is still)
void CarryParentMotion(LinkMotion& m, int i, int p) {
  const Vec3 r = m.frames[i].translation() - m.frames[p].translation();
  const Vec3& w = m.angular_velocity[p];
  m.angular_velocity[i] = w;
  m.angular_acceleration[i] = m.angular_acceleration[p];
  m.linear_velocity[i] = m.linear_velocity[p] + w.cross(r);
  m.linear_acceleration[i] =
      m.linear_acceleration[p] + m.angular_acceleration[p].cross(r) + w.cross(w.cross(r));
}

// adds the joint's own motion: a turn about, or a slide along, the axis s (world)
void AddJointMotion(LinkMotion& m, int i, const LinkDesc& link, double dq, double ddq) {
  const Vec3 s = m.frames[i].linear() * link.axis.normalized();
  const Vec3 w = m.angular_velocity[i];  // the parent's
  if (link.axis_type == LinkJointAxis::kRevolute) {
    m.angular_velocity[i] += s * dq;
    m.angular_acceleration[i] += w.cross(s * dq) + s * ddq;
  } else {
    m.linear_velocity[i] += s * dq;
    m.linear_acceleration[i] += 2.0 * w.cross(s * dq) + s * ddq;
  }
}

}  // namespace

Vec3 LinkMotion::PointVelocity(int i, const Vec3& point_world) const {
  return linear_velocity[i] + angular_velocity[i].cross(point_world - frames[i].translation());
}

Vec3 LinkMotion::PointAcceleration(int i, const Vec3& point_world) const {
  const Vec3 r = point_world - frames[i].translation();
  const Vec3& w = angular_velocity[i];
  return linear_acceleration[i] + angular_acceleration[i].cross(r) + w.cross(w.cross(r));
}

LinkMotion ComputeLinkMotion(const RobotDesc& robot, const VecX& q, const VecX& dq,
                             const VecX& ddq) {
  RequireSize(dq, robot.dof(), "dq");
  RequireSize(ddq, robot.dof(), "ddq");
  LinkMotion m;
  m.frames = LinkTransforms(robot, q);
  const size_t n = robot.links.size();
  for (auto* v :
       {&m.angular_velocity, &m.linear_velocity, &m.angular_acceleration, &m.linear_acceleration}) {
    v->assign(n, Vec3::Zero());
  }
  for (size_t i = 0; i < n; ++i) {
    const LinkDesc& link = robot.links[i];
    const int k = static_cast<int>(i);
    if (link.parent >= 0) CarryParentMotion(m, k, link.parent);
    AddJointMotion(m, k, link, dq[k], ddq[k]);
  }
  return m;
}

}  // namespace lamina::core
