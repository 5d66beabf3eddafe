// SPDX-License-Identifier: MIT
// The editor's live session (ui/viewer/live_session.h): loading (a failed load keeps the previous
// world and says why), lockstep pacing in whole physics steps, commands carried out in order
// between steps (an edit reaches the document, the simulation and the published frame; undo
// takes it back), the physics on its own thread publishing frames and carrying out commands,
// and a simulation stopped by an error pausing with what to try. No GL.
#include "ui/viewer/live_session.h"

#include <chrono>
#include <cmath>
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
