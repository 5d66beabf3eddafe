// SPDX-License-Identifier: MIT
// Access paths on a running simulation (sim_access.h).
#include "core/sim/sim_access.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/diagnostics.h"
#include "core/model/params.h"
namespace lamina::core {

namespace {

// The link's body. SimBody's getters do not change the simulation, but Simulator::body() is
// not const.
SimBody LinkBody(const Simulator& simulator, const ElementIndex& link) {
  return const_cast<Simulator&>(simulator).body(WorldIdOfElement(simulator.world(), link));
}

std::optional<ParamValue> Commanded(const Simulator& simulator, const AccessTarget& target,
                                    std::string* error) {
  const RobotController& controller = simulator.controller(target.element.index);
  VecX value;
  const bool ok = target.state == StateItem::kCommandedConfig
                      ? controller.GetCommandedConfig(&value)
                      : controller.GetCommandedVelocity(&value);
  if (ok) return VectorValue(value);
  FailWith(error, target.path + ": not every driver of the robot is in PID mode");
  return std::nullopt;
}

std::optional<ParamValue> RobotState(const Simulator& simulator, const AccessTarget& target,
                                     std::string* error) {
  const int r = target.element.index;
  switch (target.state) {
    case StateItem::kRobotConfig:
      return VectorValue(simulator.GetRobotConfig(r));
    case StateItem::kRobotVelocity:
      return VectorValue(simulator.GetRobotVelocity(r));
    case StateItem::kRobotTorques:
      return VectorValue(simulator.GetActuatorTorques(r));
    case StateItem::kSensedConfig:
      return VectorValue(simulator.controller(r).sensed_config());
    case StateItem::kSensedVelocity:
      return VectorValue(simulator.controller(r).sensed_velocity());
    default:
      return Commanded(simulator, target, error);
  }
}

// the whole value of a state item
std::optional<ParamValue> StateValue(const Simulator& simulator, const AccessTarget& target,
                                     std::string* error) {
  const int i = target.element.index;
  switch (target.state) {
    case StateItem::kTime:
      return ParamValue{simulator.time()};
    case StateItem::kObjectTransform:
      return PoseToValue(simulator.GetObjectPose(i));
    case StateItem::kObjectVelocity:
      return TwistToValue(simulator.GetObjectVelocity(i));
    case StateItem::kLinkTransform:
      return PoseToValue(LinkBody(simulator, target.element).GetTransform());
    case StateItem::kLinkVelocity:
      return TwistToValue(LinkBody(simulator, target.element).GetVelocity());
    default:
      return RobotState(simulator, target, error);
  }
}

std::optional<ParamValue> WholeValue(const Simulator& simulator, const AccessTarget& target,
                                     std::string* error) {
  if (target.state == StateItem::kNone) {
    return simulator.GetParam(target.element, *target.row, error);
  }
  return StateValue(simulator, target, error);
}

// writes a checked value of a settable state item
void SetState(Simulator* simulator, const AccessTarget& target, const ParamValue& value) {
  const int i = target.element.index;
  switch (target.state) {
    case StateItem::kObjectTransform:
      simulator->SetObjectPose(i, ValueToPose(value));
      break;
    case StateItem::kObjectVelocity:
      simulator->SetObjectVelocity(i, ValueToTwist(value));
      break;
    case StateItem::kRobotConfig:
      simulator->SetRobotConfig(i, ValueVector(value));
      break;
    case StateItem::kRobotVelocity:
      simulator->SetRobotVelocity(i, ValueVector(value));
      break;
    default:
      break;
  }
}

nlohmann::ordered_json AccessNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

nlohmann::ordered_json JsonValue(const ParamValue& value) {
  if (value.size() == 1) return AccessNumber(value[0]);
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (double x : value) array.push_back(AccessNumber(x));
  return array;
}

}  // namespace

std::optional<AccessTarget> ResolveSimulationPath(const Simulator& simulator, std::string_view path,
                                                  std::string* error) {
  return ResolveAccessPath(simulator.world(), path, AccessContext::kSimulation, error);
}

std::optional<ParamValue> GetPath(const Simulator& simulator, const AccessTarget& target,
                                  std::string* error) {
  std::optional<ParamValue> whole = WholeValue(simulator, target, error);
  if (!whole) return std::nullopt;
  return SelectComponent(target, *whole);
}

std::optional<ParamValue> GetPath(const Simulator& simulator, std::string_view path,
                                  std::string* error) {
  std::optional<AccessTarget> target = ResolveSimulationPath(simulator, path, error);
  if (!target) return std::nullopt;
  return GetPath(simulator, *target, error);
}

bool SetPath(Simulator* simulator, const AccessTarget& target, const ParamValue& value,
             std::string* error) {
  if (target.read_only) return FailWith(error, target.path + ": read-only");
  if (target.component >= 0 && value.size() != 1) {
    return FailWith(
        error, target.path + ": a component takes one number, got " + std::to_string(value.size()));
  }
  std::optional<ParamValue> whole = WholeValue(*simulator, target, error);
  if (!whole) return false;
  const ParamValue full = ReplaceComponent(target, *whole, value);
  if (auto problem = CheckAccessValue(simulator->world(), target, full)) {
    return FailWith(error, *problem);
  }
  if (target.state == StateItem::kNone) {
    return simulator->SetParam(target.element, *target.row, full, error);
  }
  SetState(simulator, target, full);
  return true;
}

bool SetPath(Simulator* simulator, std::string_view path, const ParamValue& value,
             std::string* error) {
  std::optional<AccessTarget> target = ResolveSimulationPath(*simulator, path, error);
  return target && SetPath(simulator, *target, value, error);
}

bool SetPathText(Simulator* simulator, std::string_view path, std::string_view value_text,
                 std::string* error) {
  std::optional<AccessTarget> target = ResolveSimulationPath(*simulator, path, error);
  if (!target) return false;
  std::optional<ParamValue> value = ParseAccessValue(*target, value_text, error);
  return value && SetPath(simulator, *target, *value, error);
}

std::string AddGetJson(const std::string& json, const std::vector<PathValue>& values) {
  nlohmann::ordered_json out = nlohmann::ordered_json::parse(json);
  nlohmann::ordered_json get = nlohmann::ordered_json::object();
  for (const PathValue& entry : values) get[entry.path] = JsonValue(entry.value);
  out["get"] = get;
  return out.dump(2) + "\n";
}

}  // namespace lamina::core
