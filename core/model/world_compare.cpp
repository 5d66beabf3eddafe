// SPDX-License-Identifier: MIT
#include "core/model/world_compare.h"

#include <cmath>

#include "core/model/element.h"
#include "core/model/params.h"
#include "core/number_text.h"

namespace lamina::core {

namespace {

class Comparer {
 public:
  explicit Comparer(double tolerance) : tolerance_(tolerance) {}

  void Number(const std::string& field, double a, double b) {
    const bool same =
        (a == b) || (std::isfinite(a) && std::isfinite(b) && std::abs(a - b) <= tolerance_);
    if (!same) Add(field, FormatDouble(a), FormatDouble(b));
  }
  template <typename Derived>
  void Matrix(const std::string& field, const Eigen::MatrixBase<Derived>& a,
              const Eigen::MatrixBase<Derived>& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) {
      Add(field + ".size", std::to_string(a.size()), std::to_string(b.size()));
      return;
    }
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      for (Eigen::Index j = 0; j < a.cols(); ++j) {
        Number(field + "(" + std::to_string(i) + "," + std::to_string(j) + ")", a(i, j), b(i, j));
      }
    }
  }
  template <typename T>
  void Exact(const std::string& field, const T& a, const T& b, const std::string& a_text,
             const std::string& b_text) {
    if (!(a == b)) Add(field, a_text, b_text);
  }
  void Text(const std::string& field, const std::string& a, const std::string& b) {
    if (a != b) Add(field, "'" + a + "'", "'" + b + "'");
  }
  void Integer(const std::string& field, long a, long b) {
    if (a != b) Add(field, std::to_string(a), std::to_string(b));
  }
  bool Count(const std::string& field, size_t a, size_t b) {
    Integer(field + ".size", static_cast<long>(a), static_cast<long>(b));
    return a == b;
  }
  void Add(const std::string& field, const std::string& a, const std::string& b) {
    differences_.push_back(field + ": " + a + " vs " + b);
  }
  // one row's values: "objects[1].kFriction: 0.5 vs 0.8", components compared as numbers
  void Row(const std::string& field, const ParamSpec& spec, const ParamValue& a,
           const ParamValue& b) {
    if (a.size() != b.size()) {
      Integer(field + ".size", static_cast<long>(a.size()), static_cast<long>(b.size()));
      return;
    }
    const size_t before = differences_.size();
    for (size_t i = 0; i < a.size(); ++i) Number(field, a[i], b[i]);
    if (differences_.size() == before) return;
    differences_.resize(before);
    Add(field, FormatParamValue(spec, a), FormatParamValue(spec, b));
  }
  // every row of elements of `element.kind` on `element` of the two worlds, named
  // `prefix.key` (prefix: the element's access path, or what CompareRobots was given)
  void Rows(const std::string& prefix, const WorldDesc& a, const WorldDesc& b,
            const ElementIndex& element) {
    for (const ParamSpec* spec : ParamsOf(element.kind)) {
      Row(prefix + "." + std::string(spec->key), *spec, spec->get(a, element),
          spec->get(b, element));
    }
  }

  void Geometry(const std::string& f, const GeometryDesc& a, const GeometryDesc& b);
  void Link(const std::string& f, const LinkDesc& a, const LinkDesc& b);
  void Driver(const std::string& f, const DriverDesc& a, const DriverDesc& b);
  // a robot of each world at index `r`, named `f`
  void Robot(const std::string& f, const WorldDesc& a, const WorldDesc& b, int r);
  void Object(const std::string& f, const RigidObjectDesc& a, const RigidObjectDesc& b);

  std::vector<std::string> differences_;

 private:
  double tolerance_;
};

void Comparer::Geometry(const std::string& f, const GeometryDesc& a, const GeometryDesc& b) {
  Integer(f + ".kind", static_cast<int>(a.kind), static_cast<int>(b.kind));
  Text(f + ".path", a.path, b.path);
  Number(f + ".margin", a.margin, b.margin);
  Matrix(f + ".matrix", a.Matrix().matrix(), b.Matrix().matrix());
  if (a.kind == GeometryKind::kPrimitive && b.kind == GeometryKind::kPrimitive) {
    Integer(f + ".primitive.type", static_cast<int>(a.primitive.type),
            static_cast<int>(b.primitive.type));
    // compare shapes, not parameterizations: a sphere has no orientation, a cylinder none
    // about its axis
    const Pose& pa = a.primitive.pose;
    const Pose& pb = b.primitive.pose;
    Matrix(f + ".primitive.center", pa.translation(), pb.translation());
    if (a.primitive.type == PrimitiveType::kBox) {
      Matrix(f + ".primitive.rotation", pa.linear(), pb.linear());
    } else if (a.primitive.type != PrimitiveType::kSphere) {
      const Vec3 axis_a = pa.linear().col(2);
      const Vec3 axis_b = pb.linear().col(2);
      Matrix(f + ".primitive.axis", axis_a, axis_b);
    }
    Number(f + ".primitive.radius", a.primitive.radius, b.primitive.radius);
    Number(f + ".primitive.length", a.primitive.length, b.primitive.length);
    Matrix(f + ".primitive.size", a.primitive.size, b.primitive.size);
  }
  if (a.kind == GeometryKind::kMesh && b.kind == GeometryKind::kMesh) {
    Integer(f + ".triangles", a.triangle_count(), b.triangle_count());
  }
  if (a.kind == GeometryKind::kPointCloud && b.kind == GeometryKind::kPointCloud) {
    Integer(f + ".points", a.point_count(), b.point_count());
  }
}

void Comparer::Link(const std::string& f, const LinkDesc& a, const LinkDesc& b) {
  Text(f + ".name", a.name, b.name);
  Integer(f + ".parent", a.parent, b.parent);
  Integer(f + ".axis_type", static_cast<int>(a.axis_type), static_cast<int>(b.axis_type));
  Matrix(f + ".axis", a.axis, b.axis);
  Matrix(f + ".parent_transform", a.parent_transform.matrix(), b.parent_transform.matrix());
  Number(f + ".q_initial", a.q_initial, b.q_initial);
  Number(f + ".velocity_min", a.velocity_min, b.velocity_min);
  Number(f + ".velocity_max", a.velocity_max, b.velocity_max);
  Number(f + ".acceleration_max", a.acceleration_max, b.acceleration_max);
  Number(f + ".torque_max", a.torque_max, b.torque_max);
  Number(f + ".power_max", a.power_max, b.power_max);
  if (Count(f + ".geometry", a.geometry.size(), b.geometry.size())) {
    for (size_t i = 0; i < a.geometry.size(); ++i) {
      Geometry(f + ".geometry[" + std::to_string(i) + "]", a.geometry[i], b.geometry[i]);
    }
  }
}

void Comparer::Driver(const std::string& f, const DriverDesc& a, const DriverDesc& b) {
  Text(f + ".name", a.name, b.name);
  Integer(f + ".type", static_cast<int>(a.type), static_cast<int>(b.type));
  if (Count(f + ".links", a.links.size(), b.links.size())) {
    for (size_t i = 0; i < a.links.size(); ++i) {
      Integer(f + ".links[" + std::to_string(i) + "]", a.links[i], b.links[i]);
    }
  }
  if (Count(f + ".affine_scale", a.affine_scale.size(), b.affine_scale.size())) {
    for (size_t i = 0; i < a.affine_scale.size(); ++i) {
      Number(f + ".affine_scale[" + std::to_string(i) + "]", a.affine_scale[i], b.affine_scale[i]);
    }
  }
  if (Count(f + ".affine_offset", a.affine_offset.size(), b.affine_offset.size())) {
    for (size_t i = 0; i < a.affine_offset.size(); ++i) {
      Number(f + ".affine_offset[" + std::to_string(i) + "]", a.affine_offset[i],
             b.affine_offset[i]);
    }
  }
  Number(f + ".q_min", a.q_min, b.q_min);
  Number(f + ".q_max", a.q_max, b.q_max);
  Number(f + ".acceleration_min", a.acceleration_min, b.acceleration_min);
  Number(f + ".acceleration_max", a.acceleration_max, b.acceleration_max);
}

std::string PairsText(const std::vector<std::pair<int, int>>& pairs) {
  std::string text;
  for (const auto& [i, j] : pairs) {
    // appended piece by piece: GCC 12 at -O3 flags `"(" + std::string` with a false -Wrestrict
    text += '(';
    text += std::to_string(i);
    text += ',';
    text += std::to_string(j);
    text += ')';
  }
  return text;
}

void Comparer::Robot(const std::string& f, const WorldDesc& wa, const WorldDesc& wb, int r) {
  const RobotDesc& a = wa.robots[r];
  const RobotDesc& b = wb.robots[r];
  if (Count(f + ".links", a.links.size(), b.links.size())) {
    for (size_t i = 0; i < a.links.size(); ++i) {
      const std::string g = f + ".links[" + std::to_string(i) + "]";
      Link(g, a.links[i], b.links[i]);
      Rows(g, wa, wb, ElementIndex::Link(r, static_cast<int>(i)));
    }
  }
  if (Count(f + ".joints", a.joints.size(), b.joints.size())) {
    for (size_t i = 0; i < a.joints.size(); ++i) {
      const std::string g = f + ".joints[" + std::to_string(i) + "]";
      Integer(g + ".type", static_cast<int>(a.joints[i].type), static_cast<int>(b.joints[i].type));
      Integer(g + ".link", a.joints[i].link, b.joints[i].link);
      Integer(g + ".base", a.joints[i].base, b.joints[i].base);
    }
  }
  if (Count(f + ".drivers", a.drivers.size(), b.drivers.size())) {
    for (size_t i = 0; i < a.drivers.size(); ++i) {
      const std::string g = f + ".drivers[" + std::to_string(i) + "]";
      Driver(g, a.drivers[i], b.drivers[i]);
      Rows(g, wa, wb, ElementIndex::Driver(r, static_cast<int>(i)));
    }
  }
  Exact(f + ".self_collision", a.self_collision, b.self_collision, PairsText(a.self_collision),
        PairsText(b.self_collision));
  Exact(f + ".no_self_collision", a.no_self_collision, b.no_self_collision,
        PairsText(a.no_self_collision), PairsText(b.no_self_collision));
  Exact(f + ".properties", a.properties, b.properties, std::to_string(a.properties.size()),
        std::to_string(b.properties.size()));
  if (a.links.size() == b.links.size()) Rows(f, wa, wb, ElementIndex::Robot(r));
  Exact(f + ".link_display", a.link_display, b.link_display, std::to_string(a.link_display.size()),
        std::to_string(b.link_display.size()));
}

void Comparer::Object(const std::string& f, const RigidObjectDesc& a, const RigidObjectDesc& b) {
  Text(f + ".name", a.name, b.name);
  Geometry(f + ".geometry", a.geometry, b.geometry);
  Exact(f + ".display", a.display, b.display, std::to_string(a.display.size()),
        std::to_string(b.display.size()));
}

}  // namespace

std::vector<std::string> CompareRobots(const RobotDesc& a, const RobotDesc& b, double tolerance,
                                       const std::string& prefix) {
  // the rows address robots of a world: each robot is compared as robot 0 of a world of its own
  WorldDesc wa, wb;
  wa.robots.push_back(a);
  wb.robots.push_back(b);
  Comparer comparer(tolerance);
  comparer.Robot(prefix, wa, wb, 0);
  return comparer.differences_;
}

std::vector<std::string> CompareWorlds(const WorldDesc& a, const WorldDesc& b, double tolerance) {
  Comparer c(tolerance);
  if (c.Count("terrains", a.terrains.size(), b.terrains.size())) {
    for (size_t i = 0; i < a.terrains.size(); ++i) {
      const std::string f = "terrains[" + std::to_string(i) + "]";
      c.Text(f + ".name", a.terrains[i].name, b.terrains[i].name);
      c.Geometry(f + ".geometry", a.terrains[i].geometry, b.terrains[i].geometry);
      c.Rows(f, a, b, ElementIndex::Terrain(static_cast<int>(i)));
      c.Exact(f + ".display", a.terrains[i].display, b.terrains[i].display,
              std::to_string(a.terrains[i].display.size()),
              std::to_string(b.terrains[i].display.size()));
    }
  }
  if (c.Count("objects", a.objects.size(), b.objects.size())) {
    for (size_t i = 0; i < a.objects.size(); ++i) {
      const std::string f = "objects[" + std::to_string(i) + "]";
      c.Object(f, a.objects[i], b.objects[i]);
      c.Rows(f, a, b, ElementIndex::Object(static_cast<int>(i)));
    }
  }
  if (c.Count("robots", a.robots.size(), b.robots.size())) {
    for (size_t i = 0; i < a.robots.size(); ++i) {
      const std::string f = "robots[" + std::to_string(i) + "]";
      c.Text(f + ".name", a.robots[i].name, b.robots[i].name);
      c.Robot(f, a, b, static_cast<int>(i));
    }
  }
  c.Rows("settings", a, b, ElementIndex::Settings());
  c.Exact("joints", a.joints, b.joints, std::to_string(a.joints.size()) + " joints",
          std::to_string(b.joints.size()) + " joints");
  c.Exact("preserved_simulation_xml", a.preserved_simulation_xml, b.preserved_simulation_xml,
          std::to_string(a.preserved_simulation_xml.size()),
          std::to_string(b.preserved_simulation_xml.size()));
  return c.differences_;
}

}  // namespace lamina::core
