// SPDX-License-Identifier: MIT
// The two sources of a drawn frame's poses: the description's initial conditions and a running
// simulation.
#include "core/render/world_poses.h"

#include "core/robot/kinematics.h"
#include "core/sim/simulator.h"

namespace lamina::core {

VecX DisplayConfiguration(const RobotDesc& robot) {
  if (robot.config.size() == robot.dof()) return robot.config;
  VecX q(robot.dof());
  for (int l = 0; l < robot.dof(); ++l) q[l] = robot.links[l].q_initial;
  return q;
}

WorldPoses InitialPoses(const WorldDesc& world) {
  WorldPoses poses;
  poses.objects.reserve(world.objects.size());
  for (const RigidObjectDesc& object : world.objects) poses.objects.push_back(object.pose);
  poses.robots.reserve(world.robots.size());
  for (const RobotDesc& robot : world.robots) poses.robots.push_back(DisplayConfiguration(robot));
  return poses;
}

WorldPoses CurrentPoses(const Simulator& simulator) {
  WorldPoses poses;
  poses.objects.reserve(simulator.object_count());
  for (int i = 0; i < simulator.object_count(); ++i)
    poses.objects.push_back(simulator.GetObjectPose(i));
  poses.robots.reserve(simulator.robot_count());
  for (int r = 0; r < simulator.robot_count(); ++r)
    poses.robots.push_back(simulator.GetRobotConfig(r));
  return poses;
}

Pose DrawnObjectPose(const WorldDesc& world, const WorldPoses& poses, int object) {
  const size_t i = static_cast<size_t>(object);
  return i < poses.objects.size() ? poses.objects[i] : world.objects[i].pose;
}

VecX DrawnRobotConfiguration(const WorldDesc& world, const WorldPoses& poses, int robot) {
  const size_t r = static_cast<size_t>(robot);
  const RobotDesc& desc = world.robots[r];
  if (r < poses.robots.size() && poses.robots[r].size() == desc.dof()) return poses.robots[r];
  return DisplayConfiguration(desc);
}

std::optional<Pose> DrawnBodyFrame(const WorldDesc& world, const WorldPoses& poses, int id) {
  const WorldId body = world.Resolve(id);
  if (body.kind == WorldId::Kind::kRigidObject) return DrawnObjectPose(world, poses, body.index);
  if (body.kind != WorldId::Kind::kRobotLink) return std::nullopt;
  const RobotDesc& robot = world.robots[body.index];
  return LinkTransforms(robot, DrawnRobotConfiguration(world, poses, body.index))[body.link];
}

}  // namespace lamina::core
