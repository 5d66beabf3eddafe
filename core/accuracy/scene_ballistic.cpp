// SPDX-License-Identifier: MIT
// Ballistic tumbling box (numerics §6 scene 1, the Gazebo "boxes" complex case): a
// 0.1 × 0.4 × 0.9 m, 10 kg box thrown with gravity on and spinning near its intermediate axis (the
// Dzhanibekov case), no contact. The centre of mass follows the parabola p₀ + v₀t + ½gt²; the
// angular momentum about it stays L₀ and the energy E₀. ODE's semi-implicit Euler puts the
// centre of mass exactly ½·g·h·t below the parabola (vₙ₊₁ = vₙ + gh, xₙ₊₁ = xₙ + h·vₙ₊₁), so the
// error bar is that, with first-order convergence.
#include <algorithm>
#include <cmath>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scenes.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

class BallisticProbe : public AccuracyProbe {
 public:
  void Begin(const Simulator& simulator) override {
    p0_ = ObjectCom(simulator, 0);
    v0_ = ObjectComVelocity(simulator, 0);
    g_ = simulator.world().settings.gravity;
    l0_ = ObjectAngularMomentum(simulator, 0);
    e0_ = TotalEnergy(simulator);
  }
  void Observe(const StepEvent& event) override {
    const Simulator& simulator = event.simulator;
    const double t = event.time;
    const Vec3 exact = p0_ + v0_ * t + 0.5 * g_ * t * t;
    position_error_ = std::max(position_error_, (ObjectCom(simulator, 0) - exact).norm());
    const Vec3 l = ObjectAngularMomentum(simulator, 0);
    momentum_drift_ = std::max(momentum_drift_, (l - l0_).norm() / l0_.norm());
    energy_drift_ = std::max(energy_drift_, std::abs(TotalEnergy(simulator) - e0_));
  }
  ProbeResult Finish(const Simulator&) override {
    return {position_error_, {{"L drift", momentum_drift_}, {"energy drift J", energy_drift_}}, ""};
  }

 private:
  Vec3 p0_, v0_, g_, l0_;
  double e0_ = 0.0;
  double position_error_ = 0.0, momentum_drift_ = 0.0, energy_drift_ = 0.0;
};

constexpr double kBallisticDuration = 3.0;

BarCheck HalfGhT(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double bound = 0.5 * 9.8 * runs[0]->step * kBallisticDuration * 1.01;
  const double error = runs[0]->result.error;
  return {error <= bound, Measured(error, "m") + " (bound " + Measured(bound, "m") + ")"};
}

BarCheck FirstOrder(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double order = OrderBetween(runs[0], runs[1]);
  return {std::abs(order - 1.0) <= 0.1, "slope " + Measured(order, "")};
}

BarCheck MomentumKept(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double drift = RunMetric(*runs[0], "L drift");
  return {drift <= 2e-3, Measured(100.0 * drift, "%")};
}

}  // namespace

AccuracyScene BallisticBoxScene() {
  AccuracyScene scene;
  scene.name = "ballistic_box";
  scene.world = "ballistic_box.xml";
  scene.title = "Ballistic tumbling box (Dzhanibekov)";
  scene.setup =
      "0.1 × 0.4 × 0.9 m, 10 kg box thrown at (1, 0, 5) m/s spinning at (0.01, 2, 0.01) rad/s "
      "(near its intermediate axis), gravity on, no contact, 3 s";
  scene.metric = "largest distance of the centre of mass from the parabola";
  scene.unit = "m";
  scene.answer = "p₀ + v₀t + ½gt²; angular momentum and energy constant";
  scene.duration = kBallisticDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc&) { return std::make_unique<BallisticProbe>(); };
  scene.bars = {
      {"error ≤ ½·g·h·T (+1 %) at 1 ms", {1e-3}, HalfGhT},
      {"first order: slope of error against h from 0.1 to 1 ms is 1 ± 0.1",
       {1e-3, 1e-4},
       FirstOrder},
      {"angular momentum drift ≤ 0.2 % at 1 ms", {1e-3}, MomentumKept},
  };
  return scene;
}

}  // namespace lamina::core
