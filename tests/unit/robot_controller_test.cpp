// SPDX-License-Identifier: MIT
// RobotController on the UR5 and on a small affine-driver robot: link↔driver mapping, actuator
// forces, scheduling, ramps followed at 100 Hz, chained milestones, manual PID and torque
// commands, constant velocity, rejected input, gravity feed-forward and exact save/restore.
#include "core/control/robot_controller.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/control/parabolic_ramp.h"
#include "core/robot/dynamics.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

constexpr double kPeriod = 0.01;

RobotDesc Ur5() {
  auto loaded = test::LoadRobot(test::WorldsPath("klampt/robots/ur5.rob"));
  EXPECT_TRUE(loaded->ok);
  return loaded->robot;
}

// Three revolute links in a chain; one normal driver on link 0 and an affine driver on 1 and 2.
RobotDesc AffineRobot() {
  RobotDesc robot;
  for (int i = 0; i < 3; ++i) {
    LinkDesc link;
    link.parent = i - 1;
    link.axis = Vec3::UnitY();
    link.parent_transform.translation() = Vec3(0, 0, 0.3);
    link.q_min = -2;
    link.q_max = 2;
    link.velocity_max = 1;
    link.acceleration_max = 2;
    link.torque_max = 50;
    link.com = Vec3(0, 0, 0.15);
    robot.links.push_back(link);
    robot.joints.push_back(JointDesc{JointType::kNormal, i, -1});
  }
  DriverDesc normal;
  normal.links = {0};
  normal.q_min = -2;
  normal.q_max = 2;
  normal.torque_min = -50;
  normal.torque_max = 50;
  normal.servo_p = 100;
  DriverDesc affine = normal;
  affine.type = DriverType::kAffine;
  affine.links = {1, 2};
  affine.affine_scale = {2.0, -1.0};
  affine.affine_offset = {0.1, 0.2};
  robot.drivers = {normal, affine};
  robot.config = VecX::Zero(3);
  return robot;
}

// A configuration inside the UR5 limits that moves every driven joint.
VecX Ur5Target(const VecX& start) {
  VecX target = start;
  const double deltas[] = {0.8, -0.5, 1.0, 0.3, -1.2, 2.0};
  for (int j = 0; j < 6; ++j) target[j + 1] += deltas[j];
  return target;
}

// Runs `steps` control updates with sensed = commanded (a perfect tracker).
void RunPerfectTracking(RobotController* controller, int steps) {
  for (int k = 0; k < steps; ++k) {
    VecX q, dq;
    ASSERT_TRUE(controller->GetCommandedConfig(&q));
    ASSERT_TRUE(controller->GetCommandedVelocity(&dq));
    ASSERT_TRUE(controller->Update(controller->next_control_time(), q, dq))
        << controller->last_error();
  }
}

TEST(RobotControllerTest, Ur5StartsHoldingItsConfigWithContinuousDrivers) {
  const RobotDesc robot = Ur5();
  RobotController controller(robot);
  ASSERT_EQ(controller.dof(), 8);
  ASSERT_EQ(controller.driver_count(), 6);
  EXPECT_EQ(controller.control_period(), kDefaultControlPeriod);
  for (const ActuatorState& actuator : controller.actuators()) {
    EXPECT_EQ(actuator.mode, ActuatorMode::kPid);
    EXPECT_TRUE(actuator.relative_encoding);  // range ±2π
  }
  EXPECT_EQ(controller.drivers()[1].servo_p, 4000);
  VecX q;
  ASSERT_TRUE(controller.GetCommandedConfig(&q));
  EXPECT_EQ(q, VecX::Zero(8));
  EXPECT_EQ(controller.limits().acceleration_max[1], 10);
  EXPECT_EQ(controller.limits().velocity_max[1], 3.15);
}

TEST(RobotControllerTest, LinkDriverMappingRoundTrip) {
  RobotController controller(Ur5());
  VecX q(8);
  q << 0, 0.1, -0.2, 0.3, -0.4, 0.5, -0.6, 0;
  const VecX values = controller.DriverValues(q);
  ASSERT_EQ(values.size(), 6);
  EXPECT_EQ(values, q.segment(1, 6));
  EXPECT_EQ(controller.LinkValuesFromDrivers(values, VecX::Zero(8), false), q);
  EXPECT_EQ(controller.DriverForcesFromLinks(q), q.segment(1, 6));
}

TEST(RobotControllerTest, TranslationDriversActOnTheirAxisLinks) {
  auto loaded = test::LoadRobot(test::WorldsPath("klampt/robots/sphere.rob"));
  ASSERT_TRUE(loaded->ok);
  RobotController controller(loaded->robot);
  ASSERT_EQ(controller.driver_count(), 3);
  const VecX q(Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_EQ(controller.DriverValues(q), q);  // driver d reads its axis link d, not body link 2
  ASSERT_TRUE(controller.SetTorque(Eigen::Vector3d(1, -2, 9)));
  VecX forces;
  controller.ComputeLinkForces(q, VecX::Zero(3), &forces);
  EXPECT_EQ(forces, Eigen::Vector3d(1, -2, 5));  // torqueMax 5
  // Floating base: no gravity feed-forward.
  controller.SetGravityCompensation(true);
  ASSERT_TRUE(controller.SetMilestone(q));
  ASSERT_TRUE(controller.Update(0, q, VecX::Zero(3)));
  EXPECT_EQ(controller.CommandedTorques(), VecX::Zero(3));
  for (const ActuatorState& actuator : controller.actuators()) {
    EXPECT_EQ(actuator.mode, ActuatorMode::kPid);  // the queue took over again
  }
}

TEST(RobotControllerTest, AffineDriverMapping) {
  RobotController controller(AffineRobot());
  const VecX link_q =
      controller.LinkValuesFromDrivers(Eigen::Vector2d(0.3, 0.5), VecX::Zero(3), false);
  EXPECT_NEAR(link_q[0], 0.3, 1e-15);
  EXPECT_NEAR(link_q[1], 0.1 + 2.0 * 0.5, 1e-15);
  EXPECT_NEAR(link_q[2], 0.2 - 1.0 * 0.5, 1e-15);
  EXPECT_NEAR(controller.DriverValue(1, link_q), 0.5, 1e-15);
  const VecX link_dq = controller.LinkValuesFromDrivers(Eigen::Vector2d(1, 1), VecX::Zero(3), true);
  EXPECT_EQ(link_dq, Eigen::Vector3d(1, 2, -1));
  EXPECT_EQ(controller.DriverVelocity(1, link_dq), 1);
  EXPECT_EQ(controller.DriverForcesFromLinks(Eigen::Vector3d(1, 2, 3)), Eigen::Vector2d(1, 1));
}

TEST(RobotControllerTest, AffineForcesAreScaledWithAnOrthogonalCorrection) {
  RobotController controller(AffineRobot());
  ASSERT_TRUE(controller.SetTorque(Eigen::Vector2d(4, 3)));  // driver-sized
  VecX forces;
  controller.ComputeLinkForces(VecX::Zero(3), VecX::Zero(3), &forces);
  EXPECT_EQ(forces, Eigen::Vector3d(4, 6, -3));
  // PID holding driver value 0 while the links are off the affine line: the correction does no
  // work along the scale vector (s·f = |s|²·τ) and pulls the links back onto the line.
  ASSERT_TRUE(controller.SetPIDCommand(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0)));
  // off the line: link 1 alone says 0, link 2 alone 0.2·(−1)⁻¹ = −0.2; least squares −0.04
  const VecX q(Eigen::Vector3d(0, 0.1, 0.4));
  EXPECT_NEAR(controller.DriverValue(1, q), (2 * 0.0 - 1 * 0.2) / 5, 1e-15);
  controller.ComputeLinkForces(q, VecX::Zero(3), &forces);
  const Eigen::Vector2d scale(2, -1);
  const double effort = controller.DriverEfforts(q, VecX::Zero(3))[1];
  EXPECT_NEAR(scale.dot(forces.tail(2)), scale.squaredNorm() * effort, 1e-12);
  EXPECT_LT(forces[2], 0);  // link 2 sits 0.2 above its commanded 0.2 → pushed down
}

TEST(RobotControllerTest, ControlRunsOncePerPeriod) {
  RobotController controller(Ur5());
  int runs = 0;
  const VecX q = VecX::Zero(8);
  for (int step = 0; step < 1000; ++step) {
    const double end_of_step = (step + 1) * 0.001;
    if (controller.ControlDue(end_of_step)) {
      ASSERT_TRUE(controller.Update(end_of_step, q, q));
      ++runs;
    }
  }
  // Due at the first step (next control time 0), then every 10 ms up to and including 1.0 s.
  EXPECT_EQ(runs, 101);
  EXPECT_TRUE(controller.SetControlPeriod(0.02));
  EXPECT_FALSE(controller.SetControlPeriod(0));
  EXPECT_EQ(controller.control_period(), 0.02);
}

TEST(RobotControllerTest, ControllerPropertyGivesThePeriod) {
  EXPECT_DOUBLE_EQ(ControlPeriodFromProperty("<controller type=\"x\" rate=\"50\"/>"), 0.02);
  EXPECT_DOUBLE_EQ(ControlPeriodFromProperty("<controller timeStep='0.005'/>"), 0.005);
  EXPECT_EQ(ControlPeriodFromProperty("<controller/>"), 0);
  RobotDesc robot = Ur5();
  robot.properties["controller"] = "<controller rate=\"200\"/>";
  EXPECT_DOUBLE_EQ(RobotController(robot).control_period(), 0.005);
}

TEST(RobotControllerTest, FirstUpdateHoldsTheSensedConfigClampedIntoLimits) {
  RobotController controller(AffineRobot());
  ASSERT_TRUE(controller.Update(0, Eigen::Vector3d(3, 0.5, 0.2), VecX::Zero(3)));
  EXPECT_EQ(controller.actuators()[0].q_des, 2);  // clamped to q_max
  // links 1 and 2 say (0.5 - 0.1) / 2 = 0.2 and (0.2 - 0.2) / -1 = 0: least squares 0.16
  EXPECT_NEAR(controller.actuators()[1].q_des, (2 * 0.4 - 1 * 0.0) / 5, 1e-15);
}

TEST(RobotControllerTest, MilestoneIsReachedAtTheRampMinimumTime) {
  RobotController controller(Ur5());
  const VecX start = VecX::Zero(8);
  const VecX target = Ur5Target(start);
  ASSERT_TRUE(controller.SetMilestone(target)) << controller.last_error();
  EXPECT_FALSE(controller.manual_mode());
  const auto ramp =
      PlanJointRamp(start, VecX::Zero(8), target, VecX::Zero(8), controller.limits(), nullptr);
  ASSERT_TRUE(ramp);
  const double duration = ramp->Duration();
  EXPECT_NEAR(controller.RemainingTime(), duration, 1e-12);
  int reached = -1;
  for (int k = 1; k <= 500 && reached < 0; ++k) {
    RunPerfectTracking(&controller, 1);
    VecX q;
    ASSERT_TRUE(controller.GetCommandedConfig(&q));
    if ((q - target).norm() < 1e-12) reached = k;
  }
  ASSERT_GT(reached, 0);
  EXPECT_GE(reached * kPeriod, duration - 1e-9);
  EXPECT_LT(reached * kPeriod, duration + kPeriod);
  VecX dq;
  ASSERT_TRUE(controller.GetCommandedVelocity(&dq));
  EXPECT_EQ(dq, VecX::Zero(8));
}

TEST(RobotControllerTest, AddMilestoneChainsRamps) {
  RobotController controller(Ur5());
  const VecX start = VecX::Zero(8);
  const VecX first = Ur5Target(start);
  const VecX second = start;
  ASSERT_TRUE(controller.SetMilestone(first));
  ASSERT_TRUE(controller.AddMilestone(second)) << controller.last_error();
  const double t1 =
      PlanJointRamp(start, VecX::Zero(8), first, VecX::Zero(8), controller.limits(), nullptr)
          ->Duration();
  const double t2 =
      PlanJointRamp(first, VecX::Zero(8), second, VecX::Zero(8), controller.limits(), nullptr)
          ->Duration();
  EXPECT_NEAR(controller.RemainingTime(), t1 + t2, 1e-9);
  const int first_steps = static_cast<int>(std::ceil(t1 / kPeriod - 1e-9));
  RunPerfectTracking(&controller, first_steps);
  VecX q;
  ASSERT_TRUE(controller.GetCommandedConfig(&q));
  EXPECT_LT((q - first).norm(), 0.05);  // at most one period past the first stop, at rest there
  RunPerfectTracking(&controller, static_cast<int>(std::ceil(t2 / kPeriod)) + 1);
  ASSERT_TRUE(controller.GetCommandedConfig(&q));
  EXPECT_LT((q - second).norm(), 1e-12);
  EXPECT_EQ(controller.RemainingTime(), 0);
  EXPECT_TRUE(controller.AddMilestoneLinear(first)) << controller.last_error();
}

TEST(RobotControllerTest, PidCommandTurnsManualModeOnAndTheQueueNoLongerOverrides) {
  RobotController controller(Ur5());
  ASSERT_TRUE(controller.SetMilestone(Ur5Target(VecX::Zero(8))));
  RunPerfectTracking(&controller, 10);
  const double i_term = 0.125;
  controller.actuators()[2].i_term = i_term;
  VecX hold = VecX::Zero(8);
  hold[3] = 0.7;
  ASSERT_TRUE(controller.SetPIDCommand(hold, VecX::Zero(8)));
  EXPECT_TRUE(controller.manual_mode());
  EXPECT_EQ(controller.actuators()[2].i_term, i_term);  // kept
  RunPerfectTracking(&controller, 20);
  VecX q;
  ASSERT_TRUE(controller.GetCommandedConfig(&q));
  EXPECT_EQ(q, hold);
  // A motion command restarts the queue from the commanded config and leaves manual mode.
  VecX next = hold;
  next[1] = 0.2;
  ASSERT_TRUE(controller.SetMilestone(next));
  EXPECT_FALSE(controller.manual_mode());
  EXPECT_EQ(controller.queue().Config(), hold);
  // Driver-sized PID commands with feed-forward are accepted too.
  ASSERT_TRUE(controller.SetPIDCommand(VecX::Zero(6), VecX::Zero(6), VecX::Constant(6, 1.5)));
  EXPECT_EQ(controller.CommandedTorques(), VecX::Constant(6, 1.5));
}

TEST(RobotControllerTest, TorqueCommandIsClampedAndFreezesTheQueue) {
  RobotController controller(Ur5());
  VecX torque = VecX::Zero(8);
  torque[1] = 200;  // limit 150
  torque[4] = -10;  // limit 28
  ASSERT_TRUE(controller.SetTorque(torque));
  EXPECT_TRUE(controller.manual_mode());
  VecX forces;
  controller.ComputeLinkForces(VecX::Zero(8), VecX::Zero(8), &forces);
  VecX expected = VecX::Zero(8);
  expected[1] = 150;
  expected[4] = -10;
  EXPECT_EQ(forces, expected);
  VecX q;
  EXPECT_FALSE(controller.GetCommandedConfig(&q));  // not all drivers in PID mode
  ASSERT_TRUE(controller.Update(0, VecX::Zero(8), VecX::Zero(8)));
  EXPECT_EQ(controller.actuators()[0].mode, ActuatorMode::kTorque);
  // Live torque limit edit
  controller.drivers()[0].torque_max = 100;
  controller.ComputeLinkForces(VecX::Zero(8), VecX::Zero(8), &forces);
  EXPECT_EQ(forces[1], 100);
}

TEST(RobotControllerTest, VelocityCommandMovesThenHolds) {
  RobotController controller(Ur5());
  VecX velocity = VecX::Zero(8);
  velocity[2] = 0.5;
  ASSERT_TRUE(controller.SetVelocity(velocity, 0.5));
  for (int k = 1; k <= 100; ++k) {
    RunPerfectTracking(&controller, 1);
    const double t = k * kPeriod;
    const ActuatorState& actuator = controller.actuators()[1];  // drives link 2
    EXPECT_NEAR(actuator.q_des, 0.5 * std::min(t, 0.5), 1e-9) << "t " << t;
    if (std::abs(t - 0.5) > 1e-6) {
      EXPECT_NEAR(actuator.dq_des, t < 0.5 ? 0.5 : 0.0, 1e-9) << "t " << t;
    }
  }
}

TEST(RobotControllerTest, BadInputIsRejectedWithoutChanges) {
  RobotController controller(Ur5());
  ASSERT_TRUE(controller.SetMilestone(Ur5Target(VecX::Zero(8))));
  const double remaining = controller.RemainingTime();
  EXPECT_FALSE(controller.SetMilestone(VecX::Zero(3)));
  EXPECT_NE(controller.last_error().find("8 links"), std::string::npos) << controller.last_error();
  VecX nan = VecX::Zero(8);
  nan[2] = std::nan("");
  EXPECT_FALSE(controller.SetMilestone(nan));
  EXPECT_FALSE(controller.AddMilestone(nan));
  EXPECT_FALSE(controller.SetLinear(VecX::Zero(8), -1));
  EXPECT_FALSE(controller.last_error().empty());
  EXPECT_FALSE(controller.SetVelocity(VecX::Zero(8), std::nan("")));
  EXPECT_FALSE(controller.SetPIDCommand(VecX::Zero(5), VecX::Zero(5)));
  EXPECT_FALSE(controller.SetTorque(nan));
  EXPECT_FALSE(controller.SetPIDGains(VecX::Zero(6), VecX::Zero(6), VecX::Zero(2)));
  EXPECT_FALSE(controller.SetPIDGains(-VecX::Ones(6), VecX::Zero(6), VecX::Zero(6)));
  EXPECT_FALSE(controller.Update(0, nan, VecX::Zero(8)));
  EXPECT_FALSE(controller.Update(0, VecX::Zero(2), VecX::Zero(8)));
  EXPECT_NEAR(controller.RemainingTime(), remaining, 1e-15);
  EXPECT_FALSE(controller.manual_mode());
  for (const ActuatorState& actuator : controller.actuators()) {
    EXPECT_EQ(actuator.mode, ActuatorMode::kPid);
  }
}

TEST(RobotControllerTest, GainsRoundTripAndDriverEdits) {
  RobotController controller(Ur5());
  const VecX kp = VecX::Constant(6, 11), ki = VecX::Constant(6, 2), kd = VecX::Constant(6, 3);
  ASSERT_TRUE(controller.SetPIDGains(kp, ki, kd));
  VecX p, i, d;
  controller.GetPIDGains(&p, &i, &d);
  EXPECT_EQ(p, kp);
  EXPECT_EQ(i, ki);
  EXPECT_EQ(d, kd);
  EXPECT_EQ(controller.drivers()[0].servo_p, 11);
  controller.drivers()[0].servo_p = 5;
  controller.GetPIDGains(&p, &i, &d);
  EXPECT_EQ(p[0], 5);
}

TEST(RobotControllerTest, AViewSharesTheDriversOfItsRobot) {
  RobotDesc robot = Ur5();
  RobotController controller = RobotController::ViewOf(&robot);
  const VecX kp = VecX::Constant(6, 7), ki = VecX::Constant(6, 1), kd = VecX::Constant(6, 2);
  ASSERT_TRUE(controller.SetPIDGains(kp, ki, kd));
  EXPECT_EQ(robot.drivers[3].servo_p, 7);  // written into the robot itself
  robot.drivers[2].dry_friction = 0.5;
  EXPECT_EQ(controller.drivers()[2].dry_friction, 0.5);
  EXPECT_EQ(&controller.robot(), &robot);
}

TEST(RobotControllerTest, GravityCompensationFeedsForwardGravityTorques) {
  const RobotDesc robot = Ur5();
  RobotController controller(robot);
  controller.SetGravityCompensation(true);
  VecX q = VecX::Zero(8);
  q[2] = -0.7;
  q[3] = 0.4;
  ASSERT_TRUE(controller.Update(0, q, VecX::Zero(8)));
  const VecX gravity = GravityTorques(robot, q, Vec3(0, 0, -9.8));
  for (int d = 0; d < 6; ++d) {
    EXPECT_NEAR(controller.actuators()[d].torque, gravity[d + 1], 1e-12) << d;
  }
  EXPECT_GT(std::abs(gravity[2]), 1.0);
}

TEST(RobotControllerTest, LimitsFallBackToTorqueHeuristicOrDefault) {
  RobotDesc robot = AffineRobot();
  robot.links[0].acceleration_max = kInf;
  robot.links[1].acceleration_max = kInf;
  robot.links[1].torque_max = kInf;
  const JointLimits limits = LinkRampLimits(robot);
  EXPECT_TRUE(std::isfinite(limits.acceleration_max[0]));
  EXPECT_GT(limits.acceleration_max[0], 0);
  EXPECT_EQ(limits.acceleration_max[1], kDefaultAccelerationMax);
  EXPECT_EQ(limits.acceleration_max[2], 2);
  RobotController controller(robot);
  JointLimits edited = controller.limits();
  edited.velocity_max[0] = 0.25;
  ASSERT_TRUE(controller.SetLimits(edited));
  EXPECT_EQ(controller.queue().limits().velocity_max[0], 0.25);
  edited.velocity_max.resize(2);
  EXPECT_FALSE(controller.SetLimits(edited));
}

TEST(RobotControllerTest, StateRoundTripReproducesCommandsBitwise) {
  RobotController controller(Ur5());
  ASSERT_TRUE(controller.SetMilestone(Ur5Target(VecX::Zero(8))));
  // A mock plant: q follows the forces a little, so the PID integrals matter.
  VecX q = VecX::Zero(8), dq = VecX::Zero(8), forces;
  auto simulate = [&](int steps, std::vector<VecX>* trace) {
    for (int step = 0; step < steps; ++step) {
      const double t_end = controller.next_control_time();
      if (controller.ControlDue(t_end)) {
        ASSERT_TRUE(controller.Update(t_end, q, dq));
      }
      controller.ComputeLinkForces(q, dq, &forces);
      dq += 1e-4 * forces;
      q += 0.01 * dq;
      controller.AcceptStep(q, 0.01);
      trace->push_back(forces);
    }
  };
  std::vector<VecX> warmup, first, second;
  simulate(20, &warmup);
  const RobotControllerState saved = controller.GetState();
  const VecX saved_q = q, saved_dq = dq;
  simulate(50, &first);
  ASSERT_TRUE(controller.SetState(saved));
  q = saved_q;
  dq = saved_dq;
  simulate(50, &second);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) ASSERT_EQ(first[i], second[i]) << i;
  RobotControllerState wrong = saved;
  wrong.actuators.pop_back();
  EXPECT_FALSE(controller.SetState(wrong));
}

}  // namespace
}  // namespace lamina::core
