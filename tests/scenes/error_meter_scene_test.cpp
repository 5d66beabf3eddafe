// SPDX-License-Identifier: MIT
// The live accuracy meter on real simulations (core/sim/error_meter.h): on a thrown box its step
// doubling reads ½·g·h per second (the exact local error of ODE's semi-implicit Euler in
// gravity, g·h²/2 per step), which rises with the step; and turning it on changes nothing: the
// states, the statistics and the steps observers see are bit-identical with it on and off, for
// objects in contact and for a robot under control.
#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

WorldDesc Load(const std::string& path) {
  test::LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  return loaded.world;
}

double MeterRate(double step) {
  WorldDesc world = Load(test::WorldsPath("accuracy/ballistic_box.xml"));
  world.settings.timestep = step;
  Simulator simulator(world);
  simulator.SetErrorMeter(true);
  simulator.Simulate(0.5);
  const ErrorMeterReading reading = simulator.error_meter_reading();
  EXPECT_TRUE(reading.valid);
  EXPECT_GE(reading.samples, 1);
  return reading.rate;
}

// full step: x + h·v + h²·g; two halves: x + h·v + ¾·h²·g; rate = 2·(¼·g·h²)/h = ½·g·h
TEST(ErrorMeterSceneTest, BallisticBoxReadsHalfGTimesTheStepAndRisesWithIt) {
  const double at_1ms = MeterRate(1e-3), at_4ms = MeterRate(4e-3);
  EXPECT_NEAR(at_1ms, 0.5 * 9.8 * 1e-3, 0.01 * 0.5 * 9.8 * 1e-3);
  EXPECT_NEAR(at_4ms, 0.5 * 9.8 * 4e-3, 0.01 * 0.5 * 9.8 * 4e-3);
  EXPECT_GT(at_4ms, 3.9 * at_1ms);
}

struct Trace {
  SimState state;
  long steps = 0, observed = 0;
  double kinetic = 0.0;
};

Trace Run(const WorldDesc& world, bool meter, double duration) {
  Simulator simulator(world);
  simulator.SetErrorMeter(meter);
  Trace trace;
  simulator.AddStepObserver([&](const StepEvent&) { ++trace.observed; });
  for (int i = 0; i < 20; ++i) simulator.Simulate(duration / 20);
  trace.state = simulator.GetState();
  trace.steps = simulator.statistics().steps;
  trace.kinetic = simulator.KineticEnergy();
  if (meter) {
    EXPECT_GE(simulator.error_meter_reading().samples, 1);
  }
  return trace;
}

void ExpectSameWithAndWithoutMeter(const std::string& path, double duration) {
  const WorldDesc world = Load(path);
  const Trace off = Run(world, false, duration), on = Run(world, true, duration);
  EXPECT_TRUE(on.state == off.state) << path;
  EXPECT_EQ(on.steps, off.steps);
  EXPECT_EQ(on.observed, off.observed);
  EXPECT_EQ(on.kinetic, off.kinetic);
}

TEST(ErrorMeterSceneTest, SlidingAndBouncingRunsAreBitIdenticalWithTheMeterOn) {
  ExpectSameWithAndWithoutMeter(test::WorldsPath("accuracy/sliding_block_22_5.xml"), 0.6);
  ExpectSameWithAndWithoutMeter(test::WorldsPath("accuracy/bouncing_ball.xml"), 0.8);
}

TEST(ErrorMeterSceneTest, ARobotUnderControlIsBitIdenticalWithTheMeterOn) {
  // 0.15 s: 15 control periods with every sensor type sampled (36 s for 0.5 s under ASan)
  ExpectSameWithAndWithoutMeter(test::WorldsPath("examples/sensors.xml"), 0.15);
}

}  // namespace
}  // namespace lamina::core
