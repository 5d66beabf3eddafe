// SPDX-License-Identifier: MIT
// Heavy on light (numerics §6 scene 8, issue 15): a 0.4 m box of 100 kg (or 1000 kg) resting on
// a 1 kg, 0.1 m box on a rigid floor, every box on the 2.5 mm padding layers below it
// (worlds/accuracy/heavy_on_light_100.xml and _1000.xml); friction 0.5, no restitution; 2 s.
// Rigid answer: nothing moves. In Lamina the penetration is the overlap of the boundary layers
// (the cores never touch while it is below the layers' sum), so the error is the deepest layer
// overlap of the run (every pair involves the light box). Beside it: the heavy box's largest and
// final height loss (its centre of mass below its start), how far the light box was pushed
// sideways (squeezed out), and steps whose cores interpenetrated.
//
// Bars (numerics §6: "dWorldStep: no blow-up to 1000:1, penetration ≤ padding (2.5 mm)"), with
// the exact solver at 1 ms and 10 ms: the deepest overlap and the final height loss of the heavy
// box are at most one padding, no core interpenetration, no correction, nothing non-finite.
// Not a bar: the largest height loss, which at 10 ms is 3·g·h² = 2.9 mm for both ratios — the
// boxes are placed exactly where their layers touch, which is not yet a contact, so the light
// box falls freely for one step and the heavy box for two before the contacts hold them; it says
// nothing about the mass ratio.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kHeavyOnLightDuration = 2.0;  // s

// Index of the heaviest object (the heavy box); the others are light boxes.
int Heaviest(const WorldDesc& world) {
  int heaviest = 0;
  for (std::size_t i = 1; i < world.objects.size(); ++i) {
    if (world.objects[i].mass > world.objects[heaviest].mass) heaviest = static_cast<int>(i);
  }
  return heaviest;
}

class HeavyOnLightProbe : public AccuracyProbe {
 public:
  explicit HeavyOnLightProbe(const WorldDesc& world)
      : heavy_(Heaviest(world)), padding_(world.objects.at(0).sim.padding) {
    for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
      if (i != heavy_) light_.push_back(i);
    }
  }
  void Begin(const Simulator& simulator) override {
    heavy_start_ = ObjectCom(simulator, heavy_);
    for (int i : light_) light_start_.push_back(ObjectCom(simulator, i));
  }
  void Observe(const StepEvent& event) override {
    largest_ = std::max(largest_, Sink(event.simulator));
  }
  ProbeResult Finish(const Simulator& simulator) override {
    double sideways = 0.0;  // the light box pushed farthest
    for (std::size_t k = 0; k < light_.size(); ++k) {
      const Vec3 moved = ObjectCom(simulator, light_[k]) - light_start_[k];
      sideways = std::max(sideways, moved.head<2>().norm());
    }
    ProbeResult result{simulator.statistics().max_penetration, {}, ""};
    result.metrics = {{"largest sink m", largest_},
                      {"final sink m", Sink(simulator)},
                      {"light box sideways m", sideways},
                      {"padding m", padding_}};
    if (largest_ > 0.1) result.note = "the heavy box crushed a light one";
    return result;
  }

 private:
  double Sink(const Simulator& simulator) const {
    return heavy_start_.z() - ObjectCom(simulator, heavy_).z();
  }
  int heavy_;
  std::vector<int> light_;
  double padding_;
  Vec3 heavy_start_ = Vec3::Zero();
  std::vector<Vec3> light_start_;
  double largest_ = 0.0;
};

// The run's error (metric "") or a metric, at most the padding, in mm.
BarCheck WithinPadding(const std::vector<const AccuracyRun*>& runs, const std::string& metric) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  return AtMost(runs, {metric, "mm", 1e3}, RunMetric(*runs[0], "padding m"));
}

BarCheck CoresApart(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  check = Stable(runs);
  for (const AccuracyRun* run : runs) {
    check.pass = check.pass && run->unreliable == 0;
    check.measured +=
        "; " + std::to_string(run->unreliable) + " unreliable steps at " + StepText(run->step);
  }
  return check;
}

}  // namespace

AccuracyScene HeavyOnLightScene(int ratio) {
  const std::string heavy = std::to_string(ratio) + " kg";
  AccuracyScene scene;
  scene.name = "heavy_on_light_" + std::to_string(ratio);
  scene.world = scene.name + ".xml";
  scene.title = "Heavy box on a light box, " + std::to_string(ratio) + ":1";
  scene.setup = "0.4 m, " + heavy +
                " box on a 0.1 m, 1 kg box on a rigid floor, friction 0.5, "
                "no restitution, 2.5 mm padding; 2 s";
  scene.metric = "deepest boundary-layer overlap (the penetration)";
  scene.unit = "m";
  scene.answer = "0: nothing moves";
  scene.duration = kHeavyOnLightDuration;
  scene.min_step = 4e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<HeavyOnLightProbe>(world); };
  scene.bars = {
      {"deepest layer overlap ≤ the padding (2.5 mm) at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) { return WithinPadding(runs, ""); }},
      {"heavy box's final height loss ≤ the padding at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) { return WithinPadding(runs, "final sink m"); }},
      {"no core interpenetration, correction or non-finite state at 1 ms and 10 ms",
       {1e-3, 1e-2},
       CoresApart},
  };
  return scene;
}

}  // namespace lamina::core
