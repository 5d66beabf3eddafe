// SPDX-License-Identifier: MIT
// What the accuracy probes read off a simulation: an object's centre of mass, its velocity and
// its angular momentum, in world coordinates; and how a bar compares two runs.
#pragma once

#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"
#include "core/math_types.h"

namespace lamina::core {

class Simulator;
struct ContactPair;
struct StepEvent;

/// Centre of mass of rigid object `object` (m, world).
Vec3 ObjectCom(const Simulator& simulator, int object);
/// Velocity of that centre of mass (m/s, world).
Vec3 ObjectComVelocity(const Simulator& simulator, int object);
/// Deepest layer overlap of rigid object `object` with anything in `pairs` (m; 0 without
/// contact): a step event's contacts, or the simulator's contact_pairs() after a step.
double ObjectLayerOverlap(const Simulator& simulator, const std::vector<ContactPair>& pairs,
                          int object);
/// Angular momentum about the centre of mass (kg·m²/s, world): R I Rᵀ ω.
Vec3 ObjectAngularMomentum(const Simulator& simulator, int object);
/// The world's kinetic plus potential energy (J).
double TotalEnergy(const Simulator& simulator);

/// What a probe of object 0 coming to rest gathers from the steps after `settle` seconds: the
/// RMS speed of its centre of mass (m/s) and its RMS angular speed (rad/s), where the centre was
/// when the measurement began, and the range of the contact-joint count.
class RestingWatch {
 public:
  explicit RestingWatch(double settle) : settle_(settle) {}
  void Observe(const StepEvent& event);
  bool Started() const { return weight_ > 0.0; }
  double RmsSpeed() const;
  double RmsSpin() const;
  /// "moved m" (the centre since the measurement began), "contact count range", "contacts"
  std::vector<ProbeMetric> Metrics(const Simulator& simulator) const;

 private:
  double settle_;  ///< s
  Vec3 settled_ = Vec3::Zero();
  double speed2_ = 0.0, spin2_ = 0.0, weight_ = 0.0;
  int fewest_ = 1 << 30, most_ = 0;
};

/// CPU time of the calling thread (s): what the sweeps time a run by.
double ThreadCpuSeconds();
/// The value of metric `name` of a run; NaN when the run has none.
double RunMetric(const AccuracyRun& run, const std::string& name);
/// The slope of log(error) against log(step) through two runs (NaN when either error is 0 or a
/// run is missing).
double OrderBetween(const AccuracyRun* coarse, const AccuracyRun* fine);
/// "0.0123" style text with 3 significant digits, and the unit.
std::string Measured(double value, const std::string& unit);

/// The bar verdict for runs that are missing or failed: not passed, saying which.
bool RunsUsable(const std::vector<const AccuracyRun*>& runs, BarCheck* check);

}  // namespace lamina::core
