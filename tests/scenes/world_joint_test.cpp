// SPDX-License-Identifier: MIT
// World-level joints (`<simulation><joint>`, Klamp't's ODEJoint) read from world files and
// simulated: a door on a hinge spins up by tau / I about its hinge and stops at its limit, a
// drawer slides to its stop (or, with friction, stops where the friction says), a cabinet held
// to the world by a fixed joint stays in the air while its drawer slides in it; a joint pulled
// apart reads "joint open"; the files round trip and bad joints are refused with their file:line.
#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/edit/document.h"
#include "core/edit/edit.h"
#include "core/io/world_file.h"
#include "core/model/world_compare.h"
#include "core/model/world_summary.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// a box from the unit cube of worlds/klampt/objects: `size` (m) with its x = 0, y = 0 face edge
// at the object's origin when `from_edge`, else centred; mass (kg) and the box's inertia about its
// centre of mass given explicitly
std::string Box(const std::string& name, const Vec3& size, const Vec3& position, double mass,
                bool from_edge) {
  const Vec3 shift = from_edge ? Vec3(0, -size.y() / 2, 0) : Vec3(-size / 2);
  const Vec3 com = from_edge ? Vec3(size.x() / 2, 0, size.z() / 2) : Vec3::Zero();
  const double ixx = mass * (size.y() * size.y() + size.z() * size.z()) / 12;
  const double iyy = mass * (size.x() * size.x() + size.z() * size.z()) / 12;
  const double izz = mass * (size.x() * size.x() + size.y() * size.y()) / 12;
  const auto v = [](const Vec3& x) {
    return std::to_string(x.x()) + " " + std::to_string(x.y()) + " " + std::to_string(x.z());
  };
  return "  <rigidObject name=\"" + name + "\" position=\"" + v(position) + "\">\n" +
         "    <geometry mesh=\"" + test::WorldsPath("klampt/objects/cube.off") + "\" scale=\"" +
         v(size) + "\" translation=\"" + v(shift) + "\"/>\n" + "    <physics mass=\"" +
         std::to_string(mass) + "\" com=\"" + v(com) + "\" inertia=\"" + std::to_string(ixx) +
         " 0 0 0 " + std::to_string(iyy) + " 0 0 0 " + std::to_string(izz) + "\"/>\n" +
         "  </rigidObject>\n";
}

core::WorldDesc Load(const std::string& name, const std::string& xml, std::string* path = nullptr) {
  const std::string file = test::WriteScratchFile(name, xml);
  if (path != nullptr) *path = file;
  test::LoadedWorld loaded;
  test::LoadWorld(file, &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  return loaded.world;
}

// a 10 kg door, 0.8 m wide, 4 cm thick, 2 m tall, hinged at its edge about the vertical axis
// through the origin; `limits` are extra attributes of the joint
std::string DoorWorld(const std::string& limits) {
  return "<world>\n" + Box("door", Vec3(0.8, 0.04, 2.0), Vec3(0, 0, 0.1), 10.0, true) +
         "  <simulation>\n    <joint type=\"hinge\" point=\"0 0 0\" axis=\"0 0 1\"" + limits +
         ">\n      <rigidObject name=\"door\"/>\n    </joint>\n  </simulation>\n</world>\n";
}

// the door's inertia about its hinge: about its centre plus m (w/2)^2
constexpr double kDoorMass = 10.0, kDoorWidth = 0.8, kDoorDepth = 0.04;
constexpr double kDoorInertia =
    kDoorMass * (kDoorWidth * kDoorWidth + kDoorDepth * kDoorDepth) / 12 +
    kDoorMass * (kDoorWidth / 2) * (kDoorWidth / 2);

TEST(WorldJointTest, ADoorSpinsUpByTorqueOverInertiaAboutItsHingeAndDoesNotDrop) {
  core::Simulator simulator(Load("door.xml", DoorWorld("")));
  ASSERT_EQ(simulator.world_joint_count(), 1);
  EXPECT_EQ(simulator.WorldJointPosition(0), 0.0);
  const double torque = 2.0, duration = 0.5;
  core::SimBody door = simulator.body(simulator.world().ObjectId(0));
  for (int k = 0; k < 50; ++k) {
    door.ApplyWrench(Vec3::Zero(), Vec3(0, 0, torque));
    simulator.Simulate(0.01);
  }
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const double alpha = torque / kDoorInertia;
  // right-handed about the axis: the hinge angle grows with a positive torque about +z
  EXPECT_NEAR(simulator.WorldJointRate(0), alpha * duration, 0.005 * alpha * duration);
  EXPECT_NEAR(simulator.WorldJointPosition(0), 0.5 * alpha * duration * duration,
              0.01 * 0.5 * alpha * duration * duration);
  EXPECT_NEAR(door.GetVelocity().angular.z(), alpha * duration, 0.005 * alpha * duration);
  // gravity pulls down the whole time: the hinge holds the door at its height
  EXPECT_NEAR(door.GetTransform().translation().z(), 0.1, 1e-4);
}

TEST(WorldJointTest, ADoorSwingsToItsLimitAndStaysThere) {
  core::Simulator simulator(Load("door_limit.xml", DoorWorld(" min=\"-0.2\" max=\"0.5\"")));
  core::SimBody door = simulator.body(simulator.world().ObjectId(0));
  for (int k = 0; k < 200; ++k) {
    door.ApplyWrench(Vec3::Zero(), Vec3(0, 0, 5.0));
    simulator.Simulate(0.01);
  }
  EXPECT_NEAR(simulator.WorldJointPosition(0), 0.5, 0.01);
  EXPECT_NEAR(simulator.WorldJointRate(0), 0.0, 0.01);
}

// a 2 kg drawer (0.4 x 0.4 x 0.1 m) on a slider along x to the world, pulled out at 1 m/s
std::string DrawerWorld(const std::string& extra) {
  return "<world>\n" + Box("drawer", Vec3(0.4, 0.4, 0.1), Vec3(0, 0, 1), 2.0, false) +
         "  <simulation>\n    <object index=\"0\"><velocity linear=\"1 0 0\"/></object>\n" +
         "    <joint type=\"slider\" axis=\"1 0 0\" min=\"0\" max=\"0.3\"" + extra +
         ">\n      <rigidObject index=\"0\"/>\n    </joint>\n  </simulation>\n</world>\n";
}

// Klamp't reads a joint's upper limit from "minimax" (its reader's typo), so its files may say so
TEST(WorldJointTest, KlamptsMinimaxIsReadAsTheUpperLimitWithAWarning) {
  const std::string xml = DoorWorld(" minimax=\"0.7\"");
  const std::string file = test::WriteScratchFile("door_minimax.xml", xml);
  test::LoadedWorld loaded;
  test::LoadWorld(file, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.world.joints[0].max, 0.7);
  EXPECT_THAT(loaded.diagnostics.Messages(core::Severity::kWarning),
              ElementsAre(file + ":7: warning: <joint>: 'minimax' is read as the upper limit, as "
                                 "Klamp't reads it"));
}

TEST(WorldJointTest, ADrawerSlidesToItsStop) {
  core::Simulator simulator(Load("drawer.xml", DrawerWorld("")));
  simulator.Simulate(1.0);
  EXPECT_NEAR(simulator.WorldJointPosition(0), 0.3, 0.002);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), 0.3, 0.002);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.norm(), 0.0, 0.01);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 1.0, 1e-4);  // held up
}

TEST(WorldJointTest, SliderFrictionStopsTheDrawerWhereTheFrictionSays) {
  // 5 N against 2 kg at 1 m/s: 2.5 m/s^2 for 0.4 s, stopping after v^2 / 2a = 0.2 m
  core::Simulator simulator(Load("drawer_friction.xml", DrawerWorld(" friction=\"5\"")));
  simulator.Simulate(1.0);
  EXPECT_NEAR(simulator.WorldJointPosition(0), 0.2, 0.002);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.x(), 0.0, 1e-3);
}

// a 20 kg cabinet held to the world by a fixed joint 1 m up, and a 2 kg drawer in it on a slider
// along x (`slider`: the slider's extra attributes; `drawer`: the drawer's <object> settings)
std::string CabinetWorld(const std::string& slider, const std::string& drawer) {
  return "<world>\n" + Box("cabinet", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1), 20.0, false) +
         Box("drawer", Vec3(0.4, 0.4, 0.1), Vec3(0, 0, 1.1), 2.0, false) +
         "  <simulation>\n    <globals rigidObjectCollisions=\"0\"/>\n" + drawer +
         "    <joint type=\"fixed\"><rigidObject name=\"cabinet\"/></joint>\n"
         "    <joint type=\"slider\" axis=\"1 0 0\"" +
         slider +
         ">\n"
         "      <rigidObject name=\"drawer\"/><rigidObject name=\"cabinet\"/>\n    </joint>\n"
         "  </simulation>\n</world>\n";
}

TEST(WorldJointTest, AFixedJointHoldsACabinetWhoseDrawerSlidesInIt) {
  core::Simulator simulator(
      Load("cabinet.xml",
           CabinetWorld(" max=\"0.25\"",
                        "    <object index=\"1\"><velocity linear=\"0.5 0 0\"/></object>\n")));
  ASSERT_EQ(simulator.world_joint_count(), 2);
  simulator.Simulate(1.5);
  EXPECT_TRUE(simulator.GetObjectPose(0).translation().isApprox(Vec3(0, 0, 1), 1e-4));
  EXPECT_NEAR(simulator.GetObjectPose(1).translation().x(), 0.25, 0.002);
  EXPECT_NEAR(simulator.GetObjectPose(1).translation().z(), 1.1, 1e-4);
  EXPECT_NEAR(simulator.WorldJointPosition(1), 0.25, 0.002);  // the drawer in the cabinet
}

// the step guard's watch on the world's joints (robot_guard.h, joint_projection.h's JointGap): the
// door stays closed to ERP's drift, and a joint pulled apart reads "joint open" for the steps its
// gap stays over its break gap: for the door 10 % of the 1.17 m from its hinge's point to its
// centre of mass
TEST(WorldJointTest, AHingedDoorStaysClosed) {
  core::Simulator simulator(Load("door_open.xml", DoorWorld("")));
  core::SimBody door = simulator.body(simulator.world().ObjectId(0));
  for (int k = 0; k < 50; ++k) {
    door.ApplyWrench(Vec3::Zero(), Vec3(0, 0, 2.0));
    EXPECT_EQ(simulator.Simulate(0.01), core::StepStatus::kNormal);
  }
  EXPECT_EQ(simulator.statistics().joint_open_steps, 0);
  EXPECT_LT(simulator.statistics().max_joint_gap, 1e-4);
}

// a world whose joints close slowly: 0.2 % of a gap per step (ERP), so that closing a gap of
// 0.3 m gives the door 0.6 m/s, not the 6 m/s the energy check would stop at ERP 0.02
std::string SlowlyClosing(std::string xml) {
  const std::string simulation = "<simulation>\n";
  return xml.replace(xml.find(simulation), simulation.size(),
                     simulation + "    <globals ERP=\"0.002\"/>\n");
}

TEST(WorldJointTest, ADoorPulledOffItsHingeReadsJointOpenUntilTheHingeClosesIt) {
  core::Simulator simulator(Load("door_open.xml", SlowlyClosing(DoorWorld(""))));
  ASSERT_EQ(simulator.world().settings.erp, 0.002);
  // a teleport 0.3 m off the hinge (as a script or a bad edit might): the hinge pulls it back
  // over many steps, and those steps say so
  core::Pose pulled = simulator.GetObjectPose(0);
  const Vec3 hinge_point = pulled * Vec3::Zero();  // the door's origin is on its hinge
  pulled.translation() += Vec3(0.3, 0, 0);
  simulator.SetObjectPose(0, pulled);
  EXPECT_EQ(simulator.Simulate(0.001), core::StepStatus::kJointOpen);
  EXPECT_GT(simulator.statistics().max_joint_gap, 0.117);
  EXPECT_EQ(simulator.statistics().joint_open_steps, 1);
  simulator.Simulate(3.0);
  // open while 0.3 m·0.998^n > 0.117 m: for about 470 steps of 1 ms
  EXPECT_NEAR(simulator.statistics().joint_open_steps, 470, 30);
  EXPECT_LT((simulator.GetObjectPose(0) * Vec3::Zero() - hinge_point).norm(), 1e-3);
  EXPECT_EQ(simulator.Simulate(0.01), core::StepStatus::kNormal);  // closed again
}

TEST(WorldJointTest, AFixedJointAndASliderPulledApartReadJointOpen) {
  core::Simulator simulator(
      Load("cabinet_open.xml", SlowlyClosing(CabinetWorld(" min=\"-1\" max=\"1\"", ""))));
  EXPECT_EQ(simulator.Simulate(0.5), core::StepStatus::kNormal);
  EXPECT_LT(simulator.statistics().max_joint_gap, 1e-4);
  // the drawer along its slider: travel, not a gap
  core::Pose drawer = simulator.GetObjectPose(1);
  drawer.translation() += Vec3(0.5, 0, 0);
  simulator.SetObjectPose(1, drawer);
  EXPECT_EQ(simulator.Simulate(0.001), core::StepStatus::kNormal);
  // across it, 5 cm: beyond the 1 cm floor of a slider's break gap
  drawer.translation() += Vec3(0, 0.05, 0);
  simulator.SetObjectPose(1, drawer);
  EXPECT_EQ(simulator.Simulate(0.001), core::StepStatus::kJointOpen);
  simulator.Simulate(1.0);
  core::Pose cabinet = simulator.GetObjectPose(0);
  ASSERT_EQ(simulator.Simulate(0.01), core::StepStatus::kNormal);
  // the cabinet off its fixed joint to the world
  cabinet.translation() += Vec3(0, 0, 0.05);
  simulator.SetObjectPose(0, cabinet);
  EXPECT_EQ(simulator.Simulate(0.001), core::StepStatus::kJointOpen);
}

// ---- in joint coordinates (the Newton solver with jointCoordinates: object_islands.h) --------

constexpr const char* kJointCoordinates =
    "    <globals solver=\"newton\" jointCoordinates=\"1\"/>\n";

// the door as above (gravity pulls across its hinge): the reduced step is symplectic Euler on
// the hinge angle, ω_n = n·h·α and θ_n = h²·α·n(n+1)/2 to rounding (ODE
// turns a body by exactly h·ω in its finite rotation mode), and the hinge keeps the door where it
// is to rounding (the exact solver: 1e-4 m and 1 %, above)
TEST(WorldJointTest, InJointCoordinatesADoorTurnsAsSymplecticEulerOnItsHingeAngle) {
  std::string xml = DoorWorld("");
  xml.replace(xml.find("  <simulation>\n") + 15, 0, kJointCoordinates);
  core::Simulator simulator(Load("door_joints.xml", xml));
  const double torque = 2.0, h = simulator.world().settings.timestep;  // 1 ms
  const int steps = 500;
  core::SimBody door = simulator.body(simulator.world().ObjectId(0));
  for (int k = 0; k < steps; ++k) {
    door.ApplyWrench(Vec3::Zero(), Vec3(0, 0, torque));
    simulator.Simulate(h);
  }
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  EXPECT_EQ(simulator.statistics().reduced_islands, steps);
  // (the file's inertia has six decimals: α within 1e-6)
  const double alpha = torque / kDoorInertia, rate = simulator.WorldJointRate(0);
  EXPECT_NEAR(rate, steps * h * alpha, 1e-6 * steps * h * alpha);
  // θ_n = h·Σ ω_k = h·ω_n·(n + 1)/2 when every step adds the same h·α to ω
  EXPECT_NEAR(simulator.WorldJointPosition(0), h * rate * (steps + 1) / 2, 1e-12);
  EXPECT_NEAR(door.GetTransform().translation().z(), 0.1, 1e-12);
  EXPECT_NEAR(door.GetTransform().translation().norm(), 0.1, 1e-12);  // the edge on the axis
}

TEST(WorldJointTest, InJointCoordinatesADrawerSlidesToItsStopAndStaysOnItsLine) {
  std::string xml = DrawerWorld("");
  xml.replace(xml.find("  <simulation>\n") + 15, 0, kJointCoordinates);
  core::Simulator simulator(Load("drawer_joints.xml", xml));
  simulator.Simulate(1.0);
  EXPECT_EQ(simulator.statistics().reduced_islands, simulator.statistics().steps);  // every one
  EXPECT_NEAR(simulator.WorldJointPosition(0), 0.3, 0.002);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.norm(), 0.0, 0.01);
  const Vec3 at = simulator.GetObjectPose(0).translation();
  EXPECT_NEAR(at.y(), 0.0, 1e-12);
  EXPECT_NEAR(at.z(), 1.0, 1e-12);  // held up, exactly
}

// three 1 m links hung level from the world at x = 0, their joints listed out of order and
// either way round: the island's tree is found from the world outwards (reduced_basis.h
// OrientTree), every step is the reduced one, and every hinge keeps its anchors together
TEST(WorldJointTest, InJointCoordinatesAChainListedInAnyOrderKeepsEveryHingeClosed) {
  std::string xml = "<world>\n";
  for (int i = 0; i < 3; ++i) {
    xml += Box("link" + std::to_string(i), Vec3(1.0, 0.04, 0.04), Vec3(i + 0.5, 0, 2), 1.0, false);
  }
  const auto hinge = [](double x, const std::string& first, const std::string& second) {
    return "    <joint type=\"hinge\" point=\"" + std::to_string(x) +
           " 0 2\" axis=\"0 1 0\"><rigidObject name=\"" + first + "\"/>" +
           (second.empty() ? "" : "<rigidObject name=\"" + second + "\"/>") + "</joint>\n";
  };
  xml += std::string("  <simulation>\n") + kJointCoordinates + hinge(1, "link0", "link1") +
         hinge(2, "link1", "link2") + hinge(0, "link0", "") + "  </simulation>\n</world>\n";
  core::Simulator simulator(Load("chain_joints.xml", xml));
  const int steps = 1000;
  for (int k = 0; k < steps; ++k) simulator.Simulate(1e-3);
  EXPECT_EQ(simulator.statistics().reduced_islands, steps);
  // each hinge's point on both links: x = i m on the level chain, in each link's frame
  for (int i = 0; i < 3; ++i) {
    const core::Pose a = simulator.GetObjectPose(i);
    const Vec3 start_of_link = a * Vec3(-0.5, 0, 0);
    const Vec3 before =
        i == 0 ? Vec3(0, 0, 2) : Vec3(simulator.GetObjectPose(i - 1) * Vec3(0.5, 0, 0));
    EXPECT_NEAR((start_of_link - before).norm(), 0.0, 1e-12) << "hinge " << i;
  }
  // it swings: the free end has fallen well below the pivot
  EXPECT_LT((simulator.GetObjectPose(2) * Vec3(0.5, 0, 0)).z(), 1.5);
}

// the joints follow their objects through the editor's object edits
TEST(WorldJointTest, ObjectEditsKeepTheJointsOnTheirBodiesAndRefuseRemovingAHeldOne) {
  const std::string xml =
      "<world>\n" + Box("cabinet", Vec3(0.5, 0.5, 0.5), Vec3(0, 0, 1), 20.0, false) +
      Box("drawer", Vec3(0.4, 0.4, 0.1), Vec3(0, 0, 1.1), 2.0, false) +
      Box("spare", Vec3(0.1, 0.1, 0.1), Vec3(2, 0, 0.05), 1.0, false) +
      "  <simulation>\n    <joint type=\"fixed\"><rigidObject name=\"cabinet\"/></joint>\n"
      "    <joint type=\"slider\" axis=\"1 0 0\"><rigidObject name=\"drawer\"/>"
      "<rigidObject name=\"cabinet\"/></joint>\n  </simulation>\n</world>\n";
  core::WorldDocument document(Load("cabinet_edit.xml", xml));
  const auto held = [&document](int joint, int body) {
    const core::WorldDesc& desc = document.desc();
    return desc.objects[desc.joints[joint].bodies[body].index].name;
  };
  std::string error;
  ASSERT_TRUE(core::Apply(*core::MakeMoveObjectEdit(document, document.desc().objects[2].uid, 0),
                          &document, &error))
      << error;
  EXPECT_EQ(document.desc().joints[1].bodies[0].index, 2);  // the drawer moved up one
  EXPECT_EQ(held(0, 0), "cabinet");
  EXPECT_EQ(held(1, 0), "drawer");
  EXPECT_EQ(held(1, 1), "cabinet");
  ASSERT_TRUE(core::Apply(*core::MakeRemoveObjectEdit(document, document.desc().objects[0].uid),
                          &document, &error))
      << error;
  EXPECT_EQ(held(1, 0), "drawer");
  EXPECT_EQ(document.desc().joints[1].bodies[0].index, 1);
  EXPECT_FALSE(core::Apply(*core::MakeRemoveObjectEdit(document, document.desc().objects[1].uid),
                           &document, &error));
  EXPECT_EQ(error, "objects[1]: world joint 1 holds it; remove the joint first");
  EXPECT_EQ(document.desc().objects.size(), 2u);
}

TEST(WorldJointTest, JointsRoundTripAndAreListedByInfo) {
  std::string path;
  const core::WorldDesc world =
      Load("door_rt.xml", DoorWorld(" min=\"-0.2\" max=\"1.5\" friction=\"0.5\""), &path);
  ASSERT_EQ(world.joints.size(), 1u);
  EXPECT_EQ(world.joints[0].type, core::WorldJointType::kHinge);
  EXPECT_EQ(world.joints[0].max, 1.5);
  const std::string copy = test::ScratchDir() + "/door_rt_copy.xml";
  core::Diagnostics saved;
  ASSERT_TRUE(core::SaveWorldFile(world, copy, saved)) << saved.FormatAll();
  test::LoadedWorld again;
  test::LoadWorld(copy, &again);
  ASSERT_TRUE(again.ok) << again.diagnostics.FormatAll();
  EXPECT_THAT(core::CompareWorlds(world, again.world, 0.0), ::testing::IsEmpty());
  EXPECT_THAT(core::WorldSummaryText(world),
              HasSubstr("joint 0 (hinge): object 0 'door' to the world, through (0, 0, 0), axis "
                        "(0, 0, 1), limits -0.2 .. 1.5 rad, friction 0.5 N·m\n"));
}

struct BadJoint {
  const char* name;
  std::string joint;  // the <joint> element, on line 3
  std::string error;  // after "path:3: error: "
};

class WorldJointErrorTest : public ::testing::TestWithParam<BadJoint> {};

TEST_P(WorldJointErrorTest, IsRefusedWithItsLine) {
  const BadJoint& bad = GetParam();
  const std::string path = test::WriteScratchFile(
      std::string(bad.name) + ".xml",
      "<world>\n  <rigidObject name=\"box\"><geometry mesh=\"" +
          test::WorldsPath("klampt/objects/cube.off") +
          "\"/><physics mass=\"1\" automass=\"1\"/></rigidObject>\n  <simulation>" + bad.joint +
          "</simulation>\n</world>\n");
  test::LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_FALSE(loaded.ok);
  EXPECT_THAT(loaded.diagnostics.Messages(core::Severity::kError),
              ElementsAre(path + ":3: error: " + bad.error));
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, WorldJointErrorTest,
    ::testing::Values(
        BadJoint{"no_type", "<joint><rigidObject index=\"0\"/></joint>",
                 "<joint>: needs a 'type' attribute: fixed, hinge or slider"},
        BadJoint{"bad_type", "<joint type=\"ball\"><rigidObject index=\"0\"/></joint>",
                 "<joint>: attribute 'type' is 'ball'; expected fixed, hinge or slider"},
        BadJoint{"no_axis", "<joint type=\"slider\"><rigidObject index=\"0\"/></joint>",
                 "<joint>: (slider) needs an 'axis' attribute"},
        BadJoint{"zero_axis",
                 "<joint type=\"slider\" axis=\"0 0 0\"><rigidObject index=\"0\"/></joint>",
                 "<joint>: attribute 'axis' must not be zero"},
        BadJoint{"no_point",
                 "<joint type=\"hinge\" axis=\"0 0 1\"><rigidObject index=\"0\"/></joint>",
                 "<joint>: (hinge) needs a 'point' attribute on its axis"},
        BadJoint{"no_body", "<joint type=\"fixed\"/>",
                 "<joint>: holds 0 bodies; it needs one or two (<rigidObject>, <robot "
                 "body=...>, <terrain>)"},
        BadJoint{"same_body",
                 "<joint type=\"fixed\"><rigidObject index=\"0\"/><rigidObject "
                 "name=\"box\"/></joint>",
                 "<joint>: holds the same body twice"},
        BadJoint{"unordered",
                 "<joint type=\"slider\" axis=\"1 0 0\" min=\"1\" max=\"0\"><rigidObject "
                 "index=\"0\"/></joint>",
                 "<joint>: limits 1 .. 0 must be ordered (min <= max)"},
        BadJoint{"hinge_turns",
                 "<joint type=\"hinge\" point=\"0 0 0\" axis=\"0 0 1\" max=\"4\"><rigidObject "
                 "index=\"0\"/></joint>",
                 "<joint>: a hinge's limits must lie in [-pi, pi] rad (ODE's hinge angle), got "
                 "-inf .. 4"},
        BadJoint{"friction",
                 "<joint type=\"slider\" axis=\"1 0 0\" friction=\"-1\"><rigidObject "
                 "index=\"0\"/></joint>",
                 "<joint>: attribute 'friction' must be >= 0, got -1"}),
    [](const ::testing::TestParamInfo<BadJoint>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace lamina
