// SPDX-License-Identifier: MIT
// The text of sensor settings as Klamp't's `<sensors>` XML writes it: numbers separated by
// whitespace; booleans 0/1 (true/false read too); vectors such as `qvariance` with Klamp't's
// leading count ("3 0.1 0.1 0.1") or without it (its manual's spelling); transforms as 12
// numbers (rotation row by row, then translation); 3×3 matrices row by row. Each reader returns
// false with `*error` saying what was expected; nothing is changed then.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

bool ReadSensorDouble(const std::string& text, double* value, std::string* error);
bool ReadSensorInt(const std::string& text, int* value, std::string* error);
bool ReadSensorBool(const std::string& text, bool* value, std::string* error);
/// Exactly three booleans ("1 1 0").
bool ReadSensorBool3(const std::string& text, std::array<bool, 3>* value, std::string* error);
/// Exactly two / three numbers.
bool ReadSensorVec2(const std::string& text, Eigen::Vector2d* value, std::string* error);
bool ReadSensorVec3(const std::string& text, Vec3* value, std::string* error);
/// Any count of numbers (empty allowed); a leading integer equal to the count of the others is
/// Klamp't's count and is dropped.
bool ReadSensorList(const std::string& text, std::vector<double>* value, std::string* error);
/// Non-negative integers ("6 7 8").
bool ReadSensorIndices(const std::string& text, std::vector<int>* value, std::string* error);
/// 12 numbers: a rotation (row by row, orthonormal within 1e-6) then a translation.
bool ReadSensorPose(const std::string& text, Pose* value, std::string* error);
/// 9 numbers, row by row.
bool ReadSensorMat3(const std::string& text, Mat3* value, std::string* error);
/// A link of `robot` by name or index, or -1 when `allow_world`.
bool ReadSensorLink(const std::string& text, const RobotDesc& robot, bool allow_world, int* link,
                    std::string* error);

}  // namespace lamina::core
