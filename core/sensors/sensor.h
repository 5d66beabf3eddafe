// SPDX-License-Identifier: MIT
// Sensor: one emulated robot sensor (Klamp't's SensorBase), its settings as Klamp't's
// `<sensors>` XML spells them, its measurements and the state it evolves. The simulator hands
// every sensor the same SensorInputs (the robot's state at the start of a physics step); a
// sensor never reads the simulator itself, so each type is a pure function of its inputs, its
// settings and its own state, with a unit test of its own (tests/unit/sensors_test.cpp).
//
// Units: SI throughout (m, rad, s, N, N·m). Frames: `link` frames as in the robot file; a
// sensor's own frame is `Tsensor` in its link's frame (12 numbers, Klamp't's order: the
// rotation row by row, then the translation). World frame z up against gravity.
//
// Differences from Klamp't (its quirk list; fixed rather than copied, docs/sensors.md):
// - the accelerometer reads specific force, a − g (at rest it reads +9.8 along the world's up
//   axis, in free fall 0), where Klamp't adds g (reading −9.8 at rest and −19.6 in free fall);
//   joint accelerations are the mean since the robot's previous sample (RobotSensors), where
//   Klamp't differences each sensor's velocity over its own period;
// - gyroscopes read in the link frame (a real gyro), where Klamp't reports world-frame rates;
// - TransformedSensor's `maximum` is an upper bound (Klamp't applies it as a second minimum);
// - CorruptedSensor with resolution 0 does not quantise (Klamp't divides by it);
// - IMUSensor's angular velocity is the gyro's (Klamp't copies the angular acceleration);
// - wrapped sensors are stepped once per cycle (Klamp't steps them through their own slot and
//   through the wrapper);
// - vectors such as `qvariance` are read with or without Klamp't's leading count, and booleans
//   as 0/1 or true/false; an unknown attribute is a warning, not a refused robot.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"
#include "core/sensors/link_motion.h"

namespace lamina::core {

/// A contact point on one of the robot's links during the last physics step.
struct LinkContact {
  int link = -1;                 ///< the robot's link
  Vec3 position = Vec3::Zero();  ///< world, m
  Vec3 force = Vec3::Zero();     ///< on the link, world, N
};

/// Distance (m) from `origin` along unit `direction` to the first surface of the world, not
/// counting the robot link `ignore_link` (-1: none); +inf when nothing is hit within `max`.
using RayCaster =
    std::function<double(const Vec3& origin, const Vec3& direction, double max, int ignore_link)>;

/// What a camera sensor asks of a renderer (core stays free of GL: `ui` implements it).
struct CameraRequest {
  Pose camera = Pose::Identity();  ///< world pose: z forward, x right, y down (Klamp't's)
  int width = 0, height = 0;       ///< pixels
  double xfov = 1.0;               ///< horizontal field of view, rad
  double znear = 0.1, zfar = 100;  ///< clip planes, m
  bool rgb = true, depth = true;
};
/// Row-major from the top-left pixel: rgb as 0xRRGGBB, depth along the optical axis (m, +inf
/// where nothing was drawn).
struct CameraImage {
  std::vector<std::uint32_t> rgb;
  std::vector<float> depth;
};
class CameraRenderer {
 public:
  virtual ~CameraRenderer() = default;
  /// False when it cannot render now.
  virtual bool Render(const CameraRequest& request, CameraImage* image) = 0;
};

/// The robot's state at the start of a physics step, as every sensor sees it.
struct SensorInputs {
  const RobotDesc* robot = nullptr;
  double time = 0.0;  ///< s
  VecX q, dq, ddq;    ///< link space; ddq the mean since the previous sample
  /// Link frames, velocities and accelerations (world); left empty by the simulation when no
  /// sensor of the robot reads them (RobotSensors::needs_motion).
  LinkMotion motion;
  Vec3 gravity = Vec3(0, 0, -9.8);    ///< m/s²
  VecX driver_torques;                ///< the drivers' clamped efforts, driver space (when read)
  std::vector<LinkContact> contacts;  ///< the last physics step's contacts on the robot
  RayCaster ray;                      ///< may be empty (then lasers read +inf)
  CameraRenderer* camera = nullptr;   ///< may be null (then cameras measure nothing)
};

/// Seeded, counter-based normal and uniform noise: a draw depends only on (seed, count), so a
/// sensor's noise is the same however a run is chunked, and restoring `count` restores it.
class SensorNoise {
 public:
  explicit SensorNoise(std::uint64_t seed = 0) : seed_(seed) {}
  double Normal();   ///< N(0, 1)
  double Uniform();  ///< [0, 1)
  std::uint64_t count() const { return count_; }
  void set_count(std::uint64_t count) { count_ = count; }
  std::uint64_t seed() const { return seed_; }

 private:
  std::uint64_t Next();
  std::uint64_t seed_ = 0;
  std::uint64_t count_ = 0;
};

/// value + N(0, variance), then rounded to a multiple of resolution when resolution > 0.
double Discretize(double value, double resolution, double variance, SensorNoise& noise);

/// A sensor drawn in 3-D (world frame): what core/render turns into overlay lines and arrows.
struct SensorDrawing {
  enum class Kind {
    kRayHit,      ///< a laser ray to what it hit
    kRayMiss,     ///< a laser ray that hit nothing within its range (drawn to a fixed length)
    kOutline,     ///< a camera's frustum, a contact patch's edge
    kOutlineHot,  ///< a contact patch in contact
  };
  enum class Quantity { kForce, kTorque, kAcceleration };
  struct Segment {
    Vec3 from, to;
    Kind kind;
  };
  struct Arrow {
    Vec3 from;
    Vec3 value;  ///< N, N·m or m/s², world axes (the overlay scales it)
    Quantity quantity;
  };
  std::vector<Segment> segments;
  std::vector<Vec3> hits;  ///< laser hit points
  std::vector<Arrow> arrows;
};

/// A settings attribute of a sensor type: its name, default text and help.
struct SensorSettingSpec {
  const char* name;
  const char* default_text;
  const char* help;
};

class Sensor {
 public:
  virtual ~Sensor() = default;
  /// Klamp't's type name, e.g. "Accelerometer".
  virtual const char* type() const = 0;
  /// The type's own settings (not `rate` and `enabled`).
  virtual std::vector<SensorSettingSpec> SettingSpecs() const = 0;
  /// Measurement names in Klamp't's spelling, one per measurement.
  virtual std::vector<std::string> MeasurementNames() const = 0;
  /// Takes one sample of `inputs` into measurements().
  virtual void Simulate(const SensorInputs& inputs) = 0;
  /// After a sample: `dt` s until the next one (the sensor period).
  virtual void Advance(double dt) { (void)dt; }
  /// Forgets every sample (measurements zero, internal state cleared).
  virtual void Reset();
  /// The link it sits on (-1: none or the world).
  virtual int link() const { return -1; }
  /// Its frame in the link frame (or the world when link() is -1).
  virtual Pose frame() const { return Pose::Identity(); }
  /// Appends its drawing for links at `link_frames` (world) from its current measurements;
  /// sensors without a geometry (joint sensors, wrappers) draw nothing.
  virtual void Draw(const std::vector<Pose>& link_frames, SensorDrawing* out) const {
    (void)link_frames;
    (void)out;
  }

  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }
  double rate() const { return rate_; }
  bool enabled() const { return enabled_; }
  const std::vector<double>& measurements() const { return measurements_; }

  /// Sets `key` from its text as the XML attribute spells it; false with `*error` when the key
  /// is unknown or the text is not a value of it (nothing changed then).
  bool SetSetting(const std::string& key, const std::string& text, std::string* error);
  /// The setting's text (the last one set, or its default); false for an unknown key.
  bool GetSetting(const std::string& key, std::string* text) const;
  /// Every setting with its text, `rate` and `enabled` first.
  std::vector<std::pair<std::string, std::string>> Settings() const;

  /// What the sensor evolves besides its measurements (for exact save and restore).
  virtual std::vector<double> InternalState() const { return {}; }
  virtual void SetInternalState(const std::vector<double>& state) { (void)state; }
  void SetMeasurements(std::vector<double> values) { measurements_ = std::move(values); }

  SensorNoise& noise() { return noise_; }
  const SensorNoise& noise() const { return noise_; }
  void set_noise(const SensorNoise& noise) { noise_ = noise; }

 protected:
  /// Parses one of SettingSpecs() into the typed members; false with `*error` on bad text.
  virtual bool ApplySetting(const std::string& key, const std::string& text,
                            std::string* error) = 0;
  std::vector<double> measurements_;
  SensorNoise noise_;

 private:
  std::string name_ = "Unnamed sensor";
  double rate_ = 0.0;
  bool enabled_ = true;
  std::map<std::string, std::string> texts_;
};

/// A new sensor of Klamp't type `type` with its defaults, or null for an unknown type.
/// `robot` gives link names and counts; it must outlive the sensor.
std::unique_ptr<Sensor> MakeSensor(const std::string& type, const RobotDesc& robot);
/// Every type MakeSensor knows, in Klamp't's order.
std::vector<std::string> SensorTypes();

}  // namespace lamina::core
