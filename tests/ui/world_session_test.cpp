// SPDX-License-Identifier: MIT
// The viewer's world session: loading (a failed load keeps the previous world and says why),
// stepping in whole physics steps, reset (ui/viewer/world_session.h). No GL.
#include "ui/viewer/world_session.h"

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

const std::string kBounce =
    std::string(LAMINA_WORLDS_DIR) + "/klampt/simulation_test_worlds/bounce_test.xml";

TEST(WorldSession, LoadsAWorldAndStepsItInWholeSteps) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce)) << session.load_messages().FormatAll();
  ASSERT_TRUE(session.loaded());
  const double step = session.simulator()->sim_step();
  EXPECT_NEAR(session.Advance(10), 10 * step, 1e-12);
  EXPECT_NEAR(session.simulator()->time(), 10 * step, 1e-12);
  EXPECT_EQ(session.Advance(0), 0.0);
}

TEST(WorldSession, ShownWorldFollowsTheSimulationAndReset) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce));
  ASSERT_FALSE(session.shown_world().objects.empty());
  const core::Vec3 start = session.shown_world().objects[0].pose.translation();
  session.AdvanceTime(0.2);
  EXPECT_GT((session.shown_world().objects[0].pose.translation() - start).norm(), 1e-3);
  session.Reset();
  EXPECT_EQ(session.simulator()->time(), 0.0);
  EXPECT_LT((session.shown_world().objects[0].pose.translation() - start).norm(), 1e-12);
}

TEST(WorldSession, AFailedLoadKeepsThePreviousWorldAndSaysWhy) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce));
  const std::string name = session.shown_world().name;
  EXPECT_FALSE(session.Load("/no/such/world.xml"));
  EXPECT_TRUE(session.loaded());
  EXPECT_EQ(session.shown_world().name, name);
  EXPECT_TRUE(session.load_messages().HasErrors());
  EXPECT_NE(session.load_messages().FormatAll().find("/no/such/world.xml"), std::string::npos);
}

TEST(WorldSession, NothingLoadedIsHarmless) {
  WorldSession session;
  EXPECT_FALSE(session.Load(std::string(LAMINA_WORLDS_DIR)));  // a directory
  EXPECT_FALSE(session.loaded());
  EXPECT_EQ(session.Advance(5), 0.0);
  session.Reset();
  session.AdvanceTime(1.0);
  session.SetSolver(core::SolverType::kQuickStep);
  EXPECT_EQ(session.simulator(), nullptr);
}

}  // namespace
}  // namespace lamina::ui
