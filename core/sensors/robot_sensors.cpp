// SPDX-License-Identifier: MIT
#include "core/sensors/robot_sensors.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <tinyxml2.h>

#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

constexpr double kPeriodTolerance = 1e-9;  // s: accumulated periods may round

SourceLocation At(const std::string& file, const tinyxml2::XMLElement& e, int line_offset) {
  return {file, e.GetLineNum() + line_offset, 0};
}

void ApplyAttributes(const tinyxml2::XMLElement& e, Sensor* sensor, const SourceLocation& at,
                     Diagnostics* diagnostics) {
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
    const std::string key = a->Name();
    if (key == "name") continue;
    std::string error;
    if (!sensor->SetSetting(key, a->Value(), &error) && diagnostics) {
      diagnostics->Warning(at, std::string(sensor->type()) + " '" + sensor->name() + "' " + key +
                                   ": " + error + "; ignored");
    }
  }
}

// binds a wrapper to the earlier sensor its `sensor` setting names; false when there is none
bool BindWrapper(Sensor* sensor, const std::vector<std::unique_ptr<Sensor>>& earlier,
                 const SourceLocation& at, Diagnostics* diagnostics) {
  auto* wrapper = dynamic_cast<WrapperSensor*>(sensor);
  if (!wrapper) return true;
  for (const auto& s : earlier) {
    if (s->name() == wrapper->wrapped_name()) return wrapper->Bind(s.get()), wrapper->Reset(), true;
  }
  if (diagnostics) {
    diagnostics->Error(at, std::string(sensor->type()) + " '" + sensor->name() +
                               "': no earlier sensor named '" + wrapper->wrapped_name() +
                               "' to wrap; the sensor is left out");
  }
  return false;
}

std::unique_ptr<Sensor> ParseOne(const tinyxml2::XMLElement& e, const RobotDesc& robot,
                                 const std::vector<std::unique_ptr<Sensor>>& earlier,
                                 const SourceLocation& at, Diagnostics* diagnostics) {
  std::unique_ptr<Sensor> sensor = MakeSensor(e.Name(), robot);
  if (!sensor) {
    if (diagnostics) {
      diagnostics->Error(
          at, std::string("unknown sensor type '") + e.Name() + "'; the sensor is left out");
    }
    return nullptr;
  }
  if (const char* name = e.Attribute("name")) sensor->set_name(name);
  ApplyAttributes(e, sensor.get(), at, diagnostics);
  if (!BindWrapper(sensor.get(), earlier, at, diagnostics)) return nullptr;
  return sensor;
}

bool NameTaken(const std::vector<std::unique_ptr<Sensor>>& sensors, const std::string& name) {
  return std::any_of(sensors.begin(), sensors.end(),
                     [&](const auto& s) { return s->name() == name; });
}

std::uint64_t NameHash(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  return h;
}

}  // namespace

std::vector<std::unique_ptr<Sensor>> ParseSensorsElement(const tinyxml2::XMLElement& sensors,
                                                         const RobotDesc& robot,
                                                         const std::string& file, int line_offset,
                                                         Diagnostics* diagnostics) {
  std::vector<std::unique_ptr<Sensor>> out;
  for (const tinyxml2::XMLElement* e = sensors.FirstChildElement(); e;
       e = e->NextSiblingElement()) {
    const SourceLocation at = At(file, *e, line_offset);
    std::unique_ptr<Sensor> sensor = ParseOne(*e, robot, out, at, diagnostics);
    if (!sensor) continue;
    if (NameTaken(out, sensor->name()) && diagnostics) {
      diagnostics->Warning(
          at, "a second sensor named '" + sensor->name() + "': lookups by name find the first");
    }
    out.push_back(std::move(sensor));
  }
  return out;
}

std::vector<std::unique_ptr<Sensor>> ParseSensorsXml(const std::string& xml, const RobotDesc& robot,
                                                     const SourceLocation& first_line,
                                                     Diagnostics* diagnostics) {
  tinyxml2::XMLDocument doc;
  const int offset = first_line.line > 0 ? first_line.line - 1 : 0;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    if (diagnostics) {
      diagnostics->Error({first_line.file, doc.ErrorLineNum() + offset, 0},
                         std::string("sensors: ") + doc.ErrorStr());
    }
    return {};
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "sensors") {
    if (diagnostics) diagnostics->Error(first_line, "sensors: the root element must be <sensors>");
    return {};
  }
  return ParseSensorsElement(*root, robot, first_line.file, offset, diagnostics);
}

bool IsImageSensor(const Sensor& sensor) {
  const Sensor* s = &sensor;
  while (const auto* wrapper = dynamic_cast<const WrapperSensor*>(s)) {
    if (!wrapper->wrapped()) return false;
    s = wrapper->wrapped();
  }
  return std::string(s->type()) == "CameraSensor";
}

RobotSensors::RobotSensors(const RobotDesc& robot, Diagnostics* diagnostics) {
  const auto it = robot.properties.find("sensors");
  if (it != robot.properties.end()) {
    sensors_ = ParseSensorsXml(it->second, robot, {robot.source_path, 0, 0}, diagnostics);
  } else {
    defaults_ = true;
    sensors_.push_back(MakeSensor("JointPositionSensor", robot));
    sensors_.back()->set_name("q");
    sensors_.push_back(MakeSensor("JointVelocitySensor", robot));
    sensors_.back()->set_name("dq");
  }
  Seed(robot.name);
  FindNeeds();
  Reset();
}

RobotSensors::RobotSensors(RobotSensors&&) noexcept = default;
RobotSensors& RobotSensors::operator=(RobotSensors&&) noexcept = default;
RobotSensors::~RobotSensors() = default;

void RobotSensors::Seed(const std::string& robot_name) {
  for (size_t i = 0; i < sensors_.size(); ++i) {
    sensors_[i]->set_noise(SensorNoise(NameHash(robot_name + "\n" + sensors_[i]->name()) + i));
  }
}

int RobotSensors::Find(const std::string& name) const {
  for (int i = 0; i < size(); ++i) {
    if (sensors_[i]->name() == name) return i;
  }
  return -1;
}

// what the simulation must compute for these sensors: fixed with the list, so asked once
// (RecordSensorStep asks at every physics step)
void RobotSensors::FindNeeds() {
  for (const auto& s : sensors_) {
    const std::string type = s->type();
    const bool joint = type == "JointPositionSensor" || type == "JointVelocitySensor" ||
                       type == "DriverTorqueSensor";
    needs_contacts_ |= type == "ContactSensor" || type == "ForceTorqueSensor";
    needs_motion_ |= !joint && dynamic_cast<const WrapperSensor*>(s.get()) == nullptr;
    needs_driver_torques_ |= type == "DriverTorqueSensor";
    has_images_ |= IsImageSensor(*s);
  }
}

bool RobotSensors::AnyDue(double time) const {
  for (int i = 0; i < size(); ++i) {
    if (sensors_[i]->enabled() && (!started_ || time >= next_times_[i] - kPeriodTolerance)) {
      return true;
    }
  }
  return false;
}

VecX RobotSensors::MeanAcceleration(double time, const VecX& dq) const {
  const double dt = time - sample_time_;
  if (!started_ || dt <= 0.0 || sample_dq_.size() != dq.size()) return VecX::Zero(dq.size());
  return (dq - sample_dq_) / dt;
}

void RobotSensors::Sample(const SensorInputs& inputs, double step, double control_period) {
  if (!started_) std::fill(next_times_.begin(), next_times_.end(), inputs.time);
  started_ = true;
  sample_time_ = inputs.time;
  sample_dq_ = inputs.dq;
  for (int i = 0; i < size(); ++i) {
    Sensor& s = *sensors_[i];
    if (!s.enabled() || inputs.time < next_times_[i] - kPeriodTolerance) continue;
    const double period = std::max(s.rate() > 0.0 ? 1.0 / s.rate() : control_period, step);
    s.Simulate(inputs);
    s.Advance(period);
    next_times_[i] += period;
  }
}

bool RobotSensors::SensedJoints(bool velocity, VecX* out) const {
  const std::string type = velocity ? "JointVelocitySensor" : "JointPositionSensor";
  for (const auto& s : sensors_) {
    if (!s->enabled() || s->type() != type) continue;
    std::string indices;
    s->GetSetting("indices", &indices);
    if (!indices.empty() || !started_) continue;
    const std::vector<double>& m = s->measurements();
    *out = Eigen::Map<const VecX>(m.data(), static_cast<Eigen::Index>(m.size()));
    return true;
  }
  return false;
}

std::vector<SensorReadout> RobotSensors::Readouts() const {
  std::vector<SensorReadout> out;
  for (const auto& s : sensors_) {
    SensorReadout r{s->name(), s->type(), s->link(), IsImageSensor(*s), {}, {}};
    if (!r.image) {
      r.names = s->MeasurementNames();
      r.values = s->measurements();
    }
    out.push_back(std::move(r));
  }
  return out;
}

SensorDrawing RobotSensors::Drawing(const std::vector<Pose>& link_frames) const {
  SensorDrawing drawing;
  for (const auto& s : sensors_) {
    if (s->link() < static_cast<int>(link_frames.size())) s->Draw(link_frames, &drawing);
  }
  return drawing;
}

void RobotSensors::Reset() {
  for (auto& s : sensors_) {
    s->Reset();
    s->noise().set_count(0);
  }
  next_times_.assign(sensors_.size(), 0.0);
  started_ = false;
  sample_time_ = 0.0;
  sample_dq_.resize(0);
  contacts_.clear();
}

RobotSensorsState RobotSensors::GetState() const {
  RobotSensorsState state;
  state.started = started_;
  state.next_times = next_times_;
  for (const auto& s : sensors_) {
    state.measurements.push_back(s->measurements());
    state.internal.push_back(s->InternalState());
    state.noise_counts.push_back(s->noise().count());
  }
  state.sample_time = sample_time_;
  state.sample_dq = sample_dq_;
  state.contacts = contacts_;
  return state;
}

bool RobotSensors::SetState(const RobotSensorsState& state) {
  const size_t n = sensors_.size();
  if (state.next_times.size() != n || state.measurements.size() != n ||
      state.internal.size() != n || state.noise_counts.size() != n) {
    return false;
  }
  started_ = state.started;
  next_times_ = state.next_times;
  for (size_t i = 0; i < n; ++i) {
    sensors_[i]->SetMeasurements(state.measurements[i]);
    sensors_[i]->SetInternalState(state.internal[i]);
    sensors_[i]->noise().set_count(state.noise_counts[i]);
  }
  sample_time_ = state.sample_time;
  sample_dq_ = state.sample_dq;
  contacts_ = state.contacts;
  return true;
}

}  // namespace lamina::core
