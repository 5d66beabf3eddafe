// SPDX-License-Identifier: MIT
// Access paths on a running simulation: the current state under the initial conditions' names,
// rows set through Simulator::SetParam reaching the physics (a sliding box's stopping distance,
// a free fall under edited gravity), a pendulum's robot, link and controller items against
// analytic answers, and read-only items refusing.
#include "core/sim/sim_access.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/io/load_context.h"
#include "core/io/robot_file.h"
#include "core/model/world_compare.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::ParamValue;
using core::Vec3;

using test::kBoxSide;
using test::kGravity;
constexpr double kBoxPadding = 0.0025;

// a 1 kg, 10 cm box named "box" resting on a rigid plane, both with friction 0.5, no bounce
core::WorldDesc BoxOnPlane() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc box =
      test::BoxObject(kBoxSide, 1.0, Vec3(0, 0, 0.5 * kBoxSide + kBoxPadding));
  box.name = "box";
  box.sim.padding = kBoxPadding;
  box.sim.surface = {0.0, 0.5, core::kInf, core::kInf};
  world.objects.push_back(box);
  return world;
}

// A pendulum "pendulum" hinged to the world at (0, 0, 1) about y, one PID driver "motor".
core::WorldDesc PendulumWorld() {
  core::WorldDesc world = test::PendulumWorld("servoP 10\nservoI 0\nservoD 1\n");
  world.robots[0].links[0].name = "rod";
  world.robots[0].name = "pendulum";
  world.robots[0].drivers[0].name = "motor";
  return world;
}

ParamValue Get(const core::Simulator& simulator, const std::string& path) {
  std::string error;
  const std::optional<ParamValue> value = core::GetPath(simulator, path, &error);
  EXPECT_TRUE(value) << path << ": " << error;
  return value.value_or(ParamValue(12, std::nan("")));
}

void Set(core::Simulator* simulator, const std::string& path, const ParamValue& value) {
  std::string error;
  EXPECT_TRUE(core::SetPath(simulator, path, value, &error)) << path << ": " << error;
}

// the pair's friction: the harmonic mean of the two surfaces'
double PairFriction(double a, double b) {
  return 2 * a * b / (a + b);
}

TEST(SimAccessTest, TransformAndVelocityAreTheCurrentStateNotTheInitialRows) {
  core::Simulator simulator(BoxOnPlane());
  Set(&simulator, "objects[box].velocity", {0, 0, 0, 2, 0, 0});
  simulator.Simulate(0.1);
  const core::Pose pose = simulator.GetObjectPose(0);
  const ParamValue transform = Get(simulator, "rigidObjects[box].transform");
  EXPECT_EQ(transform, core::PoseToValue(pose));
  EXPECT_EQ(Get(simulator, "objects[box].transform[9]"), ParamValue{pose.translation().x()});
  // kinetic friction 0.5 g decelerates it: v = 2 - 0.5 g t
  EXPECT_NEAR(Get(simulator, "objects[box].velocity[3]")[0], 2 - 0.5 * kGravity * 0.1, 1e-9);
  EXPECT_NEAR(Get(simulator, "time")[0], 0.1, 1e-12);
  // the description the simulation was built from still starts at rest at the origin
  std::string error;
  EXPECT_EQ(core::GetPath(simulator.world(), "objects[box].transform[9]", &error), ParamValue{0.0});
  EXPECT_EQ(core::GetPath(simulator.world(), "objects[box].velocity[3]", &error), ParamValue{0.0});
}

// kFriction set while the box slides reaches the contact at once: the rest of the slide is
// v² / (2 μ g) with the new pair friction
TEST(SimAccessTest, FrictionSetWhileSlidingChangesTheStoppingDistanceByTheAnalyticAmount) {
  const double v0 = 2.0, t1 = 0.1, mu1 = 0.5;
  const double v1 = v0 - mu1 * kGravity * t1;
  const double x1 = v0 * t1 - 0.5 * mu1 * kGravity * t1 * t1;
  double stops[2];
  for (int edited = 0; edited < 2; ++edited) {
    core::Simulator simulator(BoxOnPlane());
    Set(&simulator, "objects[box].velocity", {0, 0, 0, v0, 0, 0});
    simulator.Simulate(t1);
    if (edited) Set(&simulator, "objects[box].kFriction", {0.1});
    simulator.Simulate(1.5);
    stops[edited] = simulator.GetObjectPose(0).translation().x();
    EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.norm(), 0.0, 1e-3);
  }
  const double mu2 = PairFriction(0.1, 0.5);
  // the 1 ms steps stop the box about a millimetre short of the continuous answer
  EXPECT_NEAR(stops[0], x1 + v1 * v1 / (2 * mu1 * kGravity), 2e-3);
  EXPECT_NEAR(stops[1], x1 + v1 * v1 / (2 * mu2 * kGravity), 2e-3);
  // the edit adds v1²/(2g) (1/μ2 - 1/μ1) = 0.465 m; the step's shortfall mostly cancels
  EXPECT_NEAR(stops[1] - stops[0], v1 * v1 / (2 * kGravity) * (1 / mu2 - 1 / mu1), 5e-4);
}

TEST(SimAccessTest, RowsAreReadAndWrittenThroughTheSimulatedDescription) {
  core::Simulator simulator(BoxOnPlane());
  Set(&simulator, "objects[box].kFriction", {0.1});
  EXPECT_EQ(simulator.world().objects[0].sim.surface.friction, 0.1);
  EXPECT_EQ(Get(simulator, "objects[box].kFriction"), ParamValue{0.1});
  EXPECT_EQ(Get(simulator, "terrains[0].kFriction"), ParamValue{0.5});
}

// settings.gravity[2] on a running simulation: a box in free fall from rest falls
// z0 - g t²/2 - g h t/2 (semi-implicit Euler with step h) under the new gravity
TEST(SimAccessTest, GravityComponentSetReachesTheFreeFall) {
  core::WorldDesc world;
  world.objects.push_back(test::BoxObject(kBoxSide, 1.0, Vec3(0, 0, 10)));
  world.objects[0].name = "box";
  core::Simulator simulator(world);
  Set(&simulator, "settings.gravity[2]", {-1.62});
  EXPECT_EQ(simulator.world().settings.gravity, Vec3(0, 0, -1.62));
  const double g = 1.62, t = 0.5, h = simulator.sim_step();
  simulator.Simulate(t);
  EXPECT_NEAR(Get(simulator, "objects[box].transform[11]")[0], 10 - g * t * t / 2 - g * h * t / 2,
              1e-9);
  EXPECT_NEAR(Get(simulator, "objects[box].velocity[5]")[0], -g * t, 1e-9);
}

TEST(SimAccessTest, RobotConfigVelocityAndTheirKlamptAliasesAreTheCurrentState) {
  core::Simulator simulator(PendulumWorld());
  Set(&simulator, "robots[pendulum].config", {0.3});
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 0.3, 1e-12);
  Set(&simulator, "robots[pendulum].actualVelocity[0]", {1.5});
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 1.5, 1e-12);
  EXPECT_EQ(Get(simulator, "robots[0].actualConfig"), Get(simulator, "robots[0].config"));
  EXPECT_EQ(Get(simulator, "robots[0].velocity"), Get(simulator, "robots[0].actualVelocity"));
  EXPECT_NEAR(Get(simulator, "robots[0].velocity[0]")[0], 1.5, 1e-12);
  // the description keeps its initial configuration
  EXPECT_EQ(simulator.world().robots[0].InitialConfig()[0], 0.0);
  const core::VecX torques = simulator.GetActuatorTorques(0);
  EXPECT_EQ(Get(simulator, "robots[0].torques"), ParamValue{torques[0]});
  EXPECT_EQ(Get(simulator, "robots[0].actualTorques"), ParamValue{torques[0]});
}

// the rod's frame is the pivot (0, 0, 1) rotated by q about y; its origin does not move
TEST(SimAccessTest, LinkTransformAndVelocityFollowTheJoint) {
  core::Simulator simulator(PendulumWorld());
  const double q = 0.3, dq = 1.5;
  Set(&simulator, "robots[0].config", {q});
  Set(&simulator, "robots[0].velocity", {dq});
  const ParamValue frame = Get(simulator, "robots[pendulum].links[rod].transform");
  // column-major R_y(q): (cos, 0, -sin), (0, 1, 0), (sin, 0, cos); then the translation
  const ParamValue expected = {std::cos(q), 0, -std::sin(q), 0, 1, 0,
                               std::sin(q), 0, std::cos(q),  0, 0, 1};
  ASSERT_EQ(frame.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(frame[k], expected[k], 1e-9) << k;
  const ParamValue twist = Get(simulator, "robots[0].links[0].velocity");
  const ParamValue expected_twist = {0, dq, 0, 0, 0, 0};
  ASSERT_EQ(twist.size(), expected_twist.size());
  for (size_t k = 0; k < 6; ++k) EXPECT_NEAR(twist[k], expected_twist[k], 1e-9) << k;
}

TEST(SimAccessTest, ControllerItemsAndDriverGainsReachTheController) {
  core::Simulator simulator(PendulumWorld());
  ASSERT_TRUE(simulator.controller(0).SetPIDCommand(core::VecX::Constant(1, 0.5),
                                                    core::VecX::Constant(1, 0.25)));
  EXPECT_EQ(Get(simulator, "controllers[pendulum].commandedConfig"), ParamValue{0.5});
  EXPECT_EQ(Get(simulator, "controllers[0].commandedVelocity[0]"), ParamValue{0.25});
  simulator.Simulate(0.05);
  EXPECT_EQ(Get(simulator, "controllers[0].sensedConfig"),
            ParamValue{simulator.controller(0).sensed_config()[0]});
  EXPECT_EQ(Get(simulator, "controllers[0].sensedVelocity"),
            ParamValue{simulator.controller(0).sensed_velocity()[0]});
  Set(&simulator, "robots[0].drivers[motor].kP", {60});
  EXPECT_EQ(simulator.controller(0).drivers()[0].servo_p, 60.0);
  EXPECT_EQ(simulator.world().robots[0].drivers[0].servo_p, 60.0);
  // in torque mode there is no commanded configuration (Klamp't raises)
  ASSERT_TRUE(simulator.controller(0).SetTorque(core::VecX::Zero(1)));
  std::string error;
  EXPECT_FALSE(core::GetPath(simulator, "controllers[0].commandedConfig", &error));
  EXPECT_EQ(error, "controllers[0].commandedConfig: not every driver of the robot is in PID mode");
}

TEST(SimAccessTest, ReadOnlyItemsAndRefusedValuesChangeNothing) {
  core::Simulator simulator(PendulumWorld());
  simulator.Simulate(0.05);
  const core::SimState before = simulator.GetState();
  const core::WorldDesc described = simulator.world();
  const std::pair<std::string, ParamValue> refused[] = {
      {"controllers[0].commandedConfig", {0.1}},
      {"controllers[0].sensedVelocity[0]", {0.1}},
      {"time", {1.0}},
      {"robots[0].torques", {1.0}},
      {"robots[0].links[0].transform", core::PoseToValue(core::Pose::Identity())},
      {"robots[0].links[0].velocity", {0, 0, 0, 0, 0, 0}}};
  for (const auto& [path, value] : refused) {
    std::string error;
    EXPECT_FALSE(core::SetPath(&simulator, path, value, &error)) << path;
    EXPECT_EQ(error, path + ": read-only");
  }
  std::string error;
  EXPECT_FALSE(core::SetPath(&simulator, "robots[0].config", {std::nan("")}, &error));
  EXPECT_EQ(error, "robots[0].config must be one finite number per link, got nan");
  EXPECT_FALSE(core::SetPath(&simulator, "robots[0].links[0].kRestitution", {1.5}, &error));
  EXPECT_EQ(error, "robots[0].links[0].kRestitution must be in [0, 1], got 1.5");
  EXPECT_FALSE(core::SetPath(&simulator, "settings.gravity", {std::nan(""), 0, 0}, &error));
  EXPECT_EQ(error, "settings.gravity must be 3 finite numbers, got nan,0,0");
  EXPECT_TRUE(simulator.GetState() == before);
  EXPECT_TRUE(core::CompareWorlds(simulator.world(), described).empty());
}

TEST(SimAccessTest, ObjectTeleportIsCheckedAsARigidPose) {
  core::Simulator simulator(BoxOnPlane());
  std::string error;
  EXPECT_TRUE(core::SetPathText(&simulator, "objects[box].transform",
                                "0,1,0, -1,0,0, 0,0,1, 0.5,0,1", &error))
      << error;
  const core::Pose pose = simulator.GetObjectPose(0);
  EXPECT_NEAR((pose.linear() * Vec3::UnitX() - Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((pose.translation() - Vec3(0.5, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(core::SetPathText(&simulator, "objects[box].transform", "2,0,0, 0,1,0, 0,0,1, 0,0,0",
                                 &error));
  EXPECT_EQ(error,
            "objects[box].transform must be 12 finite numbers: a rotation (column-major) and a "
            "translation, got 2,0,0,0,1,0,0,0,1,0,0,0");
  EXPECT_NEAR((simulator.GetObjectPose(0).translation() - Vec3(0.5, 0, 1)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace lamina
