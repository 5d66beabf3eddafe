// SPDX-License-Identifier: MIT
// Simulator::MirrorStep, the way lamina-peers measures MuJoCo and Bullet with the accuracy
// scenes' own probes: a simulation set to another run's states and told of its steps must give
// a probe exactly what that run gave it. Here the other run is Lamina's own, so the two answers
// must agree to rounding.
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/accuracy/accuracy_scene.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

struct Answers {
  core::ProbeResult original, mirrored;
  double original_time = 0.0, mirrored_time = 0.0;
  long mirrored_steps = 0;
};

// Runs `scene` at 1 ms and, beside it, a mirror fed the run's states after every step.
Answers RunWithMirror(const std::string& name) {
  const core::AccuracyScene* scene = core::FindAccuracyScene(name);
  EXPECT_NE(scene, nullptr) << name;
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("accuracy/" + scene->world), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::WorldDesc world = loaded.world;
  if (scene->adjust) scene->adjust(&world);
  core::Simulator simulator(world), mirror(world);
  const auto probe = scene->probe(world), mirror_probe = scene->probe(world);
  mirror.AddStepObserver([&](const core::StepEvent& event) { mirror_probe->Observe(event); });
  simulator.AddStepObserver([&](const core::StepEvent& event) {
    probe->Observe(event);
    for (int i = 0; i < simulator.object_count(); ++i) {
      mirror.SetObjectPose(i, simulator.GetObjectPose(i));
      mirror.SetObjectVelocity(i, simulator.GetObjectVelocity(i));
    }
    mirror.MirrorStep(event.h, event.contact_joints, event.contacts);
  });
  probe->Begin(simulator);
  mirror_probe->Begin(mirror);
  simulator.Simulate(scene->duration);
  Answers answers{probe->Finish(simulator), mirror_probe->Finish(mirror), simulator.time(),
                  mirror.time(), mirror.statistics().steps};
  EXPECT_EQ(answers.mirrored_steps, simulator.statistics().steps);
  return answers;
}

void ExpectSame(const Answers& answers) {
  const double tolerance = 1e-9 * std::max(1.0, std::abs(answers.original.error));
  EXPECT_NEAR(answers.mirrored.error, answers.original.error, tolerance);
  EXPECT_GT(answers.original.error, 0.0);  // a probe that measured nothing proves nothing
  ASSERT_EQ(answers.mirrored.metrics.size(), answers.original.metrics.size());
  for (std::size_t i = 0; i < answers.original.metrics.size(); ++i) {
    const double expected = answers.original.metrics[i].value;
    EXPECT_NEAR(answers.mirrored.metrics[i].value, expected,
                1e-9 * std::max(1.0, std::abs(expected)))
        << answers.original.metrics[i].name;
  }
  EXPECT_DOUBLE_EQ(answers.mirrored_time, answers.original_time);
}

TEST(MirrorStepTest, AMirroredTumblingBoxGivesItsProbeTheSameEnergyAndMomentumErrors) {
  ExpectSame(RunWithMirror("ballistic_box"));
}

TEST(MirrorStepTest, AMirroredPendulumOnAWorldHingeGivesTheSamePeriodError) {
  ExpectSame(RunWithMirror("pendulum"));
}

// its error is the deepest layer overlap: it reaches the mirror through the contacts passed
TEST(MirrorStepTest, TheMirroredContactsCarryTheDeepestOverlap) {
  ExpectSame(RunWithMirror("heavy_on_light_100"));
}

// its probe reads the simulation's time at the end
TEST(MirrorStepTest, AMirroredInclineKeepsTheTimeItsProbeReads) {
  ExpectSame(RunWithMirror("incline"));
}

TEST(MirrorStepTest, AStepThatIsNotPositiveAndFiniteIsRefusedAndChangesNothing) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("accuracy/ballistic_box.xml"), &loaded);
  ASSERT_TRUE(loaded.ok);
  core::Simulator mirror(loaded.world);
  int seen = 0;
  mirror.AddStepObserver([&seen](const core::StepEvent&) { ++seen; });
  for (double bad : {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      mirror.MirrorStep(bad, 0, {});
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("MirrorStep"), std::string::npos);
    }
  }
  EXPECT_EQ(mirror.time(), 0.0);
  EXPECT_EQ(mirror.statistics().steps, 0);
  EXPECT_EQ(seen, 0);
  mirror.MirrorStep(2e-3, 3, {});
  EXPECT_DOUBLE_EQ(mirror.time(), 2e-3);
  EXPECT_EQ(mirror.statistics().contact_joints, 3);
  EXPECT_EQ(seen, 1);
}

}  // namespace
}  // namespace lamina
