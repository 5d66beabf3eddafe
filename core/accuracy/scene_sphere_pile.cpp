// SPDX-License-Identifier: MIT
// Sphere pile (numerics §6 scene 7, SimBenchmark's "666"): 6 × 6 × 6 spheres of radius 0.1 m
// (a 0.0975 m core and the 2.5 mm padding: the padded surface is SimBenchmark's sphere), 10 kg,
// centres 0.21 m apart, each moved by up to 1 mm sideways, the lowest layer 1 mm above a rigid
// floor (worlds/accuracy/sphere_pile_666.xml, written by make_pile_worlds.py); no friction, no
// restitution, so the cube collapses and the spheres spread over the floor. Rigid answer: no two
// padded spheres overlap, nor a sphere and the floor.
//
// The error is SimBenchmark's "666 penetration metric": after every step, the sum over every
// pair of spheres and every sphere with the floor of the squared overlap of their padded surfaces
// (m²; in Lamina the layers' overlap is the penetration: the cores never touch), averaged over
// time (each step weighted by its length). It is measured from the poses alone, not from the
// contacts the simulator generated. The largest sum and the deepest single overlap are reported
// beside it.
//
// Bars (numerics §6 scene 7): the 666 metric ≤ 2e-4 m² at 1 ms (ODE 1.5e-4, RaiSim 1.4e-4;
// SimBenchmark data/666/sample.csv), every sphere still on the floor at the end, and no
// instability correction, at 1 ms and 10 ms; over numerics' 10 s. Measured: 1.25e-6 m² at 1 ms
// (5.1e-6 at 10 ms); the deepest overlap 2.17 mm at 1 ms and 2.49 mm at 10 ms, within the 2.5 mm
// padding (the cores never touch); adaptive stepping takes back 35 steps at 1 ms and 336 at
// 10 ms while the cube collapses. The run at 1 ms costs 7.4 s of CPU (RTF 1.35), so `make test`
// runs the pile for 1 s (test_duration), where the collapse and nearly all overlap happen.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kPileDuration = 10.0;  // s

// The padded radius of every object (a sphere primitive scaled uniformly, plus its padding), m.
std::vector<double> PaddedRadii(const WorldDesc& world) {
  std::vector<double> radii;
  for (const RigidObjectDesc& object : world.objects) {
    radii.push_back(object.geometry.primitive.radius * object.geometry.scale.x() +
                    object.geometry.margin + object.sim.padding);
  }
  return radii;
}

class PileOverlapProbe : public AccuracyProbe {
 public:
  explicit PileOverlapProbe(const WorldDesc& world)
      : radii_(PaddedRadii(world)), floor_(world.terrains.at(0).sim.padding) {}
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override {
    const double sum = SquaredOverlaps(event.simulator);
    weighted_ += sum * event.h;
    time_ += event.h;
    largest_sum_ = std::max(largest_sum_, sum);
  }
  ProbeResult Finish(const Simulator& simulator) override {
    ProbeResult result{time_ > 0.0 ? weighted_ / time_ : kInf, {}, ""};
    result.metrics = {{"largest sum m2", largest_sum_},
                      {"deepest overlap m", deepest_},
                      {"spheres off the floor", OffTheFloor(simulator)}};
    return result;
  }

 private:
  // Σ overlap² over sphere pairs and spheres on the floor (top z = 0, its padding above), m²
  double SquaredOverlaps(const Simulator& simulator) {
    std::vector<Vec3> centres;
    for (std::size_t i = 0; i < radii_.size(); ++i) {
      centres.push_back(ObjectCom(simulator, static_cast<int>(i)));
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      sum += Counted(radii_[i] + floor_ - centres[i].z());
      for (std::size_t j = i + 1; j < centres.size(); ++j) {
        sum += Counted(radii_[i] + radii_[j] - (centres[i] - centres[j]).norm());
      }
    }
    return sum;
  }
  // spheres whose centre ended below the floor's top (through it, or off its edge)
  double OffTheFloor(const Simulator& simulator) const {
    double count = 0.0;
    for (std::size_t i = 0; i < radii_.size(); ++i) {
      if (!(ObjectCom(simulator, static_cast<int>(i)).z() > 0.0)) count += 1.0;
    }
    return count;
  }
  // overlap² of one pair (0 when apart), keeping the deepest
  double Counted(double overlap) {
    if (overlap <= 0.0) return 0.0;
    deepest_ = std::max(deepest_, overlap);
    return overlap * overlap;
  }

  std::vector<double> radii_;
  double floor_;
  double weighted_ = 0.0, time_ = 0.0, largest_sum_ = 0.0, deepest_ = 0.0;
};

}  // namespace

AccuracyScene SpherePileScene() {
  AccuracyScene scene;
  scene.name = "sphere_pile_666";
  scene.world = "sphere_pile_666.xml";
  scene.title = "Pile of 216 frictionless spheres collapsing (SimBenchmark 666)";
  scene.setup =
      "6 × 6 × 6 spheres of radius 0.1 m (2.5 mm padding), 10 kg, 0.21 m apart with 1 mm "
      "sideways perturbations, on a rigid floor; no friction, no restitution; " +
      Measured(kPileDuration, "s");
  scene.metric = "666 metric: time-mean of the sum of squared overlaps of the padded surfaces";
  scene.unit = "m²";
  scene.answer = "0: no padded surfaces overlap";
  scene.duration = kPileDuration;
  scene.test_duration = 1.0;
  scene.min_step = 1e-3;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<PileOverlapProbe>(world); };
  scene.bars = {
      {"666 metric ≤ 2e-4 m² at 1 ms",
       {1e-3},
       [](const auto& runs) {
         return AtMost(runs, {"", "m²"}, 2e-4);
       }},
      {"every sphere stays on the floor (no centre below its top) at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"spheres off the floor", "spheres"}, 0.0);
       }},
      {"no instability corrections or non-finite states at 1 ms and 10 ms", {1e-3, 1e-2}, Stable},
  };
  return scene;
}

}  // namespace lamina::core
