// SPDX-License-Identifier: MIT
// The editor's live session (ui/viewer/live_session.h): loading (a failed load keeps the previous
// world and says why), lockstep pacing in whole physics steps, commands carried out in order
// between steps (an edit reaches the document, the simulation and the published frame; undo
// takes it back), the physics on its own thread publishing frames and carrying out commands,
// and a simulation stopped by an error pausing with what to try. No GL.
#include "ui/viewer/live_session.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/edit/edit.h"

namespace lamina::ui {
namespace {

const std::string kBounce =
    std::string(LAMINA_WORLDS_DIR) + "/klampt/simulation_test_worlds/bounce_test.xml";
const std::string kArm = std::string(LAMINA_TEST_DATA_DIR) + "/edit/arm_and_blocks.xml";
constexpr double kFrame = 1.0 / 60.0;

bool Load(LiveSession* session, const std::string& path, std::vector<std::string> sets = {}) {
  core::Diagnostics diagnostics;
  const bool ok = session->Load(path, sets, diagnostics);
  EXPECT_TRUE(ok || diagnostics.HasErrors());
  return ok;
}

// a command that sets row `key` of object 0 (one undo step)
LiveSession::Command SetObjectRow(const std::string& key, core::ParamValue value) {
  return [key, value](core::LiveWorld& world) {
    std::string error;
    const core::ElementRef ref = core::ElementRef::Object(world.document().desc().objects[0].uid);
    const auto edit = core::MakeParamEdit(world.document(), ref, key, value, &error);
    return edit && world.Do(*edit, &error) ? std::string() : error;
  };
}

TEST(LiveSessionTest, LockstepFramesTakeWholeStepsOfTheWallTimeTimesTheSpeed) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kBounce));
  const double h = session.frame()->step;
  for (int i = 0; i < 60; ++i) session.Advance(kFrame);
  // 60 frames of 1/60 s: one second of whole steps, the remainder carried
  EXPECT_NEAR(session.frame()->time, 1.0, h + 1e-12);
  EXPECT_NEAR(session.frame()->time / h, std::round(session.frame()->time / h), 1e-6);
  session.SetSpeed(0.5);
  const double before = session.frame()->time;
  for (int i = 0; i < 60; ++i) session.Advance(kFrame);
  EXPECT_NEAR(session.frame()->time - before, 0.5, h + 1e-12);
  session.SetPlaying(false);
  const double paused_at = session.frame()->time;
  session.Advance(kFrame);
  EXPECT_EQ(session.frame()->time, paused_at);
  EXPECT_FALSE(session.frame()->playing);
}

TEST(LiveSessionTest, AnEditReachesTheFrameAtTheNextStepAndUndoTakesItBack) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kBounce));
  EXPECT_FALSE(session.frame()->dirty);
  const long sequence = session.Post(SetObjectRow("kFriction", {0.25}));
  session.Advance(kFrame);
  std::shared_ptr<const SessionFrame> frame = session.frame();
  EXPECT_EQ(frame->commands_done, sequence);
  EXPECT_EQ(frame->world->objects[0].sim.surface.friction, 0.25);
  EXPECT_TRUE(frame->dirty);
  EXPECT_FALSE(frame->undo_label.empty());
  session.Post([](core::LiveWorld& world) { return world.Undo() ? "" : std::string("no undo"); });
  session.Advance(kFrame);
  frame = session.frame();
  EXPECT_NE(frame->world->objects[0].sim.surface.friction, 0.25);
  EXPECT_FALSE(frame->dirty);
  EXPECT_TRUE(session.TakeMessages().empty());
}

TEST(LiveSessionTest, ARefusedEditSaysWhyAndChangesNothing) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kBounce));
  session.Post(SetObjectRow("kRestitution", {1.5}));
  session.Advance(kFrame);
  const std::vector<std::string> messages = session.TakeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("kRestitution"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("[0, 1]"), std::string::npos) << messages[0];
  EXPECT_FALSE(session.frame()->dirty);
}

TEST(LiveSessionTest, AFailedLoadKeepsThePreviousWorldAndSaysWhy) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kBounce));
  core::Diagnostics diagnostics;
  EXPECT_FALSE(session.Load("/no/such/world.xml", {}, diagnostics));
  EXPECT_NE(diagnostics.FormatAll().find("/no/such/world.xml"), std::string::npos);
  EXPECT_NE(diagnostics.FormatAll().find("no such file"), std::string::npos);
  EXPECT_TRUE(session.frame()->loaded);
  EXPECT_NE(session.frame()->path.find("bounce_test.xml"), std::string::npos);
  EXPECT_FALSE(session.Load(kBounce, {"objects[0].kRestitution=1.5"}, diagnostics));
  EXPECT_NE(diagnostics.FormatAll().find("--set 'objects[0].kRestitution=1.5'"), std::string::npos);
}

TEST(LiveSessionTest, SetArgumentsAreInTheOpenedWorld) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kBounce, {"settings.gravity=0,0,-1.62"}));
  EXPECT_EQ(session.frame()->world->settings.gravity, core::Vec3(0, 0, -1.62));
}

TEST(LiveSessionTest, ThePhysicsThreadRunsCommandsBetweenStepsAndPublishesFrames) {
  LiveSession session(true);
  ASSERT_TRUE(Load(&session, kBounce));
  ASSERT_TRUE(session.frame()->loaded);
  const long sequence = session.Post(SetObjectRow("kFriction", {0.75}));
  session.Flush();
  std::shared_ptr<const SessionFrame> frame = session.frame();
  EXPECT_GE(frame->commands_done, sequence);
  EXPECT_EQ(frame->world->objects[0].sim.surface.friction, 0.75);
  // the simulation advances on its own (no Advance calls); a generous wait, no timing claim
  for (int i = 0; i < 200 && session.frame()->time == 0.0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_GT(session.frame()->time, 0.0);
  session.SetPlaying(false);
  session.Flush();
  const double paused_at = session.frame()->time;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  session.Flush();
  EXPECT_EQ(session.frame()->time, paused_at);
  EXPECT_FALSE(session.TakeSamples().empty());
}

// the latest frame once `done` holds for it (up to 20 s; no timing claim, a generous wait)
std::shared_ptr<const SessionFrame> WaitFor(
    LiveSession* session, const std::function<bool(const SessionFrame& frame)>& done) {
  for (int i = 0; i < 2000 && !done(*session->frame()); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return session->frame();
}

LiveSession::Command SetSettingsRow(const std::string& key, double value) {
  return [key, value](core::LiveWorld& world) {
    std::string error;
    const auto edit =
        core::MakeParamEdit(world.document(), core::ElementRef::Settings(), key, {value}, &error);
    return edit && world.Do(*edit, &error) ? std::string() : error;
  };
}

// The real-time solver choice on the physics thread, with a budget of 0 so that any measured
// cost is too much (the switch does not depend on this machine's speed): the Newton solver (a
// world without robots) runs while the document still says exact and stays unedited; a Reset
// and a rebuild keep the choice; turning it off puts the exact solver back; turning it on again
// chooses again.
TEST(LiveSessionTest, TheSolverChoiceRunsTheNewtonSolverWithoutEditingTheWorld) {
  LiveSession session(true);
  session.SetPhysicsBudget(0.0);
  session.SetSpeed(4.0);
  ASSERT_TRUE(Load(&session, kBounce));
  ASSERT_EQ(session.frame()->solver.type, core::SolverType::kStep);
  std::shared_ptr<const SessionFrame> frame =
      WaitFor(&session, [](const SessionFrame& f) { return f.solver_chosen; });
  ASSERT_TRUE(frame->solver_chosen);
  EXPECT_EQ(frame->solver.type, core::SolverType::kNewton);
  EXPECT_EQ(frame->world->settings.solver, core::SolverType::kStep);
  EXPECT_FALSE(frame->dirty);
  EXPECT_NE(SolverText(*frame).find("chosen for real time"), std::string::npos);
  const std::vector<std::string> messages = session.TakeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("Newton"), std::string::npos) << messages[0];

  session.Post([](core::LiveWorld& world) {
    world.simulator().Reset();
    return std::string();
  });
  session.Post(SetObjectRow("mass", {2.0}));  // rebuilds the simulation
  session.Flush();
  frame = session.frame();
  EXPECT_EQ(frame->world->objects[0].mass, 2.0);
  EXPECT_EQ(frame->solver.type, core::SolverType::kNewton) << "a rebuild dropped the choice";
  EXPECT_TRUE(frame->solver_chosen);
  // tuning QuickStep's iterations is not choosing a solver: the choice stays, with them
  session.Post(SetSettingsRow("quickStepIterations", 35.0));
  session.Flush();
  frame =
      WaitFor(&session, [](const SessionFrame& f) { return f.solver.quick_step_iterations == 35; });
  EXPECT_EQ(frame->solver.type, core::SolverType::kNewton);
  EXPECT_EQ(frame->solver.quick_step_iterations, 35);
  EXPECT_TRUE(frame->solver_chosen);

  session.SetAutoSolver(false);
  frame = WaitFor(&session, [](const SessionFrame& f) { return !f.auto_solver; });
  EXPECT_FALSE(frame->solver_chosen);
  EXPECT_EQ(frame->solver.type, core::SolverType::kStep);
  session.SetAutoSolver(true);
  frame = WaitFor(&session, [](const SessionFrame& f) { return f.solver_chosen; });
  EXPECT_TRUE(frame->solver_chosen);
}

// A world with a robot: the Newton solver takes its hinges, servos and friction too (the same
// answer as dWorldStep), so the choice is the Newton solver there as well.
TEST(LiveSessionTest, TheSolverChoiceRunsTheNewtonSolverInAWorldWithARobot) {
  LiveSession session(true);
  session.SetPhysicsBudget(0.0);
  session.SetSpeed(4.0);
  ASSERT_TRUE(Load(&session, kArm));
  std::shared_ptr<const SessionFrame> frame =
      WaitFor(&session, [](const SessionFrame& f) { return f.solver_chosen; });
  ASSERT_TRUE(frame->solver_chosen);
  EXPECT_EQ(frame->solver.type, core::SolverType::kNewton);
  const std::vector<std::string> messages = session.TakeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("Newton"), std::string::npos) << messages[0];
}

// Choosing a solver in the settings is the user's decision: the choice ends for the world, and
// undoing the edit runs the world's exact solver again without choosing anew.
TEST(LiveSessionTest, ChoosingASolverInTheSettingsEndsTheChoice) {
  LiveSession session(true);
  session.SetPhysicsBudget(0.0);
  session.SetSpeed(4.0);
  ASSERT_TRUE(Load(&session, kBounce));
  ASSERT_TRUE(
      WaitFor(&session, [](const SessionFrame& f) { return f.solver_chosen; })->solver_chosen);
  session.Post(SetSettingsRow("solver", 1.0));  // quick, in the world
  session.Flush();
  std::shared_ptr<const SessionFrame> frame =
      WaitFor(&session, [](const SessionFrame& f) { return !f.solver_chosen; });
  EXPECT_FALSE(frame->solver_chosen);
  EXPECT_EQ(frame->solver.type, core::SolverType::kQuickStep);
  EXPECT_EQ(frame->world->settings.solver, core::SolverType::kQuickStep);
  EXPECT_TRUE(frame->dirty);
  session.Post([](core::LiveWorld& world) { return world.Undo() ? "" : std::string("no undo"); });
  session.Flush();
  // one simulated second later (twice the evidence the choice needs), still the exact solver
  const double undone_at = session.frame()->time;
  frame = WaitFor(&session, [&](const SessionFrame& f) { return f.time > undone_at + 1.0; });
  ASSERT_GT(frame->time, undone_at + 1.0);
  EXPECT_EQ(frame->solver.type, core::SolverType::kStep);
  EXPECT_FALSE(frame->solver_chosen);
}

// An instability the step guard corrects pauses the simulation and names the body; the text and
// the status stay while paused (the status line gets it once) and go when the simulation plays
// again.
TEST(LiveSessionTest, AnInstabilityPausesAndNamesTheBody) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kArm));
  session.Post([](core::LiveWorld& world) {
    world.simulator().SetObjectVelocity(2, {core::Vec3(1e307, 0, 0), core::Vec3(0, 0, 1e307)});
    return std::string();
  });
  for (int i = 0; i < 10 && session.frame()->playing; ++i) session.Advance(kFrame);
  std::shared_ptr<const SessionFrame> frame = session.frame();
  ASSERT_FALSE(frame->playing);
  const int id = frame->world->ObjectId(2);
  EXPECT_NE(frame->problem.find("'falling_block' (id " + std::to_string(id) + ")"),
            std::string::npos)
      << frame->problem;
  EXPECT_NE(frame->problem.find("kStiffness"), std::string::npos) << frame->problem;
  EXPECT_EQ(frame->status, core::StepStatus::kUnstable);
  session.Advance(kFrame);  // paused: still said, and the status with it
  EXPECT_EQ(session.frame()->problem, frame->problem);
  EXPECT_EQ(session.frame()->status, core::StepStatus::kUnstable);
  const std::vector<std::string> messages = session.TakeMessages();
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], frame->problem);
  session.SetPlaying(true);
  session.Advance(kFrame);
  EXPECT_TRUE(session.frame()->problem.empty()) << session.frame()->problem;
  EXPECT_EQ(session.frame()->status, core::StepStatus::kNormal);
}

// An absurd robot velocity (energy beyond a double) is stopped by the step guard before the
// step: the simulation pauses and the message names the robot's links and what to try for a
// robot.
TEST(LiveSessionTest, AnAbsurdRobotVelocityPausesAndNamesTheLinks) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kArm));
  session.Post([](core::LiveWorld& world) {
    const int n = static_cast<int>(world.simulator().GetRobotConfig(0).size());
    world.simulator().SetRobotVelocity(0, core::VecX::Constant(n, 1e300));
    return std::string();
  });
  for (int i = 0; i < 10 && session.frame()->playing; ++i) session.Advance(kFrame);
  const std::shared_ptr<const SessionFrame> frame = session.frame();
  ASSERT_FALSE(frame->playing);
  EXPECT_NE(frame->problem.find("Energy blew up in"), std::string::npos) << frame->problem;
  // what to try is a robot's: not the contact parameters
  EXPECT_NE(frame->problem.find("softer servo gains"), std::string::npos) << frame->problem;
  EXPECT_EQ(frame->problem.find("kStiffness"), std::string::npos) << frame->problem;
  const core::RobotDesc& arm = frame->world->robots[0];
  EXPECT_NE(frame->problem.find("'" + arm.links[1].name + "' (id " +
                                std::to_string(frame->world->RobotLinkId(0, 1)) + ")"),
            std::string::npos)
      << frame->problem;
}

// The taut bridge under QuickStep at 10 ms opens its hinges (docs/stress.md): the frames say
// "joint open" and what to try, and the simulation plays on (nothing was corrected).
TEST(LiveSessionTest, AJointThatCameOpenIsSaidWithoutPausing) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, std::string(LAMINA_WORLDS_DIR) + "/accuracy/bridge_160.xml",
                   {"settings.solver=quick", "settings.timestep=0.01"}));
  int open_frames = 0;
  for (int i = 0; i < 150; ++i) {
    session.Advance(kFrame);
    if (session.frame()->status == core::StepStatus::kJointOpen) ++open_frames;
  }
  const std::shared_ptr<const SessionFrame> frame = session.frame();
  EXPECT_GT(open_frames, 0);
  EXPECT_TRUE(frame->playing);
  EXPECT_NEAR(frame->time, 2.5, 0.01);
  EXPECT_NE(frame->problem.find("A joint came open (up to 0."), std::string::npos)
      << frame->problem;
  EXPECT_NE(frame->problem.find("Newton solver"), std::string::npos) << frame->problem;
  EXPECT_EQ(frame->problem.find("servo"), std::string::npos) << frame->problem;  // no robot
}

TEST(LiveSessionTest, AnErrorPausesTheSimulationAndSaysWhatToTry) {
  LiveSession session(false);
  ASSERT_TRUE(Load(&session, kArm));
  session.Post([](core::LiveWorld& world) {
    core::RobotController& controller = world.simulator().controller(0);
    controller.SetTorque(core::VecX::Constant(controller.driver_count(), 1e200));
    return std::string();
  });
  for (int i = 0; i < 10 && session.frame()->playing; ++i) session.Advance(kFrame);
  const std::shared_ptr<const SessionFrame> frame = session.frame();
  EXPECT_FALSE(frame->playing);
  EXPECT_FALSE(frame->problem.empty());
  EXPECT_NE(frame->problem.find("Undo"), std::string::npos) << frame->problem;
}

}  // namespace
}  // namespace lamina::ui
