// SPDX-License-Identifier: MIT
// One-link robots on ODE against analytic answers: a pendulum's period, PID control from any
// angle, torque limits, joint stops, dry and viscous joint friction; and a pair of links coupled
// by one affine driver holding a load.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/io/load_context.h"
#include "core/io/robot_file.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;
using core::VecX;

using test::kGravity;
constexpr double kLength = 0.5;     // pivot to centre of mass, m
constexpr double kMass = 2.0;       // kg
constexpr double kInertiaC = 0.01;  // about the COM, kg·m²

// A pendulum hinged to the world at (0, 0, 1) about y, its COM kLength below the pivot at q = 0
// (tests/common/scene_builders.h). `extra` adds .rob statements (limits, gains, friction).
core::WorldDesc PendulumWorld(const std::string& extra, double q0) {
  return test::PendulumWorld(extra, q0);
}

double PivotInertia() {
  return kInertiaC + kMass * kLength * kLength;
}

// The pendulum's joint turning at 4 rad/s with no gravity, its actuator off and `friction` (a
// .rob statement) acting on it.
core::WorldDesc SpinningJointWorld(const std::string& friction) {
  core::WorldDesc world = PendulumWorld("servoP 0\nservoI 0\nservoD 0\n" + friction, 0.0);
  world.settings.gravity = core::Vec3::Zero();
  world.robots[0].velocity = VecX::Constant(1, 4.0);
  return world;
}

// with the actuator off, a pendulum released at 0.05 rad swings with the small-angle period
TEST(RobotJointTest, PassivePendulumSwingsWithItsPeriod) {
  core::Simulator simulator(PendulumWorld("servoP 0\nservoI 0\nservoD 0\n", 0.05));
  ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Zero(1)));
  // time of the downward zero crossings of q
  std::vector<double> crossings;
  double previous = simulator.GetRobotConfig(0)[0];
  for (int step = 0; step < 4000; ++step) {
    simulator.Simulate(0.001);
    const double q = simulator.GetRobotConfig(0)[0];
    if (previous > 0.0 && q <= 0.0) {
      crossings.push_back(simulator.time() - 0.001 * q / (q - previous));
    }
    previous = q;
  }
  ASSERT_GE(crossings.size(), 2u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double expected = 2 * core::kPi * std::sqrt(PivotInertia() / (kMass * kGravity * kLength));
  // small-angle error at 0.05 rad: θ²/16 = 1.6e-4
  EXPECT_NEAR(period, expected, 1e-3 * expected);
}

// the tutorial's batch example as a test loop: from anywhere in [-π, π] the PID brings the
// pendulum to its target (a continuous joint takes the short way round)
TEST(RobotJointTest, PidPendulumReachesItsTargetFromAnyAngle) {
  const double target = 0.5;
  for (double q0 = -3.0; q0 <= 3.01; q0 += 1.0) {
    SCOPED_TRACE("q0 = " + std::to_string(q0));
    core::Simulator simulator(PendulumWorld("servoP 60\nservoI 200\nservoD 8\ntorqueMax 50\n", q0));
    ASSERT_TRUE(simulator.controller(0).SetPIDCommand(VecX::Constant(1, target), VecX::Zero(1)));
    simulator.Simulate(6.0);
    const double q = simulator.GetRobotConfig(0)[0];
    EXPECT_NEAR(std::remainder(q - target, 2 * core::kPi), 0.0, 5e-3);
    EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 0.0, 5e-3);
  }
}

// Two links hinged to the world about y, coupled by one affine driver (scales 1, 1): a "catch"
// with its centre of mass on its axis and a 1 kg "handle" with its centre of mass 0.2 m out,
// which gravity turns by tau = m g L cos q. `order` lists the driver's links.
core::WorldDesc CoupledPair(const std::string& order, double servo_i) {
  return test::WorldWithRobot(
      "links \"catch\" \"handle\"\nparents -1 -1\n"
      "TParent 1 0 0  0 1 0  0 0 1  0 0 1   1 0 0  0 1 0  0 0 1  0 0.5 1\n"
      "axis 0 1 0  0 1 0\njointtype r r\nqmin -3 -3\nqmax 3 3\nmass 1 1\n"
      "com 0 0 0  0.2 0 0\n"
      "inertia 0.01 0 0 0 0.01 0 0 0 0.01  0.001 0 0 0 0.001 0 0 0 0.001\n"
      "joint normal 0\njoint normal 1\n"
      "driver affine 2 " +
      order +
      "  1 1  0 0  -3 3  -10 10  -100 100\n"
      "servoP 100\nservoI " +
      std::to_string(servo_i) + "\nservoD 5\n");
}

// The statics of the pair (docs/motion.md): the driver's PD acts along the scale vector on the
// least-squares driver value, the transmission correction (stiffness 0.25 kP) across it. With a
// load tau on the handle: handle 2.5 tau/kP and catch -1.5 tau/kP off their commands without
// integral action, +-2 tau/kP with it; whatever the order of the links in the driver.
TEST(RobotJointTest, AnAffinePairHoldsALoadAsItsTransmissionLawSays) {
  constexpr double kP = 100.0, kHandleMass = 1.0, kArm = 0.2;
  const auto load = [&](double q) { return kHandleMass * kGravity * kArm * std::cos(q); };
  struct PairCase {
    const char* order;
    double servo_i, loaded, other;  // offsets from the command, in units of tau / kP
  } cases[] = {{"0 1", 0.0, 2.5, -1.5}, {"1 0", 0.0, 2.5, -1.5}, {"0 1", 100.0, 2.0, -2.0}};
  for (const PairCase& c : cases) {
    SCOPED_TRACE(std::string("links ") + c.order + ", kI " + std::to_string(c.servo_i));
    core::Simulator simulator(CoupledPair(c.order, c.servo_i));
    simulator.Simulate(10.0);
    ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
    double handle = 0.0;  // the equilibrium: handle = loaded tau(handle) / kP
    for (int k = 0; k < 50; ++k) handle = c.loaded * load(handle) / kP;
    const VecX q = simulator.GetRobotConfig(0);
    EXPECT_NEAR(q[1], handle, 0.01 * handle);
    EXPECT_NEAR(q[0], c.other * load(handle) / kP, 0.01 * std::abs(handle));
    EXPECT_NEAR(simulator.GetRobotVelocity(0).norm(), 0.0, 1e-3);
  }
}

TEST(RobotJointTest, TorqueLimitClampsTheActuator) {
  core::Simulator simulator(PendulumWorld("servoP 1000\nservoI 0\nservoD 0\ntorqueMax 3\n", 0.0));
  ASSERT_TRUE(simulator.controller(0).SetPIDCommand(VecX::Constant(1, 1.0), VecX::Zero(1)));
  simulator.Simulate(0.001);
  // kP·Δq would be 1000 N·m; the actuator gives 3
  EXPECT_NEAR(std::abs(simulator.GetActuatorTorques(0)[0]), 3.0, 1e-12);
  // a constant 3 N·m from rest swings the arm up to θ with 3 θ = m g L (1 - cos θ) (0.62 rad),
  // far short of the 1 rad target
  double highest = 0.0;
  for (int step = 0; step < 1000; ++step) {
    simulator.Simulate(0.001);
    highest = std::max(highest, simulator.GetRobotConfig(0)[0]);
  }
  double theta = 1.0;
  for (int k = 0; k < 50; ++k) {  // Newton on f(θ) = 3 θ - m g L (1 - cos θ)
    const double mgl = kMass * kGravity * kLength;
    theta -= (3 * theta - mgl * (1 - std::cos(theta))) / (3 - mgl * std::sin(theta));
  }
  EXPECT_NEAR(highest, theta, 0.01 * theta);
}

// The arm hangs at rest at its target, so its servo's force is 0 and its row is solved without
// its bound (core/sim/servo_bounds.h); then a 20 N·m torque on the link asks the stiff servo
// (kP 1e4, kD 100) for 3.55 N·m against a 3 N·m limit. The step is retaken with the bound: the
// arm turns as under 20 - 3 = 17 N·m with no servo at all, not at the 3 % lower rate the
// unbounded row gives.
double RateAfterOneStep(const std::string& gains, double applied, bool torque_mode) {
  core::WorldDesc world = PendulumWorld(gains, 0.0);
  core::Simulator simulator(world);
  const bool commanded = torque_mode
                             ? simulator.controller(0).SetTorque(VecX::Zero(1))
                             : simulator.controller(0).SetPIDCommand(VecX::Zero(1), VecX::Zero(1));
  EXPECT_TRUE(commanded);
  simulator.SetAppliedWrench(world.RobotLinkId(0, 0), Vec3::Zero(), Vec3(0, applied, 0));
  simulator.Simulate(0.001);
  return simulator.GetRobotVelocity(0)[0];
}

TEST(RobotJointTest, AServoSolvedUnboundedStillStopsAtItsLimit) {
  const double servo =
      RateAfterOneStep("servoP 10000\nservoI 0\nservoD 100\ntorqueMax 3\n", 20.0, false);
  const double net = RateAfterOneStep("servoP 0\nservoI 0\nservoD 0\n", 17.0, true);
  EXPECT_NEAR(servo, net, 1e-12);
  // about (20 - 3) h / I (ODE's world CFM softens the hinge by 0.2 %)
  EXPECT_NEAR(servo, 17.0 / PivotInertia() * 0.001, 3e-3 * servo);
}

// The same push on an arm whose joint also has 1 N·m of dry friction (the second row of the same
// motor joint, always bounded): the servo row comes out over its limit and is bounded, both rows
// then sit at their bounds and the arm turns as under 20 - 3 - 1 = 16 N·m.
TEST(RobotJointTest, ServoAndDryFrictionOnOneJointBothStopAtTheirLimits) {
  const double both = RateAfterOneStep(
      "servoP 10000\nservoI 0\nservoD 100\ntorqueMax 3\ndryFriction 1\n", 20.0, false);
  const double net = RateAfterOneStep("servoP 0\nservoI 0\nservoD 0\n", 16.0, true);
  EXPECT_NEAR(both, net, 1e-12);
}

TEST(RobotJointTest, JointStopsHoldAtTheLimit) {
  // released at 0.3 rad under gravity towards q < 0 onto a stop at -0.2
  core::Simulator simulator(
      PendulumWorld("servoP 0\nservoI 0\nservoD 0\nqMin -0.2\nqMax 0.4\n", 0.3));
  ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Zero(1)));
  double lowest = 1.0;
  for (int step = 0; step < 2000; ++step) {
    simulator.Simulate(0.001);
    lowest = std::min(lowest, simulator.GetRobotConfig(0)[0]);
  }
  EXPECT_GT(lowest, -0.2 - 0.01);  // overshoot through the stop within ODE's stop ERP
}

TEST(RobotJointTest, StopsWorkForLimitsBeyondPi) {
  // Klamp't drops stops whose limits touch ±π; here the range [-3.5, 1] holds
  core::Simulator simulator(
      PendulumWorld("servoP 0\nservoI 0\nservoD 0\nqMin -3.5\nqMax 1.0\n", 0.9));
  ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Constant(1, -40.0)));  // drive it round
  double lowest = 0.0;
  for (int step = 0; step < 3000; ++step) {
    simulator.controller(0).SetTorque(VecX::Constant(1, -40.0));
    simulator.Simulate(0.001);
    lowest = std::min(lowest, simulator.GetRobotConfig(0)[0]);
  }
  EXPECT_LT(lowest, -3.3);         // it did go past -π
  EXPECT_GT(lowest, -3.5 - 0.05);  // and stopped at its limit
}

// the joint range edited on a running simulation: a constant torque of -5 N·m holds the
// pendulum on its lower stop; widened, the stop gives way to where gravity balances the torque
// (m g L sin q = -5); narrowed, the stop pushes the link back; widened past -π, the joint
// counts turns and stops at its new limit
TEST(RobotJointTest, JointLimitEditsTakeEffectOnTheNextStep) {
  core::Simulator simulator(
      PendulumWorld("servoP 0\nservoI 0\nservoD 0\nqMin -0.2\nqMax 0.4\n", 0.0));
  const auto run = [&](double torque, double seconds) {
    for (int step = 0; step < static_cast<int>(seconds * 1000); ++step) {
      ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Constant(1, torque)));
      simulator.Simulate(0.001);
    }
  };
  run(-5.0, 1.0);
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], -0.2, 0.01);
  simulator.SetJointLimits(0, 0, -0.6, 0.4);
  EXPECT_EQ(simulator.controller(0).limits().q_min[0], -0.6);
  // damp the swing with viscous joint friction so that it settles
  simulator.controller(0).drivers()[0].viscous_friction = 5.0;
  run(-5.0, 4.0);
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], -std::asin(5.0 / (kMass * kGravity * kLength)), 0.01);
  // beyond its new stop, the joint comes back at the capped correction speed (0.5 rad/s), not
  // at ODE's stop ERP x 0.24 rad / 1 ms = 220 rad/s
  simulator.SetJointLimits(0, 0, -0.3, 0.4);
  double fastest = 0.0;
  for (int step = 0; step < 1000; ++step) {
    run(-5.0, 0.001);
    fastest = std::max(fastest, std::abs(simulator.GetRobotVelocity(0)[0]));
  }
  EXPECT_LT(fastest, 0.5 + 0.05);
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], -0.3, 0.01);
  simulator.SetJointLimits(0, 0, -3.5, 1.0);
  double lowest = 0.0;
  for (int step = 0; step < 3000; ++step) {
    run(-40.0, 0.001);
    lowest = std::min(lowest, simulator.GetRobotConfig(0)[0]);
  }
  EXPECT_LT(lowest, -3.3);         // it went past -π
  EXPECT_GT(lowest, -3.5 - 0.05);  // and stopped at its new limit
  EXPECT_THROW(simulator.SetJointLimits(0, 0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(simulator.SetJointLimits(0, 1, -1.0, 1.0), std::out_of_range);
}

// a joint resting on its stop with joint friction stays there: ODE shares one row between a
// joint's motor and its stop and, at the stop, applies the motor's bound as a torque into the
// stop, so the unbounded motor of viscous friction used to blow the simulation up
TEST(RobotJointTest, JointFrictionDoesNotPushAJointOffItsStop) {
  for (const std::string friction : {"dryFriction 2\n", "viscousFriction 5\n"}) {
    SCOPED_TRACE(friction);
    core::WorldDesc world =
        PendulumWorld("servoP 0\nservoI 0\nservoD 0\nqMin -0.2\nqMax 0.4\n" + friction, -0.2);
    world.settings.gravity = core::Vec3::Zero();
    core::Simulator simulator(world);
    ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Zero(1)));
    simulator.Simulate(1.0);
    ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError)
        << simulator.statistics().error;
    EXPECT_NEAR(simulator.GetRobotConfig(0)[0], -0.2, 1e-4);
    EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 0.0, 1e-4);
  }
}

// without gravity only the applied torque and dry friction act on the joint
TEST(RobotJointTest, DryFrictionHoldsBelowItsLimitAndSlipsAbove) {
  for (const double torque : {1.5, 4.0}) {
    core::WorldDesc world = PendulumWorld("servoP 0\nservoI 0\nservoD 0\ndryFriction 2\n", 0.0);
    world.settings.gravity = core::Vec3::Zero();
    core::Simulator simulator(world);
    simulator.controller(0).SetTorque(VecX::Constant(1, torque));
    simulator.Simulate(1.0);
    const double velocity = simulator.GetRobotVelocity(0)[0];
    if (torque < 2.0) {
      EXPECT_NEAR(velocity, 0.0, 1e-5);  // ODE's motor creeps by its CFM
    } else {
      // slips with (τ - μ_D) / I
      EXPECT_NEAR(velocity, (torque - 2.0) / PivotInertia() * 1.0, 0.01 * velocity);
    }
  }
}

// A joint spun up to 4 rad/s against 2 N·m of dry friction, nothing else acting: it slows at
// F / I, stops at t = I ω₀ / F = 1.0204 s after ω₀² I / (2F) = 2.0400 rad and stays there. The
// exact solver gives the sliding row as a torque of −F and the stopped one unbounded
// (core/sim/friction_rows.h); the guess fails where the joint stops and the step is retaken with
// the row bounded, so no step turns the joint back.
TEST(RobotJointTest, DryFrictionSpinsAJointDownAndHoldsIt) {
  core::Simulator simulator(SpinningJointWorld("dryFriction 2\n"));
  simulator.controller(0).SetTorque(VecX::Zero(1));
  const double deceleration = 2.0 / PivotInertia();
  simulator.Simulate(0.5);
  // (ODE's world CFM softens the hinge: 8e-6 relative here)
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 4.0 - deceleration * 0.5, 1e-4);
  double smallest = 1.0;
  for (int step = 0; step < 1500; ++step) {
    simulator.Simulate(0.001);
    smallest = std::min(smallest, simulator.GetRobotVelocity(0)[0]);
  }
  EXPECT_GT(smallest, -1e-6);  // never turned back
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 0.0, 1e-6);
  // first order in h: the last step before the stop overshoots by at most ω·h
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 16.0 / (2.0 * deceleration), 4e-3);
}

TEST(RobotJointTest, ViscousFrictionDampsWithItsTimeConstant) {
  core::Simulator simulator(SpinningJointWorld("viscousFriction 0.5\n"));
  simulator.controller(0).SetTorque(VecX::Zero(1));
  simulator.Simulate(1.0);
  // I dω/dt = -μ_V ω
  const double expected = 4.0 * std::exp(-0.5 / PivotInertia() * 1.0);
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], expected, 0.01 * expected);
}

// fakeSimulate: no physics, the robot follows its commanded ramp exactly (rest to rest over the
// ramp's minimum time), with the commanded velocity
TEST(RobotJointTest, FakeSimulateMovesTheRobotToItsCommands) {
  core::Simulator simulator(
      PendulumWorld("servoP 60\nservoI 0\nservoD 8\nvelMax 2\naccMax 4\n", 0));
  core::RobotController& controller = simulator.controller(0);
  simulator.FakeSimulate(0.01);  // the controller starts its queue
  ASSERT_TRUE(controller.SetMilestone(VecX::Constant(1, 1.0))) << controller.last_error();
  // 1 rad with |a| <= 4: a triangle profile (peak speed 2 = velMax) of 2 sqrt(1 / 4) = 1 s
  EXPECT_NEAR(controller.RemainingTime(), 1.0, 1e-9);
  for (int k = 0; k < 50; ++k) simulator.FakeSimulate(0.01);
  VecX commanded, commanded_velocity;
  ASSERT_TRUE(controller.GetCommandedConfig(&commanded));
  ASSERT_TRUE(controller.GetCommandedVelocity(&commanded_velocity));
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], commanded[0], 1e-12);  // read back through ODE
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], commanded_velocity[0], 1e-9);
  EXPECT_GT(commanded_velocity[0], 1.0);  // mid-ramp, near the peak speed
  for (int k = 0; k < 60; ++k) simulator.FakeSimulate(0.01);
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 1.0, 1e-9);
  EXPECT_NEAR(simulator.time(), 1.11, 1e-9);
}

// a light link with stiff gains (kD h / I = 150 at 1 ms, where the explicit PD law diverges):
// the exact solver applies the servo implicitly and the arm settles on its target
TEST(RobotJointTest, StiffServoOnALightLinkSettles) {
  const std::string text =
      "links \"light\"\nparents -1\nTParent 1 0 0  0 1 0  0 0 1  0 0 1\naxis 0 0 1\n"
      "mass 0.05\ncom 0.02 0 0\ninertia 1e-6 0 0  0 1e-6 0  0 0 1e-6\n"
      "joint normal 0\ndriver normal 0\nservoP 50\nservoI 0\nservoD 3\n";
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  world.robots.emplace_back();
  ASSERT_TRUE(core::ParseRob(text, "/virtual/light.rob", context, &world.robots[0]));
  const double inertia = 1e-6 + 0.05 * 0.02 * 0.02;
  ASSERT_GT(3 * 0.001 / inertia, 2.0);  // beyond the explicit law's stability
  core::Simulator simulator(world);
  ASSERT_TRUE(simulator.controller(0).SetPIDCommand(VecX::Constant(1, 0.3), VecX::Zero(1)));
  simulator.Simulate(1.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // overdamped: kD² >> 4 kP I; it creeps in with time constant kD / kP = 0.06 s
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 0.3, 1e-6);
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 0.0, 1e-6);
}

// friction and torque limits are read live: an edit acts on the next step
TEST(RobotJointTest, FrictionEditsTakeEffectOnTheNextStep) {
  core::WorldDesc world = PendulumWorld("servoP 0\nservoI 0\nservoD 0\ndryFriction 2\n", 0.0);
  world.settings.gravity = core::Vec3::Zero();
  core::Simulator simulator(world);
  simulator.controller(0).SetTorque(VecX::Constant(1, 1.5));
  simulator.Simulate(0.5);
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], 0.0, 1e-5);  // held by 2 N·m
  simulator.controller(0).drivers()[0].dry_friction = 1.0;
  simulator.Simulate(0.5);
  // slips from the edit on with (1.5 - 1) / I
  const double expected = 0.5 / PivotInertia() * 0.5;
  EXPECT_NEAR(simulator.GetRobotVelocity(0)[0], expected, 0.01 * expected);
}

// a saved state (bodies, joint turn counters, controller with its queue) replays bit for bit
TEST(RobotJointTest, SetStateReplaysTheSameTrajectory) {
  core::Simulator simulator(
      PendulumWorld("servoP 60\nservoI 20\nservoD 8\nvelMax 3\naccMax 5\n", -2.5));
  ASSERT_TRUE(simulator.controller(0).SetMilestone(VecX::Constant(1, 2.0)));
  simulator.Simulate(0.4);
  const core::SimState saved = simulator.GetState();
  simulator.Simulate(0.6);
  const VecX q_first = simulator.GetRobotConfig(0);
  const VecX dq_first = simulator.GetRobotVelocity(0);
  simulator.SetState(saved);
  simulator.Simulate(0.6);
  EXPECT_EQ(simulator.GetRobotConfig(0)[0], q_first[0]);
  EXPECT_EQ(simulator.GetRobotVelocity(0)[0], dq_first[0]);
}

// The same with a friction row whose guess failed just before the state was saved (the spinning
// joint stops at 1.02 s and its row stays bounded for 50 steps after): the replay keeps it bounded
// for the same steps, so it is the same trajectory to the bit.
TEST(RobotJointTest, SetStateReplaysJointFrictionRowsToo) {
  core::Simulator simulator(SpinningJointWorld("dryFriction 2\n"));
  simulator.SetDirectRobotSolve(false);  // the guesses are dWorldStep's (friction_rows.h)
  simulator.controller(0).SetTorque(VecX::Constant(1, 0.0));
  simulator.Simulate(1.03);
  const core::SimState saved = simulator.GetState();
  ASSERT_GT(saved.robots[0].friction_holdoff.at(0), 0);
  simulator.controller(0).SetTorque(VecX::Constant(1, 1.9));  // held by the 2 N·m row
  simulator.Simulate(0.2);
  const VecX q_first = simulator.GetRobotConfig(0);
  EXPECT_EQ(simulator.GetState().robots[0].friction_holdoff.at(0), 0);  // (run out by now)
  simulator.SetState(saved);
  EXPECT_EQ(simulator.GetState().robots[0].friction_holdoff, saved.robots[0].friction_holdoff);
  simulator.controller(0).SetTorque(VecX::Constant(1, 1.9));
  simulator.Simulate(0.2);
  EXPECT_EQ(simulator.GetRobotConfig(0)[0], q_first[0]);
}

// Self-collision: a fixed base box (link 0), a hinge link without geometry (1) and a box on it
// (2) folded back through the base. Links 0 and 2 may touch only with robotSelfCollisions on
// and when no `noselfcollision` line forbids it; parent and child never do.
int SelfContactPairs(bool self_collisions, const std::string& extra) {
  const std::string text =
      "links \"base\" \"elbow\" \"forearm\"\nparents -1 0 1\n"
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 0.7  1 0 0 0 1 0 0 0 1 0 0 0\n"
      "axis 0 0 1  0 1 0  0 1 0\njointtype r r r\ngeometry \"box.off\" \"\" \"box.off\"\n"
      "mass 1 1 1\nq 0 3.0 0\njoint weld 0\njoint normal 1\njoint normal 2\n"
      "driver normal 1\ndriver normal 2\nservoP 0 0\nservoI 0 0\nservoD 0 0\n" +
      extra;
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  world.settings.gravity = core::Vec3::Zero();
  world.settings.robot_self_collisions = self_collisions;
  world.robots.emplace_back();
  EXPECT_TRUE(core::ParseRob(text, test::DataPath("robots/folded.rob"), context, &world.robots[0]))
      << diagnostics.FormatAll();
  core::Simulator simulator(world);
  simulator.controller(0).SetTorque(VecX::Zero(2));
  simulator.Simulate(0.001);
  int pairs = 0;
  for (const core::ContactPair& pair : simulator.contact_pairs()) {
    const core::WorldId a = world.Resolve(pair.a), b = world.Resolve(pair.b);
    EXPECT_NE(std::abs(a.link - b.link), 1) << "parent and child touched";
    if (std::min(a.link, b.link) == 0 && std::max(a.link, b.link) == 2) ++pairs;
  }
  return pairs;
}

TEST(RobotJointTest, SelfCollisionOnlyForAllowedPairs) {
  EXPECT_EQ(SelfContactPairs(true, ""), 1);
  EXPECT_EQ(SelfContactPairs(false, ""), 0);
  EXPECT_EQ(SelfContactPairs(true, "noselfcollision 0 2\n"), 0);
}

}  // namespace
}  // namespace lamina
