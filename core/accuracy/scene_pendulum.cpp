// SPDX-License-Identifier: MIT
// Physical pendulum (numerics §6 scene 2): a 1 m, 2 × 2 cm, 1 kg rod hung by one end from a
// world hinge (worlds/accuracy/pendulum.xml), released from rest at θ₀ = 60°, no contact, 10 s
// (about 5.7 periods). The period of a physical pendulum is
//   T = 4·√(I_pivot/(m·g·d))·K(sin(θ₀/2)),
// with d the distance of the centre of mass from the axis, I_pivot the moment of inertia about the
// axis and K the complete elliptic integral of the first kind (std::comp_ellint_1, modulus);
// 1.7588 s here. All of it is read from the world: the hinge's point and axis, the rod's mass,
// inertia and initial pose. The energy E = KE + PE stays E₀.
//
// The period is measured from the zero crossings of the angle (linear interpolation between
// steps; the angle's curvature vanishes there, so the interpolation adds nothing of order h²),
// averaged over every whole half period of the run. Energy is judged against the swing energy
// m·g·d·(1 − cos θ₀), the energy that trades between kinetic and potential.
//
// Bars (numerics §6 scene 2): a first-order symplectic integrator has a period error of about
// (ωh)²/24 and an energy oscillation of about ωh/2 with no secular drift. ODE's step is
// semi-implicit Euler on the velocities with the hinge solved as a velocity constraint plus a
// correction of its drift with the world's ERP (0.95), which is not symplectic Euler in the angle;
// Lamina then takes back the drift the step left at the hinge (joint_stabilization.h, the world's
// jointStabilization, on by default). ω₀ = √(m·g·d/I) is the small-amplitude frequency
// (numerics' "4e-7 for a 1 m pendulum at 1 ms" uses √(g/L)).
// - Energy: as symplectic Euler (the oscillation is 0.00180 of the swing energy at 1 ms, 0.00180
//   for symplectic Euler on θ, bound ω₀h/2 = 0.00192), and the mean energy of the last period is
//   2.1e-9 of the swing energy below the first's: no secular drift (bar: within 1 % of ω₀h/2).
//   (Moving the rod back onto its hinge along the rows of the end of the step instead, the
//   velocities left as they were, lost 3 % of the swing energy in the 10 s.)
// - Period: 3.06e-7·T at 1 ms, as symplectic Euler on θ (−3.1e-7), within numerics'
//   (ω₀h)²/24 = 6.1e-7, and second order. ODE's step moves the centre of mass along the chord
//   h·v while it turns the rod by h·ω, so the hinge's point the rod carries leaves the axis by
//   ½(ωh)²·d. ODE alone (jointStabilization off, as Klamp't) gives 2.5e-6·T, longer: the ERP
//   pulls the point back a step later, so the rod swings on a slightly longer effective radius
//   (lowering ERP lengthens it further: 5.4e-6 at ERP 0.5, 1.4e-5 at 0.2). Taking that drift back
//   with the impulse at the start of the step that lands the rod on its hinge (SHAKE) gave
//   9.7e-7·T, 1.6 times the bar, shorter: the rod's centre then advances by the chord whose
//   tangential part is h·ω·d, so its angle by asin(h·ω) rather than h·ω per step, (ωh)²/6 faster
//   (measured the same in a model of the step; the error grows with the swing's speed, so with
//   the amplitude). A body on a hinge to the world now follows the arc instead
//   (joint_stabilization.h: ArcOffset, with the world's jointStabilization): its centre goes where
//   the turn about the hinge's point puts it and its velocity turns with it, which is the step in
//   joint coordinates; the correction is left only the softness of the world's CFM (1e-8 m).
// - In joint coordinates (the Newton solver with the world's `jointCoordinates`: the rod's
//   island solved over the hinge's rate, the rod placed back on its hinge after the step,
//   joint_projection.h) the step is symplectic Euler on θ, and numerics' period bar holds; so
//   does the energy bar.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/scenes.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

constexpr double kPendulumDuration = 10.0;  // s

// The pendulum as the world describes it (the first joint, a hinge, holding object 0).
struct Pendulum {
  Vec3 pivot, axis, down, side;  // side = axis × down: where positive angles lie
  double mass = 0.0, g = 0.0, d = 0.0, inertia = 0.0, theta0 = 0.0;

  // Angle of the centre of mass from straight down, rad.
  double Angle(const Vec3& com) const {
    const Vec3 arm = com - pivot;
    return std::atan2(arm.dot(side), arm.dot(down));
  }
  double Period() const {
    const double k = std::sin(0.5 * theta0);
    return 4.0 * std::sqrt(inertia / (mass * g * d)) * std::comp_ellint_1(k);
  }
  double SwingEnergy() const { return mass * g * d * (1.0 - std::cos(theta0)); }
  // Small-amplitude angular frequency √(m·g·d/I), rad/s.
  double Omega() const { return std::sqrt(mass * g * d / inertia); }
};

Pendulum ReadPendulum(const WorldDesc& world) {
  const WorldJointDesc& joint = world.joints.at(0);
  const RigidObjectDesc& rod = world.objects.at(0);
  Pendulum p;
  p.pivot = joint.point;
  p.axis = joint.axis.normalized();
  p.g = world.settings.gravity.norm();
  p.down = world.settings.gravity / p.g;
  p.side = p.axis.cross(p.down);
  const Vec3 arm = rod.pose * rod.com - p.pivot;
  p.d = (arm - arm.dot(p.axis) * p.axis).norm();
  p.mass = rod.mass;
  const Mat3 rotation = rod.pose.linear();
  const Mat3 inertia = rotation * rod.inertia * rotation.transpose();
  p.inertia = p.axis.dot(inertia * p.axis) + p.mass * p.d * p.d;
  p.theta0 = std::abs(p.Angle(rod.pose * rod.com));
  return p;
}

struct EnergySample {
  double time, h, delta;  // s, s, J (E − E₀)
};

// Time-weighted mean of E − E₀ over the steps that end in (from, to].
double MeanDelta(const std::vector<EnergySample>& samples, double from, double to) {
  double sum = 0.0, weight = 0.0;
  for (const EnergySample& s : samples) {
    if (s.time <= from || s.time > to) continue;
    sum += s.delta * s.h;
    weight += s.h;
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

class PendulumProbe : public AccuracyProbe {
 public:
  explicit PendulumProbe(const WorldDesc& world) : pendulum_(ReadPendulum(world)) {}
  void Begin(const Simulator& simulator) override {
    e0_ = TotalEnergy(simulator);
    angle_ = pendulum_.Angle(ObjectCom(simulator, 0));
  }
  void Observe(const StepEvent& event) override {
    const double angle = pendulum_.Angle(ObjectCom(event.simulator, 0));
    if ((angle < 0.0) != (angle_ < 0.0)) {
      crossings_.push_back(event.time - event.h * angle / (angle - angle_));
    }
    angle_ = angle;
    const EnergySample sample{event.time, event.h, TotalEnergy(event.simulator) - e0_};
    samples_.push_back(sample);
    oscillation_ = std::max(oscillation_, std::abs(sample.delta));
  }
  ProbeResult Finish(const Simulator&) override {
    if (crossings_.size() < 5) return {kInf, {}, "fewer than two whole periods"};
    const double n = static_cast<double>(crossings_.size() - 1);
    const double period = 2.0 * (crossings_.back() - crossings_.front()) / n;
    const double expected = pendulum_.Period();
    ProbeResult result{std::abs(period - expected), {}, ""};
    result.metrics = {{"period s", period},
                      {"expected s", expected},
                      {"relative", std::abs(period - expected) / expected},
                      {"energy oscillation", oscillation_ / pendulum_.SwingEnergy()},
                      {"energy drift", Drift() / pendulum_.SwingEnergy()},
                      {"omega rad/s", pendulum_.Omega()}};
    return result;
  }

 private:
  // Mean energy over the last whole period minus that over the first, J.
  double Drift() const {
    const std::size_t n = crossings_.size();
    return MeanDelta(samples_, crossings_[n - 3], crossings_[n - 1]) -
           MeanDelta(samples_, crossings_[0], crossings_[2]);
  }
  Pendulum pendulum_;
  double e0_ = 0.0, angle_ = 0.0, oscillation_ = 0.0;
  std::vector<double> crossings_;
  std::vector<EnergySample> samples_;
};

// ω₀·h of a run.
double OmegaH(const AccuracyRun& run) {
  return RunMetric(run, "omega rad/s") * run.step;
}

BarCheck PeriodWithin(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double wh = OmegaH(*runs[0]);
  return AtMost(runs, {"relative", "of T"}, wh * wh / 24.0);
}

BarCheck PendulumSecondOrder(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double order = OrderBetween(runs[0], runs[1]);
  return {std::abs(order - 2.0) <= 0.1, "slope " + Measured(order, "")};
}

BarCheck EnergyOscillation(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  return AtMost(runs, {"energy oscillation", "of the swing energy"}, 0.5 * OmegaH(*runs[0]));
}

BarCheck NoSecularDrift(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  const double drift = std::abs(RunMetric(*runs[0], "energy drift"));
  const double bound = 0.01 * 0.5 * OmegaH(*runs[0]);
  return {drift <= bound,
          Measured(drift, "of the swing energy") + " (bound " + Measured(bound, "") + ")"};
}

}  // namespace

AccuracyScene PendulumScene() {
  AccuracyScene scene;
  scene.name = "pendulum";
  scene.world = "pendulum.xml";
  scene.title = "Physical pendulum released at 60°";
  scene.setup =
      "1 m, 1 kg rod on a world hinge at one end, released from rest at 60°, no "
      "contact; 10 s (5.7 periods)";
  scene.metric = "error of the mean period (zero crossings of the angle)";
  scene.unit = "s";
  scene.answer = "T = 4·√(I/(m·g·d))·K(sin(θ₀/2)) = 1.7588 s; E = E₀";
  scene.duration = kPendulumDuration;
  scene.min_step = 1e-5;
  scene.probe = [](const WorldDesc& world) { return std::make_unique<PendulumProbe>(world); };
  scene.bars = {
      {"period error ≤ (ω₀h)²/24 of T at 1 ms", {1e-3}, PeriodWithin},
      {"period error second order: slope 2 ± 0.1 from 0.1 to 1 ms",
       {1e-3, 1e-4},
       PendulumSecondOrder},
      {"energy oscillation ≤ ω₀h/2 of the swing energy at 1 ms", {1e-3}, EnergyOscillation},
      {"no secular drift: mean energy of the last period within 1 % of ω₀h/2 of the first's at "
       "1 ms",
       {1e-3},
       NoSecularDrift},
      {"in joint coordinates (newton-joints): period error ≤ (ω₀h)²/24 of T at 1 ms",
       {1e-3},
       PeriodWithin,
       false,
       JointCoordinateSolver()},
      {"in joint coordinates (newton-joints): energy oscillation ≤ ω₀h/2 of the swing energy at "
       "1 ms",
       {1e-3},
       EnergyOscillation,
       false,
       JointCoordinateSolver()},
  };
  return scene;
}

}  // namespace lamina::core
