// SPDX-License-Identifier: MIT
#include "core/accuracy/probe_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <time.h>

#include "core/sim/simulator.h"

namespace lamina::core {

Vec3 ObjectCom(const Simulator& simulator, int object) {
  return simulator.GetObjectPose(object) * simulator.world().objects.at(object).com;
}

double TotalEnergy(const Simulator& simulator) {
  return simulator.KineticEnergy() + simulator.PotentialEnergy();
}

Vec3 ObjectComVelocity(const Simulator& simulator, int object) {
  const Pose pose = simulator.GetObjectPose(object);
  const Twist twist = simulator.GetObjectVelocity(object);
  const Vec3 arm = pose.linear() * simulator.world().objects.at(object).com;
  return twist.linear + twist.angular.cross(arm);
}

void RestingWatch::Observe(const StepEvent& event) {
  if (event.time < settle_ - 1e-12) return;
  const Simulator& simulator = event.simulator;
  if (weight_ == 0.0) settled_ = ObjectCom(simulator, 0);
  speed2_ += ObjectComVelocity(simulator, 0).squaredNorm() * event.h;
  spin2_ += simulator.GetObjectVelocity(0).angular.squaredNorm() * event.h;
  weight_ += event.h;
  fewest_ = std::min(fewest_, event.contact_joints);
  most_ = std::max(most_, event.contact_joints);
}

double RestingWatch::RmsSpeed() const {
  return std::sqrt(speed2_ / weight_);
}

double RestingWatch::RmsSpin() const {
  return std::sqrt(spin2_ / weight_);
}

std::vector<ProbeMetric> RestingWatch::Metrics(const Simulator& simulator) const {
  return {{"moved m", (ObjectCom(simulator, 0) - settled_).norm()},
          {"contact count range", static_cast<double>(most_ - fewest_)},
          {"contacts", static_cast<double>(most_)}};
}

double ObjectLayerOverlap(const Simulator& simulator, const std::vector<ContactPair>& pairs,
                          int object) {
  const int id = simulator.world().ObjectId(object);
  double depth = 0.0;
  for (const ContactPair& pair : pairs) {
    if (pair.a == id || pair.b == id) depth = std::max(depth, pair.max_depth);
  }
  return depth;
}

Vec3 ObjectAngularMomentum(const Simulator& simulator, int object) {
  const Mat3 rotation = simulator.GetObjectPose(object).linear();
  const Mat3 inertia = simulator.world().objects.at(object).inertia;
  return rotation * inertia * rotation.transpose() * simulator.GetObjectVelocity(object).angular;
}

double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double RunMetric(const AccuracyRun& run, const std::string& name) {
  for (const ProbeMetric& metric : run.result.metrics) {
    if (metric.name == name) return metric.value;
  }
  return std::nan("");
}

double OrderBetween(const AccuracyRun* coarse, const AccuracyRun* fine) {
  if (coarse == nullptr || fine == nullptr) return std::nan("");
  const double e1 = coarse->result.error, e0 = fine->result.error;
  if (!(e1 > 0.0) || !(e0 > 0.0)) return std::nan("");
  return std::log(e1 / e0) / std::log(coarse->step / fine->step);
}

std::string Measured(double value, const std::string& unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", value);
  return unit.empty() ? std::string(text) : std::string(text) + " " + unit;
}

bool RunsUsable(const std::vector<const AccuracyRun*>& runs, BarCheck* check) {
  for (const AccuracyRun* run : runs) {
    if (run == nullptr) {
      *check = {false, "not run"};
      return false;
    }
    if (!run->failure.empty()) {
      *check = {false, "failed: " + run->failure};
      return false;
    }
  }
  return true;
}

}  // namespace lamina::core
