// SPDX-License-Identifier: MIT
// LiveWorld: every kind of edit applied to a running simulation and undone restores the
// description and the simulation exactly (the next 200 steps are bit for bit those of a
// simulation that never saw the edit), redo gives back the state the edit left, structural
// edits carry the running state over by uid, gains edited live survive Reset and are saved,
// undoing an edit that stopped the simulation with an error revives it, and the current state
// can become the initial state. The world: tests/data/edit/arm_and_blocks.xml (a PID-driven arm,
// two stacked blocks at rest and a block falling onto the plane).
#include "core/edit/live_world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/edit/state_carry.h"
#include "core/model/world_compare.h"
#include "tests/common/edit_support.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::ExpectSameWorld;

using core::ElementIndex;
using core::LiveWorld;
using core::SimState;
using core::WorldDocument;

constexpr double kStep = 0.001;  // s, one physics step per Simulate call

void Advance(core::Simulator& simulator, int steps) {
  for (int i = 0; i < steps; ++i) simulator.Simulate(kStep);
}

bool StateIsFinite(const SimState& state) {
  for (const core::BodyState& body : state.objects) {
    if (!body.com_position.allFinite() || !body.linear_velocity.allFinite()) return false;
  }
  for (const core::RobotSimState& robot : state.robots) {
    for (const core::BodyState& body : robot.bodies) {
      if (!body.com_position.allFinite() || !body.angular_velocity.allFinite()) return false;
    }
  }
  return true;
}

// steps both simulations and expects bit-identical states after every step
void ExpectSameTrajectory(core::Simulator& a, core::Simulator& b, int steps) {
  for (int i = 0; i < steps; ++i) {
    a.Simulate(kStep);
    b.Simulate(kStep);
    ASSERT_TRUE(a.GetState() == b.GetState()) << "the states differ after step " << i + 1;
  }
  EXPECT_TRUE(StateIsFinite(a.GetState()));
}

core::Pose Raised(const core::Pose& pose) {
  core::Pose raised = pose;
  raised.translation() += core::Vec3(0.0, 0.5, 0.3);
  return raised;
}

struct EditCase {
  std::string name;
  std::function<core::Edit(const LiveWorld&)> make;
};

// one edit of every kind, made on a running world (objects: base_block, top_block,
// falling_block)
std::vector<EditCase> EveryKindOfEdit() {
  const auto object = [](int i) { return ElementIndex::Object(i); };
  return {
      {"live row (friction)",
       [=](auto& l) { return test::ParamEditOf(l.document(), object(0), "kFriction", {0.05}); }},
      {"live row (servo gain)",
       [](auto& l) {
         return test::ParamEditOf(l.document(), ElementIndex::Driver(0, 0), "servoP", {400.0});
       }},
      {"live row (gravity)",
       [](auto& l) {
         return test::ParamEditOf(l.document(), ElementIndex::Settings(), "gravity", {1, 0, -3});
       }},
      {"geometry row (padding)",
       [=](auto& l) { return test::ParamEditOf(l.document(), object(1), "padding", {0.01}); }},
      {"simulator row (object mass)",
       [=](auto& l) { return test::ParamEditOf(l.document(), object(2), "mass", {3.0}); }},
      {"simulator row (link mass)",
       [](auto& l) {
         return test::ParamEditOf(l.document(), ElementIndex::Link(0, 1), "mass", {2.5});
       }},
      {"initial row (pose)",
       [=](auto& l) {
         const core::Pose pose = l.document().desc().objects[2].pose;
         return test::ParamEditOf(l.document(), object(2), "transform",
                                  core::PoseToValue(Raised(pose)));
       }},
      {"rename",
       [](auto& l) {
         const core::ElementUid robot = l.document().desc().robots[0].uid;
         return core::Edit(
             *core::MakeRenameEdit(l.document(), core::ElementRef::Robot(robot), "crane"));
       }},
      {"add",
       [](auto& l) {
         return core::Edit(core::MakeAddObjectEdit(
             l.document(), test::BoxObject(0.2, 2.0, core::Vec3(3, 0, 0.5)), 1));
       }},
      {"remove",
       [](auto& l) {
         return core::Edit(
             *core::MakeRemoveObjectEdit(l.document(), l.document().desc().objects[1].uid));
       }},
      {"move",
       [](auto& l) {
         return core::Edit(
             *core::MakeMoveObjectEdit(l.document(), l.document().desc().objects[2].uid, 0));
       }},
      {"initial state",
       [](auto& l) {
         return core::Edit(core::MakeInitialStateEdit(l.document(), l.CurrentState()));
       }},
  };
}

// what exact undo stands on: restoring a state is bit for bit (ODE's dBodySetQuaternion
// normalizes again, which changed the last bit of the top block's orientation at 0.2 s)
TEST(LiveWorldTest, RestoringTheCurrentStateChangesNothing) {
  LiveWorld live(test::ArmAndBlocksDocument()), twin(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 200);
  Advance(twin.simulator(), 200);
  const SimState state = live.simulator().GetState();
  live.simulator().SetState(state);
  EXPECT_TRUE(live.simulator().GetState() == state);
  ExpectSameTrajectory(live.simulator(), twin.simulator(), 200);
}

TEST(LiveWorldTest, DoThenUndoOfEveryKindOfEditRestoresTheWorldAndTheSimulationExactly) {
  for (const EditCase& c : EveryKindOfEdit()) {
    SCOPED_TRACE(c.name);
    LiveWorld live(test::ArmAndBlocksDocument());
    core::Simulator reference(live.document().desc());
    Advance(live.simulator(), 200);
    Advance(reference, 200);
    ASSERT_TRUE(live.simulator().GetState() == reference.GetState());
    const SimState before = live.simulator().GetState();
    const core::WorldDesc described = live.document().desc();

    std::string error;
    ASSERT_TRUE(live.Do(c.make(live), &error)) << error;
    EXPECT_FALSE(core::CompareWorlds(described, live.document().desc(), 0.0).empty());
    ASSERT_TRUE(live.Undo(&error)) << error;
    EXPECT_TRUE(live.simulator().GetState() == before);
    ExpectSameWorld(described, live.document().desc());
    EXPECT_TRUE(core::CompareWorlds(reference.world(), live.simulator().world(), 0.0).empty());
    EXPECT_FALSE(live.document().dirty());
    ExpectSameTrajectory(live.simulator(), reference, 200);
  }
}

TEST(LiveWorldTest, RedoRightAfterUndoGivesBackTheStateTheEditLeft) {
  for (const EditCase& c : EveryKindOfEdit()) {
    SCOPED_TRACE(c.name);
    LiveWorld live(test::ArmAndBlocksDocument()),
        twin(test::ArmAndBlocksDocument());  // the twin makes the edit and keeps it
    Advance(live.simulator(), 200);
    Advance(twin.simulator(), 200);
    std::string error;
    ASSERT_TRUE(live.Do(c.make(live), &error)) << error;
    ASSERT_TRUE(twin.Do(c.make(twin), &error)) << error;
    const SimState done = live.simulator().GetState();
    ASSERT_TRUE(twin.simulator().GetState() == done);
    const core::WorldDesc described = live.document().desc();
    const core::Revision revision = live.document().revision();
    ASSERT_TRUE(live.Undo(&error)) << error;
    ASSERT_TRUE(live.Redo(&error)) << error;
    EXPECT_TRUE(live.simulator().GetState() == done);
    ExpectSameWorld(described, live.document().desc());
    EXPECT_EQ(live.document().revision(), revision);
    EXPECT_TRUE(live.document().dirty());
    ExpectSameTrajectory(live.simulator(), twin.simulator(), 200);
  }
}

TEST(LiveWorldTest, UndoAfterSimulatingAppliesTheInverseAndGoesOn) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 200);
  const SimState before = live.simulator().GetState();
  ASSERT_TRUE(live.Do(test::ParamEditOf(live.document(), ElementIndex::Object(2), "mass", {3.0})));
  Advance(live.simulator(), 50);
  const double time = live.simulator().time();
  ASSERT_TRUE(live.Undo());
  EXPECT_EQ(live.simulator().time(), time);  // not rewound
  EXPECT_FALSE(live.simulator().GetState() == before);
  EXPECT_EQ(live.document().desc().objects[2].mass, 1.0);
  EXPECT_EQ(live.simulator().world().objects[2].mass, 1.0);
  // and redo right away restores where the undo was made, exactly
  const SimState undone_at = live.simulator().GetState();
  ASSERT_TRUE(live.Redo());
  ASSERT_TRUE(live.Undo());
  EXPECT_TRUE(live.simulator().GetState() == undone_at);
}

TEST(LiveWorldTest, ARefusedEditChangesNeitherTheDocumentNorTheSimulation) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 100);
  const SimState before = live.simulator().GetState();
  const core::WorldDesc simulated = live.simulator().world();
  const core::Revision revision = live.document().revision();
  std::string error;
  EXPECT_FALSE(live.Do(
      test::ParamEditOf(live.document(), ElementIndex::Object(0), "kRestitution", {1.5}), &error));
  EXPECT_EQ(error, "objects[0].kRestitution must be in [0, 1], got 1.5");
  EXPECT_FALSE(live.Do(core::RenameEdit{core::ElementRef::Object(12345), "x", "y"}, &error));
  EXPECT_EQ(error, "object #12345 is not in the world (removed)");
  EXPECT_TRUE(live.simulator().GetState() == before);
  EXPECT_TRUE(core::CompareWorlds(simulated, live.simulator().world(), 0.0).empty());
  EXPECT_EQ(live.document().revision(), revision);
  EXPECT_FALSE(live.CanUndo());
}

// ---- structural edits carry the running state ---------------------------------------------

TEST(LiveWorldTest, RemovingAnObjectCarriesTheOthersStateByUid) {
  LiveWorld live(test::ArmAndBlocksDocument());
  live.simulator().EnableContactFeedbackAll();
  Advance(live.simulator(), 200);
  const SimState before = live.simulator().GetState();
  ASSERT_TRUE(
      live.Do(*core::MakeRemoveObjectEdit(live.document(), live.document().desc().objects[1].uid)));
  const SimState after = live.simulator().GetState();
  EXPECT_EQ(after.time, before.time);
  ASSERT_EQ(after.objects.size(), 2u);
  EXPECT_TRUE(after.objects[0] == before.objects[0]);
  EXPECT_TRUE(after.objects[1] == before.objects[2]);
  EXPECT_TRUE(after.robots == before.robots);
  // the base block's anchor on the ground (ids 1 and 0) is kept; the top block's are gone
  ASSERT_NE(core::FindAnchor(before.anchors, 1, 0), nullptr);
  ASSERT_NE(core::FindAnchor(after.anchors, 1, 0), nullptr);
  EXPECT_TRUE(*core::FindAnchor(after.anchors, 1, 0) == *core::FindAnchor(before.anchors, 1, 0));
  const auto touches_top = [](const core::FrictionAnchor& a) { return a.a == 2 || a.b == 2; };
  const long top_anchors = std::count_if(before.anchors.begin(), before.anchors.end(), touches_top);
  ASSERT_GT(top_anchors, 0);  // the top block sticks to the base block
  EXPECT_EQ(static_cast<long>(after.anchors.size()),
            static_cast<long>(before.anchors.size()) - top_anchors);
  // feedback pairs renumbered: the falling block (id 3, now 2) with the ground
  const auto pairs = live.simulator().ContactFeedbackPairs();
  EXPECT_NE(std::find(pairs.begin(), pairs.end(), std::make_pair(0, 2)), pairs.end());
}

TEST(LiveWorldTest, AnAddedObjectStartsAtItsInitialPoseAndTheOthersGoOn) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 200);
  const SimState before = live.simulator().GetState();
  core::RigidObjectDesc box = test::BoxObject(0.2, 2.0, core::Vec3(3, 0, 0.5));
  box.initial_velocity.linear = core::Vec3(0.5, 0, 0);
  ASSERT_TRUE(live.Do(core::MakeAddObjectEdit(live.document(), box, 0)));
  const core::Simulator& simulator = live.simulator();
  EXPECT_EQ(simulator.time(), before.time);
  EXPECT_LT((simulator.GetObjectPose(0).translation() - core::Vec3(3, 0, 0.5)).norm(), 1e-15);
  EXPECT_LT((simulator.GetObjectVelocity(0).linear - core::Vec3(0.5, 0, 0)).norm(), 1e-15);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(simulator.GetState().objects[i + 1] == before.objects[i]);
}

TEST(LiveWorldTest, StructuralEditsKeepSolverSleepingAndBodyFlags) {
  LiveWorld live(test::ArmAndBlocksDocument());
  core::Simulator& old = live.simulator();
  old.SetSolver({core::SolverType::kQuickStep, 30});
  old.SetSleeping(true);
  old.body(3).Enable(false);          // falling_block
  old.body(2).EnableDynamics(false);  // top_block
  old.EnableContactFeedback(3, 0);
  Advance(old, 100);
  ASSERT_TRUE(live.Do(
      *core::MakeMoveObjectEdit(live.document(), live.document().desc().objects[2].uid, 0)));
  core::Simulator& now = live.simulator();
  EXPECT_EQ(now.solver().type, core::SolverType::kQuickStep);
  EXPECT_EQ(now.solver().quick_step_iterations, 30);
  EXPECT_TRUE(now.sleeping());
  EXPECT_FALSE(now.body(1).enabled());  // falling_block is object 0 now
  EXPECT_TRUE(now.body(2).enabled());
  EXPECT_FALSE(now.body(3).dynamics_enabled());  // top_block is object 2
  EXPECT_TRUE(now.body(2).dynamics_enabled());
  EXPECT_EQ(now.ContactFeedbackPairs(), (std::vector<std::pair<int, int>>{{0, 1}}));
}

TEST(StateCarryTest, WorldIdsAndStatesFollowTheirUids) {
  core::WorldLayout from{{1}, {10, 11, 12}, {20}, {2}};
  core::WorldLayout to{{1}, {12, 13, 10}, {20}, {2}};  // 11 removed, 13 added, 12 first
  EXPECT_EQ(core::MapWorldIds(from, to), (std::vector<int>{0, 3, -1, 1, 4, 5, 6}));

  SimState state, initial;
  state.time = 2.5;
  for (int i = 0; i < 3; ++i) {
    core::BodyState body;
    body.com_position = core::Vec3(i, 0, 0);
    state.objects.push_back(body);
    state.sleep.push_back({0.1 * i, i == 2});
    body.com_position = core::Vec3(0, 0, -i);
    initial.objects.push_back(body);
    initial.sleep.push_back({});
  }
  state.robots.resize(1);
  state.robots[0].joints.turns = {1, 2};
  initial.robots.resize(1);
  core::FrictionAnchor on_ground{1, 0, core::Mat3::Identity(), core::Vec3(1, 2, 3)};
  core::FrictionAnchor of_removed{2, 0, core::Mat3::Identity(), core::Vec3::Zero()};
  const core::Mat3 turn = Eigen::AngleAxisd(0.5, core::Vec3::UnitZ()).toRotationMatrix();
  core::FrictionAnchor stacked{1, 3, turn, core::Vec3(0, 0, 0.1)};  // 10 on 12
  state.anchors = {on_ground, stacked, of_removed};

  // in `to`: the terrain 0 is static, the objects 1..3 and the robot's link 5 move
  const std::vector<bool> moves = {false, true, true, true, false, true, true};
  const SimState carried = core::CarryState(from, state, to, moves, initial);
  EXPECT_EQ(carried.time, 2.5);
  EXPECT_TRUE(carried.objects[0] == state.objects[2]);
  EXPECT_TRUE(carried.objects[1] == initial.objects[1]);  // new: its own start
  EXPECT_TRUE(carried.objects[2] == state.objects[0]);
  EXPECT_EQ(carried.sleep[0], state.sleep[2]);
  EXPECT_EQ(carried.sleep[1], core::ObjectSleep{});
  EXPECT_EQ(carried.robots[0].joints.turns, (std::vector<int>{1, 2}));
  ASSERT_EQ(carried.anchors.size(), 2u);
  const core::FrictionAnchor* ground = core::FindAnchor(carried.anchors, 3, 0);
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(ground->position, core::Vec3(1, 2, 3));
  // 10 (now id 3) on 12 (now id 1): the lower id moves, so the anchor is 12's in 10's frame
  const core::FrictionAnchor* swapped = core::FindAnchor(carried.anchors, 1, 3);
  ASSERT_NE(swapped, nullptr);
  EXPECT_LT((swapped->rotation * turn - core::Mat3::Identity()).norm(), 1e-15);
  EXPECT_LT((swapped->rotation * core::Vec3(0, 0, 0.1) + swapped->position).norm(), 1e-15);

  EXPECT_EQ(core::CarryPairs(core::MapWorldIds(from, to), {{0, 1}, {0, 2}, {1, 3}, {5, 3}}),
            (std::vector<std::pair<int, int>>{{0, 3}, {1, 3}, {1, 5}}));
}

// ---- gains, revival, initial state --------------------------------------------------------

TEST(LiveWorldTest, GainsEditedLiveSurviveResetAndAreSaved) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 100);
  ASSERT_TRUE(
      live.Do(test::ParamEditOf(live.document(), ElementIndex::Driver(0, 0), "servoP", {321.0})));
  ASSERT_TRUE(live.Do(
      test::ParamEditOf(live.document(), ElementIndex::Driver(0, 0), "dryFriction", {0.75})));
  EXPECT_EQ(live.simulator().controller(0).drivers()[0].servo_p, 321.0);
  live.simulator().Reset();
  EXPECT_EQ(live.simulator().controller(0).drivers()[0].servo_p, 321.0);
  EXPECT_EQ(live.simulator().controller(0).drivers()[0].dry_friction, 0.75);

  core::Diagnostics diagnostics;
  ASSERT_TRUE(live.SaveAs(test::ScratchDir() + "/gains.xml", diagnostics))
      << diagnostics.FormatAll();
  EXPECT_FALSE(live.document().dirty());
  WorldDocument loaded;
  ASSERT_TRUE(loaded.Load(live.document().path(), diagnostics)) << diagnostics.FormatAll();
  EXPECT_EQ(loaded.desc().robots[0].drivers[0].servo_p, 321.0);
  EXPECT_EQ(loaded.desc().robots[0].drivers[0].dry_friction, 0.75);
  const std::vector<std::string> differences =
      core::CompareWorlds(live.document().desc(), loaded.desc(), 0.0);
  EXPECT_TRUE(differences.empty()) << differences.front();
}

// gravity 1e300 makes ODE fail inside its first step (a quaternion it cannot normalize); 1e20
// once did too, through the arm, which the robot guard now puts back (core/sim/robot_guard.h)
TEST(LiveWorldTest, UndoingTheEditThatStoppedTheSimulationRevivesIt) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 100);
  const SimState recorded = live.simulator().GetState();
  ASSERT_TRUE(live.Do(
      test::ParamEditOf(live.document(), ElementIndex::Settings(), "gravity", {0, 0, -1e300})));
  for (int i = 0; i < 100 && !live.simulator().halted(); ++i) live.simulator().Simulate(kStep);
  ASSERT_TRUE(live.simulator().halted());
  EXPECT_EQ(live.simulator().Simulate(kStep), core::StepStatus::kError);

  ASSERT_TRUE(live.Undo());
  EXPECT_FALSE(live.simulator().halted());
  EXPECT_TRUE(live.simulator().GetState() == recorded);
  core::Simulator fresh(live.document().desc());
  fresh.SetState(recorded);
  for (int i = 0; i < 200; ++i) {
    ASSERT_NE(live.simulator().Simulate(kStep), core::StepStatus::kError) << "step " << i;
    fresh.Simulate(kStep);
  }
  EXPECT_TRUE(StateIsFinite(live.simulator().GetState()));
  EXPECT_TRUE(live.simulator().GetState() == fresh.GetState());
}

TEST(LiveWorldTest, AStructuralEditOfAStoppedSimulationStartsItFromTheInitialState) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 100);
  ASSERT_TRUE(live.Do(
      test::ParamEditOf(live.document(), ElementIndex::Settings(), "gravity", {0, 0, -1e300})));
  for (int i = 0; i < 100 && !live.simulator().halted(); ++i) live.simulator().Simulate(kStep);
  ASSERT_TRUE(live.simulator().halted());
  ASSERT_TRUE(
      live.Do(*core::MakeRemoveObjectEdit(live.document(), live.document().desc().objects[0].uid)));
  EXPECT_FALSE(live.simulator().halted());
  EXPECT_EQ(live.simulator().time(), 0.0);
  EXPECT_LT((live.simulator().GetObjectPose(0).translation() - core::Vec3(1, 0, 0.15)).norm(),
            1e-15);
  // undoing it cannot go back to the broken state: the object comes back, nothing else moves
  ASSERT_TRUE(live.Undo());
  EXPECT_FALSE(live.simulator().halted());
  EXPECT_EQ(live.simulator().object_count(), 3);
  EXPECT_EQ(live.simulator().time(), 0.0);
  EXPECT_TRUE(StateIsFinite(live.simulator().GetState()));
  // and undoing the gravity lets it run
  ASSERT_TRUE(live.Undo());
  Advance(live.simulator(), 100);
  EXPECT_FALSE(live.simulator().halted());
  EXPECT_TRUE(StateIsFinite(live.simulator().GetState()));
}

TEST(LiveWorldTest, TheCurrentStateBecomesWhatResetStartsFrom) {
  LiveWorld live(test::ArmAndBlocksDocument());
  Advance(live.simulator(), 250);  // the falling block is still falling
  core::Simulator& simulator = live.simulator();
  const core::Pose pose = simulator.GetObjectPose(2);
  const core::Twist velocity = simulator.GetObjectVelocity(2);
  const core::VecX config = simulator.GetRobotConfig(0);
  const core::VecX rates = simulator.GetRobotVelocity(0);
  ASSERT_GT(-velocity.linear.z(), 1.0);
  const core::WorldDesc original = live.document().desc();
  ASSERT_TRUE(live.MakeCurrentStateInitial());
  EXPECT_TRUE(live.document().dirty());
  Advance(simulator, 100);
  simulator.Reset();
  EXPECT_EQ(simulator.time(), 0.0);
  // through ODE's centre-of-mass state: rounding only
  EXPECT_LT((simulator.GetObjectPose(2).matrix() - pose.matrix()).norm(), 1e-14);
  EXPECT_LT((simulator.GetObjectVelocity(2).linear - velocity.linear).norm(), 1e-14);
  EXPECT_LT((simulator.GetRobotConfig(0) - config).norm(), 1e-12);
  EXPECT_LT((simulator.GetRobotVelocity(0) - rates).norm(), 1e-12);
  EXPECT_EQ(live.document().desc().objects[2].pose.matrix(), pose.matrix());

  ASSERT_TRUE(live.Undo());
  ExpectSameWorld(original, live.document().desc());
  simulator.Reset();
  EXPECT_LT((simulator.GetObjectPose(2).translation() - core::Vec3(2, 0, 0.4)).norm(), 1e-15);
}

// the pose tool edits a paused world's initial poses: at the start (time 0, no step) the body
// shown moves with the edit and undo puts it back exactly; once the world has run, only what
// Reset starts from changes
TEST(LiveWorldTest, AnInitialPoseEditedAtTheStartMovesTheBodyAndUndoPutsItBack) {
  LiveWorld live(test::ArmAndBlocksDocument());
  const core::Pose start = live.simulator().GetObjectPose(2);
  const core::Pose raised = Raised(live.document().desc().objects[2].pose);
  ASSERT_TRUE(live.Do(test::ParamEditOf(live.document(), ElementIndex::Object(2), "transform",
                                        core::PoseToValue(raised))));
  EXPECT_LT((live.simulator().GetObjectPose(2).matrix() - raised.matrix()).norm(), 1e-14);
  EXPECT_EQ(live.simulator().time(), 0.0);
  ASSERT_TRUE(live.Undo());
  EXPECT_EQ(live.simulator().GetObjectPose(2).matrix(), start.matrix());

  Advance(live.simulator(), 10);
  const core::Pose running = live.simulator().GetObjectPose(2);
  ASSERT_TRUE(live.Do(test::ParamEditOf(live.document(), ElementIndex::Object(2), "transform",
                                        core::PoseToValue(raised))));
  EXPECT_EQ(live.simulator().GetObjectPose(2).matrix(), running.matrix());
}

// a slider drag is one entry; when the simulation ran during it, undo applies the old value live
// instead of restoring the state from before the drag (which would throw the run away)
TEST(LiveWorldTest, UndoOfAGroupThatSpannedSimulatedTimeDoesNotRewind) {
  LiveWorld live(test::ArmAndBlocksDocument());
  const core::ElementRef block = core::ElementRef::Object(live.document().desc().objects[0].uid);
  live.BeginGroup("friction drag");
  for (int k = 1; k <= 5; ++k) {
    ASSERT_TRUE(live.Do(*core::MakeParamEdit(live.document(), block, "kFriction", {0.1 * k})));
    Advance(live.simulator(), 20);
  }
  ASSERT_TRUE(live.Do(*core::MakeParamEdit(live.document(), block, "kFriction", {0.9})));
  live.EndGroup();
  const double time = live.simulator().time();
  ASSERT_TRUE(live.Undo());
  EXPECT_EQ(live.simulator().time(), time);  // not rewound to the start of the drag
  EXPECT_EQ(live.document().desc().objects[0].sim.surface.friction,
            test::ArmAndBlocksDocument().desc().objects[0].sim.surface.friction);
  EXPECT_EQ(live.simulator().world().objects[0].sim.surface.friction,
            test::ArmAndBlocksDocument().desc().objects[0].sim.surface.friction);
}

TEST(LiveWorldTest, ObserversOutliveStructuralEditsAndTargetsEndWithThem) {
  LiveWorld live(test::ArmAndBlocksDocument());
  int steps = 0;
  live.AddStepObserver([&](const core::StepEvent&) { ++steps; });
  const int block = live.simulator().world().ObjectId(0);
  core::Pose target = live.simulator().GetObjectPose(0);
  target.translation().z() += 0.05;
  ASSERT_TRUE(live.simulator().SetKinematicTarget(block, target, 0.1));
  Advance(live.simulator(), 10);
  ASSERT_TRUE(live.Do(*core::MakeRenameEdit(
      live.document(), core::ElementRef::Object(live.document().desc().objects[0].uid),
      "renamed")));
  Advance(live.simulator(), 10);
  EXPECT_EQ(steps, 20);  // the new simulation calls the world's observers too
  EXPECT_TRUE(live.simulator().body(block).dynamics_enabled());  // not left kinematic
}

TEST(LiveWorldTest, AnAddedObjectIsCheckedByTheTable) {
  LiveWorld live(test::ArmAndBlocksDocument());
  core::RigidObjectDesc bad = live.document().desc().objects[0];
  bad.uid = 0;
  bad.sim.surface.restitution = 1.5;
  std::string error;
  EXPECT_FALSE(live.Do(core::MakeAddObjectEdit(live.document(), bad), &error));
  EXPECT_THAT(error, ::testing::HasSubstr("kRestitution must be in [0, 1], got 1.5"));
  EXPECT_EQ(live.document().desc().objects.size(),
            test::ArmAndBlocksDocument().desc().objects.size());
}

}  // namespace
}  // namespace lamina
