// SPDX-License-Identifier: MIT
// Sensors made of another sensor's measurements (its `sensor` setting names it; it must come
// earlier in the robot's list):
// - TransformedSensor: m·scale + bias, then clamped to [minimum, maximum] (one value for all
//   measurements or one each; Klamp't applies `maximum` as a second minimum);
// - CorruptedSensor: N(0, variance) added to every non-zero measurement, then quantised to
//   `resolution` when it is > 0 (Klamp't divides by a zero resolution);
// - FilteredSensor: exponential smoothing out ← s·out + (1 − s)·m once per sample (the first
//   output is (1 − s)·m, as Klamp't's);
// - TimeDelayedSensor: each sample is delivered `delay` s later, ± Uniform(−jitter, jitter);
//   until the first delivery it measures nothing (an empty vector, as Klamp't's).
#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

std::vector<std::string> WrapperSensor::MeasurementNames() const {
  return wrapped_ ? wrapped_->MeasurementNames() : std::vector<std::string>{};
}

bool WrapperSensor::ApplyWrappedName(const std::string& text, std::string* error) {
  if (text.empty()) return *error = "'sensor' must name the wrapped sensor", false;
  wrapped_name_ = text;
  wrapped_ = nullptr;
  return true;
}

namespace {

const SensorSettingSpec kWrapped = {"sensor", "", "the name of the sensor it wraps"};

// entry i of a one-or-each list (`fallback` when empty or of another size)
double Each(const std::vector<double>& v, size_t i, double fallback) {
  if (v.size() == 1) return v[0];
  return i < v.size() ? v[i] : fallback;
}

class TransformedSensor : public WrapperSensor {
 public:
  const char* type() const override { return "TransformedSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {kWrapped,
            {"scale", "", "factor (one, or one per measurement)"},
            {"bias", "", "offset (one, or one per measurement)"},
            {"minimum", "", "lower bound (one, or one per measurement)"},
            {"maximum", "", "upper bound (one, or one per measurement)"}};
  }
  void Simulate(const SensorInputs&) override {
    if (!wrapped_) return;
    measurements_ = wrapped_->measurements();
    for (size_t i = 0; i < measurements_.size(); ++i) {
      double m = measurements_[i] * Each(scale_, i, 1.0) + Each(bias_, i, 0.0);
      m = std::max(Each(minimum_, i, -kInf), std::min(Each(maximum_, i, kInf), m));
      measurements_[i] = m;
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "sensor") return ApplyWrappedName(text, error);
    std::vector<double>* target = key == "scale"     ? &scale_
                                  : key == "bias"    ? &bias_
                                  : key == "minimum" ? &minimum_
                                                     : &maximum_;
    return ReadSensorList(text, target, error);
  }

 private:
  std::vector<double> scale_, bias_, minimum_, maximum_;
};

class CorruptedSensor : public WrapperSensor {
 public:
  const char* type() const override { return "CorruptedSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {kWrapped,
            {"variance", "", "noise variance (one, or one per measurement)"},
            {"resolution", "", "quantisation step (one, or one per measurement)"}};
  }
  void Simulate(const SensorInputs&) override {
    if (!wrapped_) return;
    measurements_ = wrapped_->measurements();
    for (size_t i = 0; i < measurements_.size(); ++i) {
      if (measurements_[i] == 0.0) continue;
      measurements_[i] =
          Discretize(measurements_[i], Each(resolution_, i, 0.0), Each(variance_, i, 0.0), noise_);
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "sensor") return ApplyWrappedName(text, error);
    return ReadSensorList(text, key == "variance" ? &variance_ : &resolution_, error);
  }

 private:
  std::vector<double> variance_, resolution_;
};

class FilteredSensor : public WrapperSensor {
 public:
  const char* type() const override { return "FilteredSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {kWrapped, {"smoothing", "0", "weight of the previous output, 0 ... 1"}};
  }
  void Simulate(const SensorInputs&) override {
    if (!wrapped_) return;
    const std::vector<double>& m = wrapped_->measurements();
    if (measurements_.size() != m.size()) measurements_.assign(m.size(), 0.0);
    for (size_t i = 0; i < m.size(); ++i) {
      measurements_[i] = smoothing_ * measurements_[i] + (1.0 - smoothing_) * m[i];
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "sensor") return ApplyWrappedName(text, error);
    double s = 0.0;
    if (!ReadSensorDouble(text, &s, error)) return false;
    if (!(s >= 0.0 && s <= 1.0)) return *error = "smoothing must be in [0, 1]", false;
    smoothing_ = s;
    return true;
  }

 private:
  double smoothing_ = 0.0;
};

class TimeDelayedSensor : public WrapperSensor {
 public:
  const char* type() const override { return "TimeDelayedSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {kWrapped,
            {"delay", "0", "delivery delay, s"},
            {"jitter", "0", "the delay varies by up to ± this, s"}};
  }
  void Simulate(const SensorInputs& in) override {
    if (!wrapped_) return;
    const double jitter = jitter_ > 0.0 ? jitter_ * (2.0 * noise_.Uniform() - 1.0) : 0.0;
    queue_.push_back({in.time + delay_ + jitter, wrapped_->measurements()});
    // deliveries are taken in order of sampling (a jittered later sample waits for the earlier)
    while (!queue_.empty() && queue_.front().time <= in.time + 1e-9) {
      measurements_ = std::move(queue_.front().values);
      queue_.pop_front();
    }
  }
  void Reset() override {
    queue_.clear();
    measurements_.clear();
  }
  std::vector<double> InternalState() const override {
    std::vector<double> s = {static_cast<double>(queue_.size())};
    for (const Item& item : queue_) {
      s.push_back(item.time);
      s.push_back(static_cast<double>(item.values.size()));
      s.insert(s.end(), item.values.begin(), item.values.end());
    }
    return s;
  }
  void SetInternalState(const std::vector<double>& s) override {
    queue_.clear();
    size_t next = 1;
    const size_t count = s.empty() ? 0 : static_cast<size_t>(s[0]);
    for (size_t k = 0; k < count && next + 1 < s.size(); ++k) {
      Item item{s[next], {}};
      const size_t n = static_cast<size_t>(s[next + 1]);
      if (next + 2 + n > s.size()) break;
      item.values.assign(s.begin() + next + 2, s.begin() + next + 2 + n);
      next += 2 + n;
      queue_.push_back(std::move(item));
    }
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "sensor") return ApplyWrappedName(text, error);
    double v = 0.0;
    if (!ReadSensorDouble(text, &v, error)) return false;
    if (!(v >= 0.0 && std::isfinite(v))) return *error = key + " must be a finite time >= 0", false;
    (key == "delay" ? delay_ : jitter_) = v;
    return true;
  }

 private:
  struct Item {
    double time;
    std::vector<double> values;
  };
  double delay_ = 0.0, jitter_ = 0.0;
  std::deque<Item> queue_;
};

}  // namespace

std::unique_ptr<Sensor> MakeWrapperSensor(const std::string& type) {
  if (type == "TransformedSensor") return std::make_unique<TransformedSensor>();
  if (type == "CorruptedSensor") return std::make_unique<CorruptedSensor>();
  if (type == "FilteredSensor") return std::make_unique<FilteredSensor>();
  if (type == "TimeDelayedSensor") return std::make_unique<TimeDelayedSensor>();
  return nullptr;
}

}  // namespace lamina::core
