// SPDX-License-Identifier: MIT
// The Simulator's robot sensors: built once with the controllers, sampled at the start of every
// physics step before the controllers (Klamp't's order), fed after every accepted step with the
// contacts on the links of robots with contact or force/torque sensors (from the contact feedback
// those sensors register), and a ray caster over the bodies for laser range sensors.
#include <cmath>

#include "core/contact/ray_cast.h"
#include "core/sensors/link_motion.h"
#include "core/sim/simulator.h"

namespace lamina::core {

RobotSensors& Simulator::sensors(int robot) {
  return sensors_[RequireRobot(robot)];
}

const RobotSensors& Simulator::sensors(int robot) const {
  return sensors_[RequireRobot(robot)];
}

// the sensors of every robot, and the contact feedback of the links of robots whose sensors
// read contacts (each link against everything it may touch)
void Simulator::BuildSensors() {
  sensors_.clear();
  for (const RobotDesc& robot : world_.robots) sensors_.emplace_back(robot, &diagnostics_);
  for (int r = 0; r < robot_count(); ++r) {
    if (!sensors_[r].needs_contacts()) continue;
    const int first = world_.RobotLinkId(r, 0);
    for (int id = first; id < first + world_.robots[r].dof(); ++id) {
      if (!bodies_[id].geometry) continue;
      for (int other = 0; other < body_count(); ++other) {
        if (other != id && bodies_[other].geometry && MayCollide(bodies_[id], bodies_[other])) {
          feedback_.Enable(id, other);
        }
      }
    }
  }
}

double Simulator::CastRay(const Vec3& origin, const Vec3& direction, double max_distance,
                          int ignore_id) const {
  double nearest = kInf;
  for (int id = 0; id < body_count(); ++id) {
    const BodyRecord& body = bodies_[id];
    if (id == ignore_id || !body.geometry || !BodyEnabled(id)) continue;
    const double limit = std::min(nearest, max_distance);
    nearest = std::min(nearest, RayCast(*body.geometry, BodyPose(id), origin, direction, limit));
  }
  return nearest;
}

void Simulator::SampleSensors(int robot, double step) {
  RobotSensors& sensors = sensors_[robot];
  if (!sensors.AnyDue(time_)) return;
  const RobotDesc& desc = world_.robots[robot];
  SensorInputs in;
  in.robot = &desc;
  in.time = time_;
  in.q = GetRobotConfig(robot);
  in.dq = GetRobotVelocity(robot);
  in.ddq = sensors.MeanAcceleration(time_, in.dq);
  if (sensors.needs_motion()) in.motion = ComputeLinkMotion(desc, in.q, in.dq, in.ddq);
  in.gravity = world_.settings.gravity;
  if (sensors.needs_driver_torques()) {
    in.driver_torques = controllers_[robot].DriverEfforts(in.q, in.dq);
  }
  in.contacts = sensors.last_contacts();
  const int first = world_.RobotLinkId(robot, 0);
  in.ray = [this, first](const Vec3& origin, const Vec3& direction, double max, int link) {
    return CastRay(origin, direction, max, link >= 0 ? first + link : -1);
  };
  in.camera = camera_renderer_;
  sensors.Sample(in, step, controllers_[robot].control_period());
}

// the contacts of the last accepted step on the robot's links (forces on the links)
std::vector<LinkContact> Simulator::RobotContacts(int robot) const {
  std::vector<LinkContact> out;
  const int first = world_.RobotLinkId(robot, 0);
  const int end = first + world_.robots[robot].dof();
  for (const ContactFeedbackRecord& r : feedback_.records()) {
    for (const int id : {r.first, r.second}) {
      if (id < first || id >= end) continue;
      const double sign = id == r.first ? 1.0 : -1.0;
      for (const FeedbackContact& c : r.contacts)
        out.push_back({id - first, c.position, sign * c.force});
    }
  }
  return out;
}

// after an accepted step: the contacts on the robot's links, for its contact and force sensors
void Simulator::RecordSensorStep(int robot) {
  RobotSensors& sensors = sensors_[robot];
  if (sensors.needs_contacts()) sensors.RecordContacts(RobotContacts(robot));
}

}  // namespace lamina::core
