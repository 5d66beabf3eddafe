// SPDX-License-Identifier: MIT
// Sensors that look: LaserRangeSensor (rays swept in its frame) and CameraSensor (RGB and depth
// images through a CameraRenderer that `ui` provides).
//
// LaserRangeSensor frame (Tsensor on `link`, or in the world when link is -1): z forward, x to
// the side swept by the x angle, y by the y angle. Ray i points along
// (sin θx, cos θx sin θy, cos θx cos θy) with θx = xSweepMagnitude·W(u) (likewise y), starts
// depthMinimum along itself and reads the distance from the sensor origin (m) to the first
// surface not of its own link; noise variance d·depthVarianceLinear + depthVarianceConstant,
// then quantised to depthResolution; readings ≤ depthMinimum, ≥ depthMaximum or missing read
// depthMaximum (+inf by default). Waveforms W: 0 sinusoid sin(2πu), 1 triangle
// 1 − 4|frac(u + ¼) − ½|, 2 sawtooth 2·frac(u) − 1. With period 0 a whole sweep happens every
// sample (u = i/(n−1), the sawtooth's last ray at +magnitude: the readings span the fan
// inclusive, where Klamp't's last ray wraps round before its first advance); with period P the
// rays of a sample cover the sensor's period before it, u = (t + phase)/P.
// CameraSensor frame: z forward, x right, y down (Klamp't's); the vertical field of view
// follows from xfov and the aspect xres:yres (as Klamp't; yfov is read and unused). Values: rgb
// as 0xRRGGBB numbers, then depth along the optical axis (m; zmax where nothing is nearer),
// both row by row from the top-left pixel, named rgb[x,y] and d[x,y] in that same order
// (Klamp't names them column by column). zresolution is a length (Klamp't reads an integer).
#include <cmath>
#include <string>
#include <vector>

#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

double Frac(double u) {
  return u - std::floor(u);
}

double Waveform(int type, double u, bool last_of_fan) {
  if (type == 0) return std::sin(2.0 * kPi * u);
  if (type == 1) return 1.0 - 4.0 * std::abs(Frac(u + 0.25) - 0.5);
  return last_of_fan ? 1.0 : 2.0 * Frac(u) - 1.0;
}

struct Sweep {
  double magnitude = 0.0, period = 0.0, phase = 0.0;
  int type = 0;
  // the angle of ray i of n for a sample at sensor time t after a period dt
  double Angle(int i, int n, double t, double dt) const {
    if (magnitude == 0.0) return 0.0;
    if (period <= 0.0) {
      const double u = n > 1 ? static_cast<double>(i) / (n - 1) : 0.5;
      return magnitude * Waveform(type, u, n > 1 && i == n - 1 && type == 2);
    }
    const double u = (t - dt + dt * (i + 1) / n + phase) / period;
    return magnitude * Waveform(type, u, false);
  }
};

Pose SensorPose(const SensorInputs& in, int link, const Pose& tsensor) {
  return link >= 0 ? Pose(in.motion.frames[link] * tsensor) : tsensor;
}

class LaserRangeSensor : public Sensor {
 public:
  explicit LaserRangeSensor(const RobotDesc& robot) : robot_(robot) {
    x_.magnitude = kPi / 2;
    x_.type = 2;
    Reset();
  }
  const char* type() const override { return "LaserRangeSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"link", "-1", "the link it sits on (name or index; -1: the world)"},
            {"Tsensor", "1 0 0 0 1 0 0 0 1 0 0 0", "its frame: z forward"},
            {"measurementCount", "180", "rays per sample"},
            {"depthResolution", "0", "quantisation step, m"},
            {"depthMinimum", "0.1", "nearest reading, m"},
            {"depthMaximum", "inf", "farthest reading (and the reading of a miss), m"},
            {"depthVarianceLinear", "0", "noise variance per metre of depth, m"},
            {"depthVarianceConstant", "0", "noise variance, m²"},
            {"xSweepMagnitude", "1.5707963267948966", "x half-angle of the fan, rad"},
            {"xSweepPeriod", "0", "s; 0: a whole sweep every sample"},
            {"xSweepPhase", "0", "s"},
            {"xSweepType", "2", "0 sinusoid, 1 triangle, 2 sawtooth"},
            {"ySweepMagnitude", "0", "y half-angle, rad"},
            {"ySweepPeriod", "0", "s"},
            {"ySweepPhase", "0", "s"},
            {"ySweepType", "0", "0 sinusoid, 1 triangle, 2 sawtooth"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names;
    for (int i = 0; i < count_; ++i) names.push_back("d[" + std::to_string(i) + "]");
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    const Pose sensor = SensorPose(in, link_, tsensor_);
    sample_time_ = time_;
    sample_dt_ = last_dt_;
    measurements_.assign(count_, max_);
    for (int i = 0; i < count_; ++i) {
      const Vec3 dir = sensor.linear() * RayDirection(i, time_, last_dt_);
      measurements_[i] = Reading(in, sensor.translation(), dir);
    }
  }
  void Advance(double dt) override {
    last_dt_ = dt;
    time_ += dt;
  }
  void Reset() override {
    measurements_.assign(count_, 0.0);
    time_ = last_dt_ = 0.0;
  }
  int link() const override { return link_; }
  Pose frame() const override { return tsensor_; }
  std::vector<double> InternalState() const override { return {time_, last_dt_}; }
  void SetInternalState(const std::vector<double>& s) override {
    if (s.size() == 2) time_ = s[0], last_dt_ = s[1];
  }
  /// The direction of ray i in the sensor frame for a sample at sensor time t after dt.
  Vec3 RayDirection(int i, double t, double dt) const {
    const double tx = x_.Angle(i, count_, t, dt);
    const double ty = y_.Angle(i, count_, t, dt);
    return Vec3(std::sin(tx), std::cos(tx) * std::sin(ty), std::cos(tx) * std::cos(ty));
  }
  // rays to their readings (hits) or, missing, 2 m long at most
  void Draw(const std::vector<Pose>& frames, SensorDrawing* out) const override {
    const Pose sensor = link_ >= 0 ? Pose(frames[link_] * tsensor_) : tsensor_;
    const Vec3 origin = sensor.translation();
    for (int i = 0; i < count_ && i < static_cast<int>(measurements_.size()); ++i) {
      const Vec3 dir = sensor.linear() * RayDirection(i, sample_time_, sample_dt_);
      const double d = measurements_[i];
      const bool hit = std::isfinite(d) && d > min_ && d < max_;
      const Vec3 end = origin + dir * (hit ? d : std::min(std::isfinite(max_) ? max_ : 2.0, 2.0));
      out->segments.push_back(
          {origin, end, hit ? SensorDrawing::Kind::kRayHit : SensorDrawing::Kind::kRayMiss});
      if (hit) out->hits.push_back(end);
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "link") return ReadSensorLink(text, robot_, true, &link_, error);
    if (key == "Tsensor") return ReadSensorPose(text, &tsensor_, error);
    if (key == "measurementCount") return ReadCount(text, error);
    if (key.rfind("depth", 0) == 0) return ApplyDepth(key, text, error);
    Sweep& sweep = key[0] == 'x' ? x_ : y_;
    const std::string what = key.substr(6);
    if (what == "Type") return ReadType(text, &sweep.type, error);
    double* target = what == "Magnitude" ? &sweep.magnitude
                     : what == "Period"  ? &sweep.period
                                         : &sweep.phase;
    return ReadSensorDouble(text, target, error);
  }

 private:
  double Reading(const SensorInputs& in, const Vec3& origin, const Vec3& dir) {
    if (!in.ray) return max_;
    const double far = std::isfinite(max_) ? max_ - min_ : kInf;
    double d = in.ray(origin + min_ * dir, dir, far, link_);
    if (!std::isfinite(d)) return max_;
    d += min_;
    d = Discretize(d, resolution_, d * variance_linear_ + variance_constant_, noise_);
    return d <= min_ || d >= max_ ? max_ : d;
  }
  bool ApplyDepth(const std::string& key, const std::string& text, std::string* error) {
    double* target = key == "depthResolution"       ? &resolution_
                     : key == "depthMinimum"        ? &min_
                     : key == "depthMaximum"        ? &max_
                     : key == "depthVarianceLinear" ? &variance_linear_
                                                    : &variance_constant_;
    double v = 0.0;
    if (!ReadSensorDouble(text, &v, error)) return false;
    if (v < 0.0) return *error = key + " must be >= 0", false;
    *target = v;
    return true;
  }
  bool ReadCount(const std::string& text, std::string* error) {
    int n = 0;
    if (!ReadSensorInt(text, &n, error)) return false;
    if (n < 1 || n > 100000) return *error = "measurementCount must be 1 ... 100000", false;
    count_ = n;
    Reset();
    return true;
  }
  static bool ReadType(const std::string& text, int* type, std::string* error) {
    int t = 0;
    if (!ReadSensorInt(text, &t, error)) return false;
    if (t < 0 || t > 2) return *error = "a sweep type is 0, 1 or 2", false;
    *type = t;
    return true;
  }
  const RobotDesc& robot_;
  int link_ = -1;
  Pose tsensor_ = Pose::Identity();
  int count_ = 180;
  double resolution_ = 0.0, min_ = 0.1, max_ = kInf;
  double variance_linear_ = 0.0, variance_constant_ = 0.0;
  Sweep x_, y_;
  double time_ = 0.0, last_dt_ = 0.0;
  double sample_time_ = 0.0, sample_dt_ = 0.0;  ///< of the last sample (for drawing)
};

class CameraSensor : public Sensor {
 public:
  explicit CameraSensor(const RobotDesc& robot) : robot_(robot) { Reset(); }
  const char* type() const override { return "CameraSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"link", "-1", "the link it sits on (name or index; -1: the world)"},
            {"Tsensor", "1 0 0 0 1 0 0 0 1 0 0 0", "its frame: z forward, x right, y down"},
            {"rgb", "1", "takes colour images"},
            {"depth", "1", "takes depth images"},
            {"xres", "640", "image width, pixels"},
            {"yres", "480", "image height, pixels"},
            {"xfov", "0.9773843811168246", "horizontal field of view, rad"},
            {"yfov", "0.7504915783575616", "read, unused: the aspect gives it (as Klamp't)"},
            {"zmin", "0.4", "nearest depth, m"},
            {"zmax", "4", "farthest depth (and the depth of nothing), m"},
            {"zresolution", "0", "depth quantisation step, m"},
            {"zvarianceLinear", "0", "depth noise variance per metre, m"},
            {"zvarianceConstant", "0", "depth noise variance, m²"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names;
    for (const char* channel : {"rgb", "d"}) {
      if ((channel[0] == 'r' && !rgb_) || (channel[0] == 'd' && !depth_)) continue;
      for (int y = 0; y < yres_; ++y) {
        for (int x = 0; x < xres_; ++x) {
          names.push_back(std::string(channel) + "[" + std::to_string(x) + "," + std::to_string(y) +
                          "]");
        }
      }
    }
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    CameraImage image;
    if (!in.camera || !in.camera->Render(Request(in), &image)) return;
    measurements_.clear();
    const size_t n = static_cast<size_t>(xres_) * yres_;
    if (rgb_) {
      for (size_t i = 0; i < n; ++i)
        measurements_.push_back(i < image.rgb.size() ? image.rgb[i] : 0);
    }
    if (depth_) {
      for (size_t i = 0; i < n; ++i)
        measurements_.push_back(Depth(i < image.depth.size() ? image.depth[i] : kInf));
    }
    rendered_ = true;
  }
  void Reset() override {
    const size_t n = static_cast<size_t>(xres_) * yres_;
    measurements_.assign(n * ((rgb_ ? 1 : 0) + (depth_ ? 1 : 0)), 0.0);
    rendered_ = false;
  }
  int link() const override { return link_; }
  Pose frame() const override { return tsensor_; }
  // its frustum to 0.5 m (or zmax when nearer)
  void Draw(const std::vector<Pose>& frames, SensorDrawing* out) const override {
    const Pose camera = link_ >= 0 ? Pose(frames[link_] * tsensor_) : tsensor_;
    const double depth = std::min(zmax_, 0.5);
    const double tx = std::tan(0.5 * xfov_) * depth, ty = tx * yres_ / xres_;
    const Vec3 corners[4] = {camera * Vec3(-tx, -ty, depth), camera * Vec3(tx, -ty, depth),
                             camera * Vec3(tx, ty, depth), camera * Vec3(-tx, ty, depth)};
    for (int k = 0; k < 4; ++k) {
      out->segments.push_back({camera.translation(), corners[k], SensorDrawing::Kind::kOutline});
      out->segments.push_back({corners[k], corners[(k + 1) % 4], SensorDrawing::Kind::kOutline});
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    bool ok = false;
    if (key == "link")
      ok = ReadSensorLink(text, robot_, true, &link_, error);
    else if (key == "Tsensor")
      ok = ReadSensorPose(text, &tsensor_, error);
    else if (key == "rgb")
      ok = ReadSensorBool(text, &rgb_, error);
    else if (key == "depth")
      ok = ReadSensorBool(text, &depth_, error);
    else if (key == "xres" || key == "yres")
      ok = ReadResolution(text, key == "xres" ? &xres_ : &yres_, error);
    else
      ok = ApplyNumber(key, text, error);
    if (ok) Reset();
    return ok;
  }

 private:
  CameraRequest Request(const SensorInputs& in) const {
    CameraRequest r;
    r.camera = SensorPose(in, link_, tsensor_);
    r.width = xres_;
    r.height = yres_;
    r.xfov = xfov_;
    r.znear = std::min(0.1, zmin_);
    r.zfar = std::max(100.0, zmax_);
    r.rgb = rgb_;
    r.depth = depth_;
    return r;
  }
  double Depth(double z) {
    if (!(z < zmax_ - 1e-4)) return zmax_;
    return Discretize(z, zresolution_, z * zvariance_linear_ + zvariance_constant_, noise_);
  }
  static bool ReadResolution(const std::string& text, int* value, std::string* error) {
    int v = 0;
    if (!ReadSensorInt(text, &v, error)) return false;
    if (v < 1 || v > 8192) return *error = "an image size is 1 ... 8192 pixels", false;
    *value = v;
    return true;
  }
  bool ApplyNumber(const std::string& key, const std::string& text, std::string* error) {
    double v = 0.0;
    if (!ReadSensorDouble(text, &v, error)) return false;
    if (key == "xfov" && !(v > 0.0 && v < kPi)) return *error = "xfov must be in (0, π)", false;
    if (v < 0.0) return *error = key + " must be >= 0", false;
    double* target = key == "xfov"              ? &xfov_
                     : key == "yfov"            ? &yfov_
                     : key == "zmin"            ? &zmin_
                     : key == "zmax"            ? &zmax_
                     : key == "zresolution"     ? &zresolution_
                     : key == "zvarianceLinear" ? &zvariance_linear_
                                                : &zvariance_constant_;
    *target = v;
    return true;
  }
  const RobotDesc& robot_;
  int link_ = -1;
  Pose tsensor_ = Pose::Identity();
  bool rgb_ = true, depth_ = true, rendered_ = false;
  int xres_ = 640, yres_ = 480;
  double xfov_ = 0.9773843811168246, yfov_ = 0.7504915783575616;
  double zmin_ = 0.4, zmax_ = 4.0, zresolution_ = 0.0;
  double zvariance_linear_ = 0.0, zvariance_constant_ = 0.0;
};

}  // namespace

std::unique_ptr<Sensor> MakeVisualSensor(const std::string& type, const RobotDesc& robot) {
  if (type == "LaserRangeSensor") return std::make_unique<LaserRangeSensor>(robot);
  if (type == "CameraSensor") return std::make_unique<CameraSensor>(robot);
  return nullptr;
}

}  // namespace lamina::core
