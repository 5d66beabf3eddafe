// SPDX-License-Identifier: MIT
// Sliding block to rest (numerics §6 scene 3): a 10 cm, 1 kg block on a rigid floor, both with
// friction 0.5 and no restitution, launched at v₀ = 2 m/s along 0°, 22.5° or 45° from the contact
// frame's first axis (x). Coulomb friction stops it after d = v₀²/(2μg) = 0.408 m and
// t = v₀/(μg) = 0.408 s, on the line it was launched along; it then stays put. A pyramid friction
// cone (ODE's default, Klamp't's 0.707 factor) would stop it short or bend its path off the
// diagonal; Lamina's cone keeps μ in every direction.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scenes.h"
#include "core/contact/surface_blend.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kSlidingDuration = 0.8;
constexpr double kStoppedSpeed = 1e-4;  // m/s: slower than this counts as stopped
constexpr double kSlidingSettle = 0.1;  // s after the stop before creep is measured

class SlidingProbe : public AccuracyProbe {
 public:
  explicit SlidingProbe(const WorldDesc& world) {
    const Vec3 v0 = world.objects.at(0).initial_velocity.linear;
    speed0_ = v0.norm();
    direction_ = v0 / speed0_;
    const double mu =
        BlendSurfaces(world.objects[0].sim.surface, world.terrains.at(0).sim.surface).friction;
    const double g = world.settings.gravity.norm();
    distance_ = speed0_ * speed0_ / (2.0 * mu * g);
    stop_time_ = speed0_ / (mu * g);
  }
  void Begin(const Simulator& simulator) override { p0_ = ObjectCom(simulator, 0); }
  void Observe(const StepEvent& event) override {
    const double speed = ObjectComVelocity(event.simulator, 0).norm();
    if (stopped_at_ < 0.0 && speed < kStoppedSpeed) stopped_at_ = event.time;
    if (settled_at_ < 0.0 && stopped_at_ >= 0.0 && event.time >= stopped_at_ + kSlidingSettle) {
      settled_at_ = event.time;
      settled_ = ObjectCom(event.simulator, 0);
    }
  }
  ProbeResult Finish(const Simulator& simulator) override {
    const Vec3 moved = ObjectCom(simulator, 0) - p0_;
    const double along = moved.dot(direction_);
    const double lateral = (moved - along * direction_).head<2>().norm();
    ProbeResult result{std::abs(along - distance_), {}, ""};
    result.metrics = {{"stop distance m", along},
                      {"lateral m", lateral},
                      {"stop time error s", stopped_at_ < 0.0 ? kInf : stopped_at_ - stop_time_},
                      {"creep m/s", Creep(simulator)}};
    if (stopped_at_ < 0.0) result.note = "never stopped";
    return result;
  }

 private:
  double Creep(const Simulator& simulator) const {
    if (settled_at_ < 0.0 || simulator.time() <= settled_at_) return kInf;
    return (ObjectCom(simulator, 0) - settled_).norm() / (simulator.time() - settled_at_);
  }
  double speed0_ = 0.0, distance_ = 0.0, stop_time_ = 0.0;
  Vec3 direction_ = Vec3::UnitX(), p0_ = Vec3::Zero(), settled_ = Vec3::Zero();
  double stopped_at_ = -1.0, settled_at_ = -1.0;
};

constexpr double kDistance = 2.0 * 2.0 / (2.0 * 0.5 * 9.8);

BarCheck StopDistance(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  std::string text;
  bool pass = true;
  for (const AccuracyRun* run : runs) {
    const double bound = 2.0 * run->step + 0.005 * kDistance;
    pass = pass && run->result.error <= bound;
    text += (text.empty() ? "" : "; ") + Measured(run->result.error, "m") + " at " +
            Measured(run->step * 1e3, "ms") + " (bound " + Measured(bound, "m") + ")";
  }
  return {pass, text};
}

BarCheck StaysOnLine(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double lateral = RunMetric(*runs[0], "lateral m");
  return {lateral <= 0.005 * kDistance, Measured(lateral, "m")};
}

BarCheck StaysPut(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double creep = RunMetric(*runs[0], "creep m/s");
  return {creep < 1e-6, Measured(creep, "m/s")};
}

std::string DegreesText(double degrees) {
  std::string text = Measured(degrees, "");
  return text == "22.5" ? "22_5" : text;
}

}  // namespace

AccuracyScene SlidingBlockScene(double degrees) {
  AccuracyScene scene;
  scene.name = "sliding_block_" + DegreesText(degrees);
  scene.world = scene.name + ".xml";
  scene.title = "Block sliding to rest at " + Measured(degrees, "°");
  scene.setup = "10 cm, 1 kg block, friction 0.5, no restitution, 2.5 mm padding, launched at " +
                Measured(degrees, "°") + " from x at 2 m/s; 0.8 s";
  scene.metric = "stop distance error along the launch direction";
  scene.unit = "m";
  scene.answer = "d = v₀²/(2μg) = 0.408 m at t = v₀/(μg) = 0.408 s, on the launch line";
  scene.duration = kSlidingDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<SlidingProbe>(world); };
  scene.bars = {
      {"stop distance within v₀·h + 0.5 % at 1 ms and 10 ms", {1e-3, 1e-2}, StopDistance},
      {"path stays on the launch line: sideways ≤ 0.5 % of d at 1 ms", {1e-3}, StaysOnLine},
      {"no creep after stopping: < 1e-6 m/s at 1 ms", {1e-3}, StaysPut},
  };
  return scene;
}

}  // namespace lamina::core
