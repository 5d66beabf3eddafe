// SPDX-License-Identifier: MIT
#include "core/sim/run_report.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/json_values.h"
#include "core/model/world_summary.h"

namespace lamina::core {

namespace {

using nlohmann::ordered_json;

double RealTimeFactor(const Simulator& simulator, const RunTiming& timing) {
  return timing.wall_time > 0.0 ? simulator.time() / timing.wall_time : 0.0;
}

// seconds per part of the simulation (see SimTimeSplit)
ordered_json TimeSplit(const SimTimeSplit& split) {
  return {{"broad_phase", split.broad_phase},
          {"contact_generation", split.contact_generation},
          {"clustering", split.clustering},
          {"solver", split.solver},
          {"other", split.other}};
}

double Percent(double part, double total) {
  return total > 0.0 ? 100.0 * part / total : 0.0;
}

// each sensor's measurements by Klamp't's names (an image sensor: its size only; an infinite
// reading, a laser's miss, is null in JSON)
ordered_json SensorsJson(const RobotSensors& sensors) {
  ordered_json out = ordered_json::array();
  for (int i = 0; i < sensors.size(); ++i) {
    const Sensor& s = sensors.sensor(i);
    ordered_json sensor = {{"name", s.name()}, {"type", s.type()}, {"enabled", s.enabled()}};
    if (IsImageSensor(s)) {
      sensor["measurement_count"] = s.measurements().size();
    } else {
      ordered_json values = ordered_json::object();
      const std::vector<std::string> names = s.MeasurementNames();
      for (size_t k = 0; k < names.size() && k < s.measurements().size(); ++k) {
        values[names[k]] = s.measurements()[k];
      }
      sensor["measurements"] = values;
    }
    out.push_back(sensor);
  }
  return out;
}

// the live accuracy meter's reading (error_meter.h), when it is on
ordered_json ErrorMeterJson(const Simulator& simulator) {
  const ErrorMeterReading r = simulator.error_meter_reading();
  return {{"error_rate", r.valid ? ordered_json(r.rate) : ordered_json(nullptr)},
          {"local_error", r.valid ? ordered_json(r.local_error) : ordered_json(nullptr)},
          {"sampled_at", r.time},
          {"samples", r.samples},
          {"overhead", r.overhead}};
}

}  // namespace

std::string RunReportJson(const Simulator& simulator, const RunTiming& timing) {
  const SimStatistics& stats = simulator.statistics();
  ordered_json out = {
      {"time", simulator.time()},
      {"wall_time", timing.wall_time},
      {"real_time_factor", RealTimeFactor(simulator, timing)},
      {"steps", stats.steps},
      {"status", StepStatusName(stats.worst_status)},
      {"rollbacks", stats.rollbacks},
      {"instability_corrections", stats.instability_corrections},
      {"unreliable_steps", stats.unreliable_steps},
      {"max_penetration", stats.max_penetration},
      {"joint_open_steps", stats.joint_open_steps},
      {"max_joint_gap", stats.max_joint_gap},
      {"max_contacts", stats.max_contacts_in_step},
      {"mean_contacts",
       stats.steps > 0 ? static_cast<double>(stats.contact_joints) / stats.steps : 0.0},
      {"time_split", TimeSplit(stats.time_split)},
      {"newton",
       {{"islands", stats.newton_islands},
        {"fallbacks", stats.newton_fallbacks},
        {"unconverged", stats.newton_unconverged},
        {"iterations", stats.newton_iterations},
        {"factorizations", stats.newton_factorizations}}},
      {"direct", {{"islands", stats.direct_islands}, {"fallbacks", stats.direct_fallbacks}}},
      {"reduced", {{"islands", stats.reduced_islands}, {"fallbacks", stats.reduced_fallbacks}}},
      {"mesh_pairs",
       {{"searches", simulator.ContactPairSearches()}, {"reused", simulator.ContactPairReuses()}}},
      {"sleeping_objects", simulator.SleepingObjectCount()}};
  if (!stats.error.empty()) out["error"] = stats.error;
  if (simulator.error_meter()) out["error_meter"] = ErrorMeterJson(simulator);
  // every settings row in force, the internal constants included (core/model/params.h)
  out["settings"] = ordered_json::parse(ParamsJson(simulator.world(), ElementIndex::Settings()));
  ordered_json objects = ordered_json::array();
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Pose pose = simulator.GetObjectPose(i);
    const Eigen::Quaterniond q(pose.linear());
    const Twist velocity = simulator.GetObjectVelocity(i);
    objects.push_back({{"name", simulator.world().objects[i].name},
                       {"position", JsonVector(pose.translation())},
                       {"quaternion", ordered_json::array({q.w(), q.x(), q.y(), q.z()})},
                       {"velocity", JsonVector(velocity.linear)},
                       {"angular_velocity", JsonVector(velocity.angular)},
                       {"asleep", simulator.ObjectAsleep(i)}});
  }
  out["objects"] = objects;
  ordered_json robots = ordered_json::array();
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const VecX q = simulator.GetRobotConfig(r);
    const VecX dq = simulator.GetRobotVelocity(r);
    VecX commanded;
    ordered_json robot = {{"name", simulator.world().robots[r].name},
                          {"config", std::vector<double>(q.data(), q.data() + q.size())},
                          {"velocity", std::vector<double>(dq.data(), dq.data() + dq.size())}};
    const VecX torques = simulator.GetActuatorTorques(r);
    robot["actuator_torques"] =
        std::vector<double>(torques.data(), torques.data() + torques.size());
    if (simulator.controller(r).GetCommandedConfig(&commanded)) {
      robot["commanded_config"] =
          std::vector<double>(commanded.data(), commanded.data() + commanded.size());
      robot["tracking_error"] = (commanded - q).cwiseAbs().maxCoeff();
    }
    robot["sensors"] = SensorsJson(simulator.sensors(r));
    robots.push_back(robot);
  }
  out["robots"] = robots;
  return out.dump(2) + "\n";
}

std::string RunReportText(const Simulator& simulator, const RunTiming& timing) {
  const SimStatistics& stats = simulator.statistics();
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof(line),
                "simulated %.6g s in %ld steps, %.3f s wall (%.2fx real time), status %s\n",
                simulator.time(), stats.steps, timing.wall_time, RealTimeFactor(simulator, timing),
                StepStatusName(stats.worst_status));
  out << line;
  std::snprintf(line, sizeof(line),
                "rollbacks %ld, instability corrections %ld, max penetration %.6g m, widest joint "
                "gap %.6g m\n",
                stats.rollbacks, stats.instability_corrections, stats.max_penetration,
                stats.max_joint_gap);
  out << line;
  std::snprintf(line, sizeof(line), "contacts: max %d per step, mean %.3g per step\n",
                stats.max_contacts_in_step,
                stats.steps > 0 ? static_cast<double>(stats.contact_joints) / stats.steps : 0.0);
  out << line;
  const SimTimeSplit& split = stats.time_split;
  const double total = split.total();
  std::snprintf(line, sizeof(line),
                "time split: broad phase %.1f%%, contact generation %.1f%%, clustering %.1f%%, "
                "solver %.1f%%, other %.1f%%\n",
                Percent(split.broad_phase, total), Percent(split.contact_generation, total),
                Percent(split.clustering, total), Percent(split.solver, total),
                Percent(split.other, total));
  out << line;
  if (!stats.error.empty()) out << "error: " << stats.error << "\n";
  const ErrorMeterReading meter = simulator.error_meter_reading();
  if (simulator.error_meter() && meter.valid) {
    std::snprintf(line, sizeof(line),
                  "error meter: position error growing about %.3g m per simulated s (%.3g m per "
                  "step; %ld samples, %.1f%% extra time)\n",
                  meter.rate, meter.local_error, meter.samples, 100.0 * meter.overhead);
    out << line;
  }
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Vec3 p = simulator.GetObjectPose(i).translation();
    const Vec3 v = simulator.GetObjectVelocity(i).linear;
    std::snprintf(line, sizeof(line),
                  "object '%s': position (%.6g, %.6g, %.6g) velocity (%.6g, %.6g, %.6g)\n",
                  simulator.world().objects[i].name.c_str(), p.x(), p.y(), p.z(), v.x(), v.y(),
                  v.z());
    out << line;
  }
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const VecX q = simulator.GetRobotConfig(r);
    out << "robot '" << simulator.world().robots[r].name << "': config";
    for (const double value : q) out << " " << value;
    VecX commanded;
    if (simulator.controller(r).GetCommandedConfig(&commanded)) {
      out << "\n  tracking error (commanded - sensed, largest) "
          << (commanded - q).cwiseAbs().maxCoeff();
    }
    const VecX torques = simulator.GetActuatorTorques(r);
    out << "\n  actuator torques";
    for (const double value : torques) out << " " << value;
    out << "\n";
  }
  return out.str();
}

}  // namespace lamina::core
