// SPDX-License-Identifier: MIT
#include "core/sensors/sensor_text.h"

#include <cmath>
#include <sstream>

#include "core/diagnostics.h"
#include "core/number_text.h"

namespace lamina::core {

namespace {

std::vector<std::string> TextWords(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// every word a finite number (inf allowed when `allow_inf`)
bool Numbers(const std::string& text, bool allow_inf, std::vector<double>* out,
             std::string* error) {
  std::vector<double> values;
  for (const std::string& word : TextWords(text)) {
    double v = 0.0;
    if (!ParseDouble(word, &v) || std::isnan(v) || (!allow_inf && std::isinf(v))) {
      return FailWith(error, "'" + word + "' is not a number");
    }
    values.push_back(v);
  }
  *out = std::move(values);
  return true;
}

bool FixedNumbers(const std::string& text, size_t count, std::vector<double>* out,
                  std::string* error) {
  if (!Numbers(text, true, out, error)) return false;
  if (out->size() == count) return true;
  return FailWith(
      error, "expected " + std::to_string(count) + " numbers, got " + std::to_string(out->size()));
}

}  // namespace

bool ReadSensorDouble(const std::string& text, double* value, std::string* error) {
  std::vector<double> v;
  if (!FixedNumbers(text, 1, &v, error)) return false;
  *value = v[0];
  return true;
}

bool ReadSensorInt(const std::string& text, int* value, std::string* error) {
  const std::vector<std::string> words = TextWords(text);
  if (words.size() != 1 || !ParseInt(words[0], value)) {
    return FailWith(error, "'" + text + "' is not an integer");
  }
  return true;
}

bool ReadSensorBool(const std::string& text, bool* value, std::string* error) {
  const std::vector<std::string> words = TextWords(text);
  const std::string word = words.size() == 1 ? ToLower(words[0]) : "";
  if (word == "1" || word == "true")
    *value = true;
  else if (word == "0" || word == "false")
    *value = false;
  else
    return FailWith(error, "'" + text + "' is not a boolean (0 or 1)");
  return true;
}

bool ReadSensorBool3(const std::string& text, std::array<bool, 3>* value, std::string* error) {
  const std::vector<std::string> words = TextWords(text);
  if (words.size() != 3) return FailWith(error, "expected 3 booleans (0 or 1), got '" + text + "'");
  std::array<bool, 3> flags{};
  for (int i = 0; i < 3; ++i) {
    if (!ReadSensorBool(words[i], &flags[i], error)) return false;
  }
  *value = flags;
  return true;
}

bool ReadSensorVec2(const std::string& text, Eigen::Vector2d* value, std::string* error) {
  std::vector<double> v;
  if (!FixedNumbers(text, 2, &v, error)) return false;
  *value = Eigen::Vector2d(v[0], v[1]);
  return true;
}

bool ReadSensorVec3(const std::string& text, Vec3* value, std::string* error) {
  std::vector<double> v;
  if (!FixedNumbers(text, 3, &v, error)) return false;
  *value = Vec3(v[0], v[1], v[2]);
  return true;
}

bool ReadSensorList(const std::string& text, std::vector<double>* value, std::string* error) {
  std::vector<double> v;
  if (!Numbers(text, true, &v, error)) return false;
  const bool counted = !v.empty() && v[0] == std::floor(v[0]) &&
                       static_cast<size_t>(v[0]) == v.size() - 1 && v.size() > 1;
  if (counted || (v.size() == 1 && v[0] == 0.0 && text.find('.') == std::string::npos)) {
    v.erase(v.begin());
  }
  *value = std::move(v);
  return true;
}

bool ReadSensorIndices(const std::string& text, std::vector<int>* value, std::string* error) {
  std::vector<int> indices;
  for (const std::string& word : TextWords(text)) {
    int i = 0;
    if (!ParseInt(word, &i) || i < 0) return FailWith(error, "'" + word + "' is not an index");
    indices.push_back(i);
  }
  *value = std::move(indices);
  return true;
}

bool ReadSensorPose(const std::string& text, Pose* value, std::string* error) {
  std::vector<double> v;
  if (!FixedNumbers(text, 12, &v, error)) return false;
  const Mat3 r = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v.data());
  if (!IsRotation(r, 1e-6)) return FailWith(error, "the first 9 numbers are not a rotation");
  Pose pose = Pose::Identity();
  pose.linear() = r;
  pose.translation() = Vec3(v[9], v[10], v[11]);
  *value = pose;
  return true;
}

bool ReadSensorMat3(const std::string& text, Mat3* value, std::string* error) {
  std::vector<double> v;
  if (!FixedNumbers(text, 9, &v, error)) return false;
  *value = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v.data());
  return true;
}

bool ReadSensorLink(const std::string& text, const RobotDesc& robot, bool allow_world, int* link,
                    std::string* error) {
  const std::vector<std::string> words = TextWords(text);
  const std::string word = words.size() == 1 ? words[0] : text;
  for (int i = 0; i < robot.dof(); ++i) {
    if (robot.links[i].name == word) return *link = i, true;
  }
  int index = 0;
  if (!ParseInt(word, &index)) return FailWith(error, "no link named '" + word + "'");
  if ((index == -1 && allow_world) || (index >= 0 && index < robot.dof())) {
    return *link = index, true;
  }
  return FailWith(error, "link " + word + " is out of range (the robot has " +
                             std::to_string(robot.dof()) + " links)");
}

}  // namespace lamina::core
