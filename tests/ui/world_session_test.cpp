// SPDX-License-Identifier: MIT
// The viewer's world session: loading (a failed load keeps the previous world and says why),
// stepping in whole physics steps, reset, and the split between the description (as loaded,
// never written) and the poses drawn (the simulation's state) (ui/viewer/world_session.h). No GL.
#include "ui/viewer/world_session.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/world_file.h"
#include "core/model/world_compare.h"

namespace lamina::ui {
namespace {

const std::string kBounce =
    std::string(LAMINA_WORLDS_DIR) + "/klampt/simulation_test_worlds/bounce_test.xml";
// a servoed sphere robot and a block dropped onto a terrain
const std::string kBlock = std::string(LAMINA_WORLDS_DIR) + "/klampt/block.xml";

TEST(WorldSession, LoadsAWorldAndStepsItInWholeSteps) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce)) << session.load_messages().FormatAll();
  ASSERT_TRUE(session.loaded());
  const double step = session.simulator()->sim_step();
  EXPECT_NEAR(session.Advance(10), 10 * step, 1e-12);
  EXPECT_NEAR(session.simulator()->time(), 10 * step, 1e-12);
  EXPECT_EQ(session.Advance(0), 0.0);
}

// the world file as it loads, for comparing with the session's description
core::WorldDesc LoadedFile(const std::string& path) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  EXPECT_TRUE(core::LoadWorldFile(path, context, &world)) << diagnostics.FormatAll();
  return world;
}

std::string Lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// the session's poses are the simulator's state, bit for bit
void ExpectPosesAreTheSimulations(const WorldSession& session) {
  const core::Simulator& simulator = *session.simulator();
  const core::WorldPoses& poses = session.poses();
  ASSERT_EQ(poses.objects.size(), static_cast<size_t>(simulator.object_count()));
  ASSERT_EQ(poses.robots.size(), static_cast<size_t>(simulator.robot_count()));
  for (int i = 0; i < simulator.object_count(); ++i) {
    EXPECT_TRUE(poses.objects[i].matrix() == simulator.GetObjectPose(i).matrix()) << "object " << i;
  }
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const core::VecX q = simulator.GetRobotConfig(r);
    ASSERT_EQ(poses.robots[r].size(), q.size());
    EXPECT_TRUE(poses.robots[r] == q) << "robot " << r;
  }
}

// advances 0.5 s in the viewer's chunks of 2 steps (the session took the poses after each)
void AdvanceHalfASecond(WorldSession* session) {
  const int steps = static_cast<int>(std::lround(0.5 / session->simulator()->sim_step()));
  for (int done = 0; done < steps; done += 2) session->Advance(2);
  EXPECT_NEAR(session->simulator()->time(), 0.5, 1e-9);
}

TEST(WorldSession, DescriptionStaysAsLoadedWhileThePosesFollowTheSimulation) {
  const core::WorldDesc loaded = LoadedFile(kBounce);
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce)) << session.load_messages().FormatAll();
  AdvanceHalfASecond(&session);
  // every sphere fell (2 m up, 0.5 s of free fall: 1.226 m) ...
  ASSERT_EQ(session.poses().objects.size(), loaded.objects.size());
  for (size_t i = 0; i < loaded.objects.size(); ++i) {
    const double drop =
        loaded.objects[i].pose.translation().z() - session.poses().objects[i].translation().z();
    EXPECT_NEAR(drop, 0.5 * 9.8 * 0.25, 0.01) << loaded.objects[i].name;
  }
  ExpectPosesAreTheSimulations(session);
  // ... and the description is the file, poses and initial velocities included
  EXPECT_EQ(Lines(core::CompareWorlds(loaded, session.description(), 0.0)), "");
}

TEST(WorldSession, RobotConfigurationsAreDrawnFromTheSimulationNotWrittenIntoTheDescription) {
  const core::WorldDesc loaded = LoadedFile(kBlock);
  WorldSession session;
  ASSERT_TRUE(session.Load(kBlock)) << session.load_messages().FormatAll();
  ASSERT_EQ(loaded.robots.size(), 1u);
  AdvanceHalfASecond(&session);
  // the block settled onto the terrain and the servoed sphere sagged under gravity: both moved
  EXPECT_GT(
      (session.poses().objects[0].translation() - loaded.objects[0].pose.translation()).norm(),
      1e-3);
  EXPECT_GT((session.poses().robots[0] - loaded.robots[0].config).norm(), 1e-6);
  ExpectPosesAreTheSimulations(session);
  EXPECT_EQ(Lines(core::CompareWorlds(loaded, session.description(), 0.0)), "");
}

TEST(WorldSession, ResetTakesThePosesBackToTheDescription) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce));
  ASSERT_FALSE(session.description().objects.empty());
  const core::Vec3 start = session.description().objects[0].pose.translation();
  EXPECT_EQ((session.poses().objects[0].translation() - start).norm(), 0.0);
  session.AdvanceTime(0.2);
  EXPECT_GT((session.poses().objects[0].translation() - start).norm(), 1e-3);
  session.Reset();
  EXPECT_EQ(session.simulator()->time(), 0.0);
  EXPECT_LT((session.poses().objects[0].translation() - start).norm(), 1e-12);
  ExpectPosesAreTheSimulations(session);
}

TEST(WorldSession, AFailedLoadKeepsThePreviousWorldAndSaysWhy) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce));
  const std::string name = session.description().name;
  EXPECT_FALSE(session.Load("/no/such/world.xml"));
  EXPECT_TRUE(session.loaded());
  EXPECT_EQ(session.description().name, name);
  EXPECT_TRUE(session.load_messages().HasErrors());
  EXPECT_NE(session.load_messages().FormatAll().find("/no/such/world.xml"), std::string::npos);
}

// lamina --set: the arguments change the loaded description before its simulation is built; a
// refused one fails the load and names the argument
TEST(WorldSession, SetArgumentsApplyToTheDescriptionBeforeTheSimulationIsBuilt) {
  WorldSession session;
  ASSERT_TRUE(session.Load(kBounce, {"settings.gravity=0,0,-1.62", "objects[0].kFriction=0.25"}))
      << session.load_messages().FormatAll();
  EXPECT_EQ(session.description().settings.gravity, core::Vec3(0, 0, -1.62));
  EXPECT_EQ(session.simulator()->world().objects[0].sim.surface.friction, 0.25);
  const double z = session.poses().objects[0].translation().z();
  session.AdvanceTime(0.1);  // free fall on the moon: g t² / 2
  EXPECT_NEAR(z - session.poses().objects[0].translation().z(), 0.5 * 1.62 * 0.01, 1e-4);
  EXPECT_FALSE(session.Load(kBounce, {"objects[0].kRestitution=1.5"}));
  EXPECT_NE(session.load_messages().FormatAll().find(
                "--set 'objects[0].kRestitution=1.5': objects[0].kRestitution must be in [0, 1]"),
            std::string::npos)
      << session.load_messages().FormatAll();
  EXPECT_EQ(session.description().settings.gravity, core::Vec3(0, 0, -1.62));  // kept
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
