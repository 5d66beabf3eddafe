// SPDX-License-Identifier: MIT
// Slide to roll (numerics §6 scene 5, Drake's bowling ball): a solid ball, r = 0.10795 m,
// m = 6.35 kg, I = ⅖·m·r² = 0.0296 kg·m², launched at v₀ = 8 m/s along x on a rigid lane,
// friction 0.12, without spin (worlds/accuracy/slide_to_roll.xml) or with Drake's side spin
// ω₀ = 8π rad/s about the launch direction (slide_to_roll_spin.xml); 2.5 s. The contact point
// slips at s = v + ω × (−R·n) (n the lane's normal, +z); kinetic friction −μ·m·g·ŝ slows the
// slip along its own direction, which therefore stays fixed:
//   s(t) = s₀ − μ·g·(1 + m·R²/I)·t·ŝ₀,
// so rolling starts at t_roll = |s₀| / (μ·g·(1 + β)), β = m·R²/I, and the ball then rolls on at
// v₀ − μ·g·t_roll·ŝ₀. Without spin: t_roll = 2v₀/(7μg) = 1.944 s, 5/7·v₀ = 5.714 m/s. With the
// side spin, s₀ = (8, 2.712, 0) m/s: the ball hooks, t_roll = 2.052 s, v = (5.714, −0.775, 0) m/s
// (Drake's answer in its axes). The speed along the launch is 5/7·v₀ whatever the spin. R is the
// lever arm of the contact: the padded radius (the ball is preshrunk, so it is r; without
// preshrink it would be r + padding, 2.3 % more, and the final speed 1.3 % higher). Mass,
// inertia, radius, padding, μ, v₀ and ω₀ are all read from the world.
//
// The error is the relative error of the final velocity (|v − v_roll| / |v_roll|); t_roll is the
// first step after which the slip is below 1e-6·v₀. Bars as numerics §6 (Drake's): |Δv| < 0.5 %,
// |Δt_roll| < 5 steps.
//
// Measured beside the bars: the error falls with h down to 1 ms (2e-8) and then rises again
// (2.6e-7 at 0.1 ms, 5.8e-6 at 0.01 ms, where the roll also starts 20 steps late): the rolling
// ball's friction anchor is re-anchored only after every 0.01 rad of turn, and until then it asks
// for a tangential velocity of 0.2·drift/h, which at small h makes the contact slip back and forth
// (with frictionAnchorGain 0: 4e-11 and 5e-12). Far inside the bars, so not a bar.
#include <cmath>
#include <string>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/contact/surface_blend.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kSlideToRollDuration = 2.5;  // s

// The ball's rolling answer from the world: lane normal +z, the ball object 0 on terrain 0.
struct RollAnswer {
  Vec3 launch;          // unit, of the initial velocity
  Vec3 final_velocity;  // once rolling, m/s
  double radius = 0.0;  // lever arm of the contact, m
  double roll_time = 0.0, v0 = 0.0;
};

double LeverArm(const RigidObjectDesc& ball) {
  const double radius = ball.geometry.primitive.radius * ball.geometry.scale.x();
  return ball.sim.preshrink == Preshrink::kNone ? radius + ball.sim.padding : radius;
}

// Velocity of the contact point of a ball of radius `radius` on a lane of normal +z.
Vec3 SlipOf(const Vec3& velocity, const Vec3& omega, double radius) {
  return velocity + omega.cross(Vec3(0, 0, -radius));
}

RollAnswer ReadAnswer(const WorldDesc& world) {
  const RigidObjectDesc& ball = world.objects.at(0);
  const double mu = BlendSurfaces(ball.sim.surface, world.terrains.at(0).sim.surface).friction;
  const double g = world.settings.gravity.norm();
  RollAnswer answer;
  const Vec3 v0 = ball.initial_velocity.linear;
  answer.v0 = v0.norm();
  answer.launch = v0 / answer.v0;
  answer.radius = LeverArm(ball);
  const Vec3 slip0 = SlipOf(v0, ball.initial_velocity.angular, answer.radius);
  const Vec3 direction = slip0.normalized();
  const Vec3 axis = Vec3::UnitZ().cross(direction);  // the friction torque's
  const Mat3 inertia = ball.pose.linear() * ball.inertia * ball.pose.linear().transpose();
  const double beta = ball.mass * answer.radius * answer.radius / axis.dot(inertia * axis);
  answer.roll_time = slip0.norm() / (mu * g * (1.0 + beta));
  answer.final_velocity = v0 - mu * g * answer.roll_time * direction;
  return answer;
}

class SlideToRollProbe : public AccuracyProbe {
 public:
  explicit SlideToRollProbe(const WorldDesc& world) : answer_(ReadAnswer(world)) {}
  void Begin(const Simulator&) override {}
  void Observe(const StepEvent& event) override {
    if (rolling_at_ >= 0.0) return;
    if (Slip(event.simulator) < 1e-6 * answer_.v0) rolling_at_ = event.time;
  }
  ProbeResult Finish(const Simulator& simulator) override {
    const Vec3 velocity = ObjectComVelocity(simulator, 0);
    const double dt = rolling_at_ < 0.0 ? kInf : rolling_at_ - answer_.roll_time;
    const Vec3 expected = answer_.final_velocity;
    ProbeResult result{(velocity - expected).norm() / expected.norm(), {}, ""};
    const Vec3 side = Vec3::UnitZ().cross(answer_.launch);
    result.metrics = {{"final speed m/s", velocity.dot(answer_.launch)},
                      {"expected m/s", expected.dot(answer_.launch)},
                      {"final sideways m/s", velocity.dot(side)},
                      {"expected sideways m/s", expected.dot(side)},
                      {"t_roll s", rolling_at_},
                      {"t_roll error steps", std::abs(dt) / simulator.sim_step()}};
    if (rolling_at_ < 0.0) result.note = "never rolled";
    return result;
  }

 private:
  // Speed of the ball's contact point, m/s.
  double Slip(const Simulator& simulator) const {
    const Vec3 slip = SlipOf(ObjectComVelocity(simulator, 0),
                             simulator.GetObjectVelocity(0).angular, answer_.radius);
    return (slip - slip.dot(Vec3::UnitZ()) * Vec3::UnitZ()).norm();
  }
  RollAnswer answer_;
  double rolling_at_ = -1.0;
};

}  // namespace

AccuracyScene SlideToRollScene(bool spin) {
  AccuracyScene scene;
  scene.name = spin ? "slide_to_roll_spin" : "slide_to_roll";
  scene.world = scene.name + ".xml";
  scene.title = spin ? "Bowling ball with side spin hooking into rolling"
                     : "Bowling ball sliding into rolling";
  scene.setup = std::string("solid ball r = 0.10795 m, 6.35 kg, launched at 8 m/s ") +
                (spin ? "with 8π rad/s of spin about its launch direction" : "without spin") +
                ", μ = 0.12, preshrunk (rolls on its padded surface); 2.5 s";
  scene.metric = "relative error of the final (rolling) velocity";
  scene.unit = "";
  scene.answer = spin ? "t_roll = |s₀|/(3.5μg) = 2.052 s, v = (5.714, −0.775, 0) m/s"
                      : "t_roll = 2v₀/(7μg) = 1.944 s, v = 5/7·v₀ = 5.714 m/s";
  scene.duration = kSlideToRollDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<SlideToRollProbe>(world); };
  scene.bars = {
      {"final velocity within 0.5 % at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"", "%", 100.0}, 0.005);
       }},
      {"roll starts within 5 steps of t_roll at 1 ms and 10 ms",
       {1e-3, 1e-2},
       [](const auto& runs) {
         return AtMost(runs, {"t_roll error steps", "steps"}, 5.0);
       }},
  };
  return scene;
}

}  // namespace lamina::core
