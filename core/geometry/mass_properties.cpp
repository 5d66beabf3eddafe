// SPDX-License-Identifier: MIT
#include "core/geometry/mass_properties.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "core/geometry/tessellate.h"

namespace lamina::core {

namespace {

// Below this fraction of the bounding size (cubed for volume, squared for area) a mesh has no
// usable volume or area.
constexpr double kDegenerateFraction = 1e-12;
// Circle divisions when a primitive has to be meshed (volume error ~ 0.1 % at 128).
constexpr int kMassSegments = 128;

// Integrals over a body of 1, x and x x^T, with x relative to a reference point.
struct Moments {
  double measure = 0.0;  ///< volume or area
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
};

// Sum of v v^T over the three vertices plus s s^T for their sum s: the bracket of the
// closed forms for triangles and tetrahedra with a vertex at the origin.
Mat3 VertexBracket(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 s = a + b + c;
  return a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose();
}

// Signed tetrahedra (reference, a, b, c): ∫ x x^T = det/120 · bracket, volume det/6.
Moments SolidMoments(const TriangleMesh& mesh, const Vec3& reference) {
  Moments m;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - reference;
    const Vec3 b = mesh.vertices[t[1]] - reference;
    const Vec3 c = mesh.vertices[t[2]] - reference;
    const double det = a.dot(b.cross(c));
    m.measure += det / 6.0;
    m.first += det / 24.0 * (a + b + c);
    m.second += det / 120.0 * VertexBracket(a, b, c);
  }
  return m;
}

// Uniform thin triangles: ∫ x x^T = area/12 · bracket.
Moments ShellMoments(const TriangleMesh& mesh, const Vec3& reference) {
  Moments m;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]] - reference;
    const Vec3 b = mesh.vertices[t[1]] - reference;
    const Vec3 c = mesh.vertices[t[2]] - reference;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    m.measure += area;
    m.first += area / 3.0 * (a + b + c);
    m.second += area / 12.0 * VertexBracket(a, b, c);
  }
  return m;
}

// COM = reference + mean; inertia from the covariance of the per-unit-mass distribution.
MassProperties FromDistribution(const Vec3& reference, const Vec3& mean, const Mat3& second,
                                double mass) {
  Mat3 covariance = second - mean * mean.transpose();
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  MassProperties out;
  out.com = reference + mean;
  out.inertia = mass * (covariance.trace() * Mat3::Identity() - covariance);
  out.valid = true;
  return out;
}

// Per-unit-measure second moments (diagonal, about the centre) of a centred primitive.
struct PrimitiveMoments {
  double volume = 0.0;
  double area = 0.0;
  Vec3 solid = Vec3::Zero();  ///< E[x²], E[y²], E[z²] of the solid
  Vec3 shell = Vec3::Zero();  ///< same for the surface
};

PrimitiveMoments BoxMoments(const Vec3& size) {
  PrimitiveMoments m;
  m.volume = size.prod();
  m.area = 2.0 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
  for (int i = 0; i < 3; ++i) {
    const double a = size[i], b = size[(i + 1) % 3], c = size[(i + 2) % 3];
    m.solid[i] = a * a / 12.0;
    // two faces across axis i at ±a/2, four faces along it where x_i is uniform
    const double integral = a * a * b * c / 2.0 + a * a * a * (b + c) / 6.0;
    m.shell[i] = m.area > 0.0 ? integral / m.area : 0.0;
  }
  return m;
}

PrimitiveMoments CylinderMoments(double r, double h) {
  PrimitiveMoments m;
  m.volume = kPi * r * r * h;
  m.area = 2.0 * kPi * r * h + 2.0 * kPi * r * r;
  m.solid = Vec3(r * r / 4.0, r * r / 4.0, h * h / 12.0);
  const double radial = kPi * r * r * r * h + kPi * r * r * r * r / 2.0;
  const double axial = kPi * r * h * h * h / 6.0 + kPi * r * r * h * h / 2.0;
  if (m.area > 0.0) m.shell = Vec3(radial, radial, axial) / m.area;
  return m;
}

PrimitiveMoments CapsuleMoments(double r, double h) {
  PrimitiveMoments m;
  const double cylinder_volume = kPi * r * r * h;
  const double ball_volume = 4.0 / 3.0 * kPi * r * r * r;
  m.volume = cylinder_volume + ball_volume;
  // hemispheres centred at ±h/2: solid E[u] = 3r/8, E[u²] = r²/5; shell E[u] = r/2, E[u²] = r²/3
  const double solid_radial = cylinder_volume * r * r / 4.0 + ball_volume * r * r / 5.0;
  const double solid_axial = cylinder_volume * h * h / 12.0 +
                             ball_volume * (h * h / 4.0 + 3.0 * h * r / 8.0 + r * r / 5.0);
  const double side_area = 2.0 * kPi * r * h;
  const double ball_area = 4.0 * kPi * r * r;
  m.area = side_area + ball_area;
  const double shell_radial = side_area * r * r / 2.0 + ball_area * r * r / 3.0;
  const double shell_axial =
      side_area * h * h / 12.0 + ball_area * (h * h / 4.0 + h * r / 2.0 + r * r / 3.0);
  if (m.volume > 0.0) m.solid = Vec3(solid_radial, solid_radial, solid_axial) / m.volume;
  if (m.area > 0.0) m.shell = Vec3(shell_radial, shell_radial, shell_axial) / m.area;
  return m;
}

PrimitiveMoments MomentsOf(const Primitive& p) {
  switch (p.type) {
    case PrimitiveType::kSphere: {
      PrimitiveMoments m;
      m.volume = p.Volume();
      m.area = 4.0 * kPi * p.radius * p.radius;
      m.solid = Vec3::Constant(p.radius * p.radius / 5.0);
      m.shell = Vec3::Constant(p.radius * p.radius / 3.0);
      return m;
    }
    case PrimitiveType::kBox:
      return BoxMoments(p.size);
    case PrimitiveType::kCylinder:
      return CylinderMoments(p.radius, p.length);
    case PrimitiveType::kCapsule:
      return CapsuleMoments(p.radius, p.length);
    case PrimitiveType::kPlane:
      break;
  }
  return PrimitiveMoments();
}

// Mass properties of a primitive placed by the rigid map `placement` (pose included).
MassProperties PrimitiveMassProperties(const Primitive& primitive, const Pose& placement,
                                       double mass, double f) {
  const PrimitiveMoments m = MomentsOf(primitive);
  if ((f < 1.0 && !(m.volume > 0.0)) || (f > 0.0 && !(m.area > 0.0))) return MassProperties();
  const Vec3 diagonal = f * m.shell + (1.0 - f) * m.solid;
  const Mat3 rotation = placement.linear();
  const Mat3 second = rotation * diagonal.asDiagonal() * rotation.transpose();
  return FromDistribution(placement.translation(), Vec3::Zero(), second, mass);
}

// Unit masses at the points, relative to `reference`.
Moments PointMoments(const std::vector<Vec3>& points, const Vec3& reference) {
  Moments m;
  for (const Vec3& p : points) {
    m.measure += 1.0;
    m.first += p - reference;
    m.second += (p - reference) * (p - reference).transpose();
  }
  return m;
}

// Equal point masses (Klamp't's rule for point clouds: mean and covariance of the points).
// Invalid without points or when they lie on one line (no inertia about it).
MassProperties PointMassProperties(const std::vector<Vec3>& points, double mass) {
  Eigen::AlignedBox3d bounds;
  for (const Vec3& p : points) bounds.extend(p);
  if (points.empty()) return MassProperties();
  const Moments m = PointMoments(points, bounds.center());
  MassProperties out =
      FromDistribution(bounds.center(), m.first / m.measure, m.second / m.measure, 1.0);
  const double least = Eigen::SelfAdjointEigenSolver<Mat3>(out.inertia).eigenvalues().minCoeff();
  if (!(least > kDegenerateFraction * bounds.diagonal().squaredNorm())) return MassProperties();
  out.inertia *= mass;
  return out;
}

bool NearlyUniform(const Vec3& scale) {
  const double tolerance = 1e-12 * std::abs(scale.x());
  return std::abs(scale.y() - scale.x()) <= tolerance &&
         std::abs(scale.z() - scale.x()) <= tolerance;
}

// The primitive after `scale` of its file axes when it stays the same kind of primitive:
// any shape under a uniform positive scale, a box whose axes are file axes under any
// positive scale.
std::optional<Primitive> ScaledPrimitive(const Primitive& primitive, const Vec3& scale) {
  if ((scale.array() <= 0.0).any()) return std::nullopt;
  Primitive out = primitive;
  out.pose.translation() = scale.cwiseProduct(primitive.pose.translation());
  if (NearlyUniform(scale)) {
    out.radius *= scale.x();
    out.length *= scale.x();
    out.size *= scale.x();
    return out;
  }
  if (primitive.type != PrimitiveType::kBox) return std::nullopt;
  const Mat3& axes = primitive.pose.linear();
  for (int j = 0; j < 3; ++j) {
    int k = 0;
    axes.col(j).cwiseAbs().maxCoeff(&k);
    if ((axes.col(j).cwiseAbs().sum() - std::abs(axes(k, j))) > 1e-12) return std::nullopt;
    out.size[j] *= scale[k];
  }
  return out;
}

}  // namespace

MassProperties ComputeMassProperties(const TriangleMesh& mesh, double mass,
                                     double surface_fraction) {
  if (mesh.triangles.empty() || std::isnan(surface_fraction)) return MassProperties();
  const double f = std::clamp(surface_fraction, 0.0, 1.0);
  const Eigen::AlignedBox3d bounds = mesh.Bounds();
  const Vec3 reference = bounds.center();  // keeps the sums well conditioned off the origin
  const double extent = bounds.diagonal().norm();
  Vec3 mean = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  if (f < 1.0) {
    // dividing by the signed volume also handles inside-out meshes
    const Moments solid = SolidMoments(mesh, reference);
    if (!(std::abs(solid.measure) > kDegenerateFraction * extent * extent * extent)) {
      return MassProperties();
    }
    mean += (1.0 - f) / solid.measure * solid.first;
    second += (1.0 - f) / solid.measure * solid.second;
  }
  if (f > 0.0) {
    const Moments shell = ShellMoments(mesh, reference);
    if (!(shell.measure > kDegenerateFraction * extent * extent)) return MassProperties();
    mean += f / shell.measure * shell.first;
    second += f / shell.measure * shell.second;
  }
  return FromDistribution(reference, mean, second, mass);
}

MassProperties ComputeMassProperties(const GeometryDesc& geometry, double mass,
                                     double surface_fraction) {
  if (std::isnan(surface_fraction)) return MassProperties();
  const double f = std::clamp(surface_fraction, 0.0, 1.0);
  switch (geometry.kind) {
    case GeometryKind::kNone:
      return MassProperties();
    case GeometryKind::kMesh:
      return geometry.mesh ? ComputeMassProperties(BakedMesh(geometry), mass, f) : MassProperties();
    case GeometryKind::kPointCloud:
      return PointMassProperties(BakedPoints(geometry), mass);
    case GeometryKind::kPrimitive:
      break;
  }
  if (geometry.primitive.type == PrimitiveType::kPlane) return MassProperties();
  const std::optional<Primitive> scaled = ScaledPrimitive(geometry.primitive, geometry.scale);
  if (scaled && IsRotation(geometry.transform.linear())) {
    Pose transform = Pose::Identity();
    transform.linear() = geometry.transform.linear();
    transform.translation() = geometry.transform.translation();
    return PrimitiveMassProperties(*scaled, transform * scaled->pose, mass, f);
  }
  // the shape changes kind (e.g. a sphere becomes an ellipsoid): integrate a fine mesh
  TriangleMesh mesh = Tessellate(geometry.primitive, kMassSegments);
  const Affine matrix = geometry.Matrix();
  for (Vec3& v : mesh.vertices) v = matrix * v;
  return ComputeMassProperties(mesh, mass, f);
}

Mat3 ShiftInertia(const Mat3& inertia_at_com, double mass, const Vec3& d) {
  return inertia_at_com + mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

CompositeMass CombineMass(const std::vector<MassPart>& parts) {
  CompositeMass composite;
  Vec3 moment = Vec3::Zero();
  for (const MassPart& part : parts) {
    composite.mass += part.mass;
    moment += part.mass * (part.pose * part.com);
  }
  if (!(composite.mass > 0.0)) return composite;
  MassProperties& properties = composite.properties;
  properties.com = moment / composite.mass;
  for (const MassPart& part : parts) {
    const Mat3 R = part.pose.linear();
    properties.inertia += ShiftInertia(R * part.inertia * R.transpose(), part.mass,
                                       part.pose * part.com - properties.com);
  }
  properties.valid = true;
  return composite;
}

}  // namespace lamina::core
