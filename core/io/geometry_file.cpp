// SPDX-License-Identifier: MIT
#include "core/io/geometry_file.h"

#include <cmath>
#include <utility>
#include <vector>

#include "core/io/mesh_file.h"
#include "core/io/paths.h"
#include "core/io/point_cloud_file.h"
#include "core/io/text_statements.h"

namespace lamina::core {

namespace {

constexpr double kAxisTolerance = 1e-6;  // orthonormality of Box axes, unit length of axes

// Parses KrisLibrary's GeometricPrimitive3D text (whitespace-separated, like its stream
// operators) into our centred primitives.
class GeomParser {
 public:
  GeomParser(const std::string& text, const std::string& file, Diagnostics& diagnostics)
      : file_(file), diagnostics_(diagnostics) {
    for (Statement& statement : SplitStatements(text, file, &diagnostics)) {
      for (Token& token : statement.tokens) tokens_.push_back(std::move(token));
    }
  }

  std::optional<Primitive> Parse() {
    if (!ReadHeader()) return std::nullopt;
    if (next_ >= tokens_.size()) {
      Error(tokens_.back().line, "expected a primitive type after 'Primitive'");
      return std::nullopt;
    }
    const Token& type = tokens_[next_++];
    std::optional<Primitive> primitive = ParseType(type);
    if (primitive && next_ < tokens_.size()) {
      diagnostics_.Warning(
          {file_, tokens_[next_].line},
          "ignoring extra text after the primitive: '" + tokens_[next_].text + "'");
    }
    return primitive;
  }

 private:
  void Error(int line, std::string message) {
    diagnostics_.Error({file_, line}, std::move(message));
  }

  bool ReadHeader() {
    if (tokens_.empty()) {
      Error(1, "empty geometry file, expected 'Primitive'");
      return false;
    }
    const Token& header = tokens_[next_++];
    const std::string lower = ToLower(header.text);
    if (lower == "primitive") return true;
    if (lower == "trianglemesh" || lower == "pointcloud" || lower == "implicitsurface" ||
        lower == "occupancygrid" || lower == "convexhull" || lower == "heightmap" ||
        lower == "group") {
      Error(header.line, "unsupported geometry type '" + header.text +
                             "', only 'Primitive' is supported in '.geom' files");
    } else {
      Error(header.line, "expected 'Primitive', got '" + header.text + "'");
    }
    return false;
  }

  std::optional<Primitive> ParseType(const Token& type) {
    const std::string lower = ToLower(type.text);
    if (lower == "sphere") return ParseSphere(type);
    if (lower == "box") return ParseBox(type);
    if (lower == "aabb") return ParseAabb(type);
    if (lower == "cylinder") return ParseCylinder(type, PrimitiveType::kCylinder);
    if (lower == "capsule") return ParseCylinder(type, PrimitiveType::kCapsule);
    if (lower == "point" || lower == "segment" || lower == "triangle" || lower == "polygon" ||
        lower == "ellipsoid" || lower == "plane") {
      Error(type.line, "unsupported primitive type '" + type.text + "'");
    } else {
      Error(type.line, "unknown primitive type '" + type.text +
                           "', expected 'Sphere', 'Box', 'AABB', 'Cylinder' or 'Capsule'");
    }
    return std::nullopt;
  }

  // Reads `count` finite numbers; `layout` names them for the message.
  bool ReadValues(const Token& type, int count, const char* layout, std::vector<double>* values) {
    const size_t available = tokens_.size() - next_;
    if (available < static_cast<size_t>(count)) {
      Error(type.line, "'" + type.text + "' expects " + std::to_string(count) + " values (" +
                           layout + "), got " + std::to_string(available));
      next_ = tokens_.size();
      return false;
    }
    bool ok = true;
    values->assign(count, 0.0);
    for (int i = 0; i < count; ++i) {
      const Token& token = tokens_[next_ + i];
      if (!ParseDouble(token.text, &(*values)[i])) {
        Error(token.line, "'" + token.text + "' is not a number");
        ok = false;
      } else if (!std::isfinite((*values)[i])) {
        Error(token.line, "'" + token.text + "' is not a finite number");
        ok = false;
      }
    }
    first_value_ = next_;
    next_ += count;
    return ok;
  }

  // Checks values[index] > 0 (or >= 0); reports at that value's line.
  bool CheckPositive(const std::vector<double>& values, int index, const char* what,
                     bool allow_zero) {
    const double v = values[index];
    if (v > 0.0 || (allow_zero && v == 0.0)) return true;
    const Token& token = tokens_[first_value_ + index];
    Error(token.line, std::string(what) + (allow_zero ? " must be >= 0" : " must be > 0") +
                          ", got '" + token.text + "'");
    return false;
  }

  std::optional<Primitive> ParseSphere(const Token& type) {
    std::vector<double> v;
    if (!ReadValues(type, 4, "center, radius", &v)) return std::nullopt;
    if (!CheckPositive(v, 3, "sphere radius", false)) return std::nullopt;
    return Primitive::Sphere(v[3], Vec3(v[0], v[1], v[2]));
  }

  // Box3D: a corner `origin`, unit axes, and the extent along each axis from that corner.
  std::optional<Primitive> ParseBox(const Token& type) {
    std::vector<double> v;
    if (!ReadValues(type, 15, "origin, x axis, y axis, z axis, dimensions", &v)) {
      return std::nullopt;
    }
    bool ok = true;
    for (int i = 12; i < 15; ++i) ok = CheckPositive(v, i, "box dimension", true) && ok;
    Vec3 origin(v[0], v[1], v[2]);
    Mat3 axes;
    axes << v[3], v[6], v[9], v[4], v[7], v[10], v[5], v[8], v[11];
    const Vec3 dims(v[12], v[13], v[14]);
    if (!(axes.transpose() * axes).isApprox(Mat3::Identity(), kAxisTolerance)) {
      Error(type.line, "'Box' axes must be orthonormal");
      return std::nullopt;
    }
    if (!ok) return std::nullopt;
    if (axes.determinant() < 0.0) {
      // a left-handed frame describes the same box from the opposite z face
      origin += axes.col(2) * dims.z();
      axes.col(2) = -axes.col(2);
    }
    Pose pose = Pose::Identity();
    pose.linear() = axes;
    pose.translation() = origin + axes * (dims / 2.0);
    return Primitive::Box(dims, pose);
  }

  std::optional<Primitive> ParseAabb(const Token& type) {
    std::vector<double> v;
    if (!ReadValues(type, 6, "min, max", &v)) return std::nullopt;
    const Vec3 low(v[0], v[1], v[2]);
    const Vec3 high(v[3], v[4], v[5]);
    if ((high.array() < low.array()).any()) {
      Error(type.line, "'AABB' max must be >= min on every axis, got min '" +
                           FormatDoubles(low.data(), 3) + "' and max '" +
                           FormatDoubles(high.data(), 3) + "'");
      return std::nullopt;
    }
    Pose pose = Pose::Identity();
    pose.translation() = (low + high) / 2.0;
    return Primitive::Box(high - low, pose);
  }

  // Cylinder3D (and our Capsule): base centre, axis, radius, height along the axis.
  std::optional<Primitive> ParseCylinder(const Token& type, PrimitiveType kind) {
    std::vector<double> v;
    if (!ReadValues(type, 8, "base center, axis, radius, height", &v)) return std::nullopt;
    const Vec3 base(v[0], v[1], v[2]);
    Vec3 axis(v[3], v[4], v[5]);
    const bool radius_ok = CheckPositive(v, 6, "radius", false);
    const bool height_ok = CheckPositive(v, 7, "height", true);
    if (axis.norm() < kAxisTolerance) {
      Error(type.line, "'" + type.text + "' axis must be non-zero");
      return std::nullopt;
    }
    if (!radius_ok || !height_ok) return std::nullopt;
    if (std::abs(axis.norm() - 1.0) > kAxisTolerance) {
      diagnostics_.Warning({file_, type.line}, "normalizing '" + type.text + "' axis of length " +
                                                   FormatDouble(axis.norm()));
    }
    axis.normalize();
    Pose pose = Pose::Identity();
    pose.linear() = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
    pose.translation() = base + axis * (v[7] / 2.0);
    return kind == PrimitiveType::kCapsule ? Primitive::Capsule(v[6], v[7], pose)
                                           : Primitive::Cylinder(v[6], v[7], pose);
  }

  const std::string& file_;
  Diagnostics& diagnostics_;
  std::vector<Token> tokens_;
  size_t next_ = 0;
  size_t first_value_ = 0;  // index of the first value read by the last ReadValues
};

bool LoadPointCloud(const std::string& path, const SourceLocation& at, LoadContext& context,
                    GeometryDesc* out) {
  std::shared_ptr<const PointCloud> cloud =
      context.meshes.GetPointCloud(path, at, context.diagnostics);
  if (!cloud) return false;
  out->kind = GeometryKind::kPointCloud;
  out->path = path;
  out->mesh = nullptr;
  out->primitive = Primitive();
  out->point_cloud = std::move(cloud);
  return true;
}

}  // namespace

std::optional<Primitive> ParseGeomText(const std::string& text, const std::string& file,
                                       Diagnostics& diagnostics) {
  return GeomParser(text, file, diagnostics).Parse();
}

bool LoadGeometryFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                      GeometryDesc* out) {
  const SourceLocation at{where.file.empty() ? path : where.file, where.line};
  const std::string extension = LowerExtension(path);
  if (extension == "geom") {
    std::string text;
    if (!ReadFileText(path, &text)) {
      context.diagnostics.Error(at, "cannot open geometry file '" + path + "'");
      return false;
    }
    std::optional<Primitive> primitive = ParseGeomText(text, path, context.diagnostics);
    if (!primitive) return false;
    out->kind = GeometryKind::kPrimitive;
    out->path = path;
    out->mesh = nullptr;
    out->primitive = *primitive;
    out->point_cloud = nullptr;
    return true;
  }
  if (extension.empty()) {
    context.diagnostics.Error(at, "geometry file '" + path + "' has no extension");
    return false;
  }
  if (IsPointCloudExtension(extension)) return LoadPointCloud(path, at, context, out);
  if (!IsMeshExtension(extension)) {
    context.diagnostics.Error(at, "unsupported geometry file type '." + extension + "'");
    return false;
  }
  std::shared_ptr<const TriangleMesh> mesh = context.meshes.Get(path, at, context.diagnostics);
  if (!mesh) return false;
  out->kind = GeometryKind::kMesh;
  out->path = path;
  out->mesh = std::move(mesh);
  out->primitive = Primitive();
  out->point_cloud = nullptr;
  return true;
}

}  // namespace lamina::core
