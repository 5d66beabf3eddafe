// SPDX-License-Identifier: MIT
#include "core/io/world_xml_transform.h"

#include <sstream>

#include "core/io/text_statements.h"
#include "core/math_types.h"

namespace lamina::core {

namespace {

std::string FormatVector(const Vec3& v) {
  return FormatDoubles(v.data(), 3);
}

}  // namespace

bool ReadPose(const XmlElementReader& reader, Pose* pose) {
  *pose = Pose::Identity();
  bool any = false;
  if (const auto t = reader.Vector3(reader.Has("translation") ? "translation" : "position")) {
    pose->translation() = *t;
    any = true;
  }
  if (reader.Has("translation") && reader.Has("position")) {
    reader.Warning("both 'translation' and 'position' given; 'position' ignored");
  }
  Mat3 rotation = Mat3::Identity();
  if (const auto rpy = reader.Vector3("rotateRPY")) {
    rotation = RotationFromRollPitchYaw(rpy->x(), rpy->y(), rpy->z());
    any = true;
  }
  if (const auto moment = reader.Vector3("rotateMoment")) {
    if (reader.Has("rotateRPY")) {
      reader.Warning("both 'rotateRPY' and 'rotateMoment' given; 'rotateMoment' replaces it");
    }
    rotation = RotationFromMoment(*moment);
    any = true;
  }
  const Vec3 axes[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  const char* names[3] = {"rotateX", "rotateY", "rotateZ"};
  for (int i = 0; i < 3; ++i) {
    if (const auto angle = reader.Number(names[i], false)) {
      rotation = Eigen::AngleAxisd(*angle, axes[i]).toRotationMatrix() * rotation;
      any = true;
    }
  }
  pose->linear() = rotation;
  return any;
}

bool ReadScale(const XmlElementReader& reader, Vec3* scale) {
  const auto text = reader.String("scale");
  if (!text) return false;
  std::istringstream words(*text);
  std::string word;
  int word_count = 0;
  while (words >> word) ++word_count;
  const bool single = word_count == 1;
  if (single) {
    const auto value = reader.Number("scale", false);
    if (!value) return false;
    *scale = Vec3::Constant(*value);
  } else {
    const auto value = reader.Vector3("scale");
    if (!value) return false;
    *scale = *value;
  }
  if ((scale->array() == 0.0).any()) {
    reader.Error("scale", "must not be zero, got '" + *text + "'");
    *scale = Vec3::Ones();
    return false;
  }
  return true;
}

void ApplyGeometryTransform(const XmlElementReader& reader, GeometryDesc* geometry) {
  Pose pose;
  Vec3 scale = Vec3::Ones();
  const bool has_pose = ReadPose(reader, &pose);
  const bool has_scale = ReadScale(reader, &scale);
  if (!has_pose && !has_scale) return;
  Affine inner = geometry->transform;
  if (IsUniformScale(scale) || inner.linear().isIdentity(0.0)) {
    // diag(s) * [R1 | t1] = [R1 | s*t1] * diag(s) when s is uniform or R1 = I
    inner.translation() = scale.cwiseProduct(inner.translation());
    geometry->transform = pose * inner;
    geometry->scale = scale.cwiseProduct(geometry->scale);
  } else {
    geometry->transform = pose * Eigen::Scaling(scale) * inner;
  }
}

std::vector<std::pair<std::string, std::string>> PoseAttributes(const Pose& pose) {
  std::vector<std::pair<std::string, std::string>> attributes;
  attributes.emplace_back("translation", FormatVector(pose.translation()));
  if (!pose.linear().isIdentity(0.0)) {
    attributes.emplace_back("rotateMoment", FormatVector(MomentFromRotation(pose.linear())));
  }
  return attributes;
}

bool GeometryTransformAttributes(const GeometryDesc& geometry,
                                 std::vector<std::pair<std::string, std::string>>* attributes) {
  attributes->clear();
  Vec3 scale = geometry.scale;
  Pose pose = Pose::Identity();
  if (IsRotation(geometry.transform.linear(), 1e-12)) {
    pose.linear() = geometry.transform.linear();
    pose.translation() = geometry.transform.translation();
  } else {
    // fold the whole linear part into scale-then-rotation if its columns are orthogonal
    const Affine matrix = geometry.Matrix();
    const Mat3 linear = matrix.linear();
    scale = linear.colwise().norm().transpose();
    const Mat3 rotation = linear * scale.cwiseInverse().asDiagonal();
    if (!IsRotation(rotation, 1e-9)) return false;
    pose.linear() = rotation;
    pose.translation() = matrix.translation();
  }
  if (scale != Vec3::Ones()) {
    attributes->emplace_back("scale",
                             IsUniformScale(scale) ? FormatDouble(scale.x()) : FormatVector(scale));
  }
  if (!pose.translation().isZero(0.0)) {
    attributes->emplace_back("translation", FormatVector(pose.translation()));
  }
  if (!pose.linear().isIdentity(0.0)) {
    attributes->emplace_back("rotateMoment", FormatVector(MomentFromRotation(pose.linear())));
  }
  return true;
}

}  // namespace lamina::core
