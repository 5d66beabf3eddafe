// SPDX-License-Identifier: MIT
// A many-contact patch and the maxContacts sweep (numerics §6 scene 12: "maxContacts ∈ {4, 20,
// 100}"): a 1 kg, 0.1 m tessellated ball (Klamp't's sphere.off, 960 triangles, as in
// stiffness_test.xml) preshrunk under a 4 cm soft layer (k = 500 N/m, critically damped) rests on
// the two-triangle mesh floor (worlds/accuracy/soft_ball_mc4.xml, _mc20, _mc100: the same ball
// with maxContacts 4, 20 and 100); 2 s. It sinks m·g/k = 19.6 mm into its layer, where the
// layer's curved patch gives hundreds of raw contacts per step: the clustering to maxContacts
// decides how many the solver sees. The pair pushes with k times its deepest overlap however
// many contacts it keeps (docs/contact-model.md, "Soft contacts"), so the answer is the same for
// every maxContacts: the overlap m·g/k (k, m, g read from the world), at rest. The error is the
// final overlap's relative error against m·g/k. After 1 s of settling the probe also measures the
// RMS speed of the centre of mass, how far the centre moved, and the range of the contact-joint
// count; the runs' CPU time shows what more contacts cost.
//
// Bars: overlap within 1 % of m·g/k, RMS resting speed < 1e-3 m/s and the contact count steady
// to within 1 over the last second, at 1 ms and 10 ms. Measured (one run, this 2-core machine):
// dWorldStep and the Newton solver hold the overlap to 1e-10 and rest at 1e-7 m/s (maxContacts 4)
// or 1e-9 m/s (20, 100) with a steady count at every maxContacts and step. What maxContacts costs
// at 1 ms: dWorldStep alone runs at 4.7×, 3.5× and 0.29× real time with 4, 20 and 100 contacts
// (its pivoting grows with the cube of the rows), the Newton solver at 4.6×, 4.1× and 3.0×; the
// exact solver gives an island of 8 contacts or more to the Newton solver (object_islands.h).
// QuickStep(20) holds with 20 and 100 but not with 4 at 10 ms: the ball creeps at 5 cm/s
// (3.7 cm in the last second).
#include <cmath>
#include <string>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/contact/surface_blend.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kSoftBallDuration = 2.0;  // s
constexpr double kSoftBallSettle = 1.0;    // s before the resting measurement starts

// m·g/k of object 0 on terrain 0, m.
double ExpectedOverlap(const WorldDesc& world) {
  const RigidObjectDesc& ball = world.objects.at(0);
  const double k = BlendSurfaces(ball.sim.surface, world.terrains.at(0).sim.surface).stiffness;
  return ball.mass * world.settings.gravity.norm() / k;
}

class SoftBallProbe : public AccuracyProbe {
 public:
  explicit SoftBallProbe(const WorldDesc& world) : expected_(ExpectedOverlap(world)) {}
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override { watch_.Observe(event); }
  ProbeResult Finish(const Simulator& simulator) override {
    if (!watch_.Started()) return {kInf, {}, "shorter than the settling time"};
    const double overlap = ObjectLayerOverlap(simulator, simulator.contact_pairs(), 0);
    ProbeResult result{std::abs(overlap - expected_) / expected_, {}, ""};
    result.metrics = {
        {"overlap m", overlap}, {"expected m", expected_}, {"RMS speed m/s", watch_.RmsSpeed()}};
    for (ProbeMetric& metric : watch_.Metrics(simulator)) result.metrics.push_back(metric);
    return result;
  }

 private:
  double expected_;
  RestingWatch watch_{kSoftBallSettle};
};

}  // namespace

AccuracyScene SoftBallScene(int max_contacts) {
  AccuracyScene scene;
  const std::string mc = std::to_string(max_contacts);
  scene.name = "soft_ball_mc" + mc;
  scene.world = scene.name + ".xml";
  scene.title = "Soft mesh ball resting, maxContacts " + mc;
  scene.setup =
      "1 kg, 0.1 m ball of 960 triangles preshrunk under a 4 cm layer with k = 500 N/m, "
      "critically damped, on a two-triangle mesh floor; maxContacts " +
      mc + "; 2 s";
  scene.metric = "relative error of the resting overlap";
  scene.unit = "";
  scene.answer = "overlap m·g/k = 19.6 mm, at rest";
  scene.duration = kSoftBallDuration;
  scene.min_step = 1e-3;  // dWorldStep with 100 contacts runs at 0.03× real time at 0.1 ms
  scene.probe = [](const WorldDesc& world) { return std::make_unique<SoftBallProbe>(world); };
  scene.bars = {
      {"overlap within 1 % of m·g/k at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"", "%", 100.0}, 0.01);
       }},
      {"RMS resting speed < 1e-3 m/s at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"RMS speed m/s", "m/s"}, 1e-3);
       }},
      {"contact count steady to within 1 over the last second at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"contact count range", "contacts"}, 1.0);
       }},
  };
  return scene;
}

}  // namespace lamina::core
