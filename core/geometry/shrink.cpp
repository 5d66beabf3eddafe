// SPDX-License-Identifier: MIT
// Preshrinking of primitives (exact offsets) and meshes (Klamp't's ApproximateShrink).
#include "core/geometry/shrink.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/geometry/primitive.h"

namespace lamina::core {

namespace {

// Vertices closer than this (L-inf, mesh units) are one vertex when finding incident faces.
constexpr double kMergeTolerance = 1e-6;
// Beyond this coordinate (mesh units) the merging grid's integer cells would overflow.
constexpr double kMergeRange = 1e12;
// Unit normals closer than this (L-inf) are one face direction at a vertex.
constexpr double kSameNormalTolerance = 1e-6;
// A displacement longer than this many times the amount is an ill-conditioned corner (a thin
// wedge); Klamp't then falls back to the average normal.
constexpr double kMaxDisplacementFactor = 3.0;
// Above this many face directions at a vertex the C(n, 3) search of Klamp't gets expensive;
// such vertices (cone tips, fans) use one direction that moves every face at least `amount`.
constexpr int kMaxNormalsForTripleSearch = 48;
// A primitive dimension shrunk to nothing keeps this fraction of its original value.
constexpr double kClampedFraction = 1e-3;
// Relative tolerance for "orthogonal" and "equal length" columns of a placement.
constexpr double kShapeTolerance = 1e-9;

std::string ShortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

// ---------------------------------------------------------------------------------------------
// Meshes

using Cell = Eigen::Matrix<int64_t, 3, 1>;

struct CellHash {
  size_t operator()(const Cell& c) const {
    const uint64_t h = static_cast<uint64_t>(c.x()) * 73856093u ^
                       static_cast<uint64_t>(c.y()) * 19349663u ^
                       static_cast<uint64_t>(c.z()) * 83492791u;
    return static_cast<size_t>(h);
  }
};

using CellMap = std::unordered_map<Cell, std::vector<int>, CellHash>;

Cell CellOf(const Vec3& v) {
  return (v / kMergeTolerance).array().floor().cast<int64_t>();
}

// A vertex already filed in `cells` within kMergeTolerance of v, or -1. The cells are
// kMergeTolerance wide, so such a vertex lies in v's cell or one of its 26 neighbours.
int NearbyVertex(const std::vector<Vec3>& vertices, const CellMap& cells, const Vec3& v) {
  const Cell cell = CellOf(v);
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = cells.find(cell + Cell(dx, dy, dz));
        if (it == cells.end()) continue;
        for (int j : it->second) {
          if ((vertices[j] - v).lpNorm<Eigen::Infinity>() < kMergeTolerance) return j;
        }
      }
    }
  }
  return -1;
}

// For each vertex, the group (the index of its first vertex) of an earlier vertex within
// kMergeTolerance, or its own index: meshes read from OFF or OBJ files often repeat a vertex at
// texture or normal seams, and those copies must see each other's triangles, or the seam opens
// when they move differently.
std::vector<int> MergedVertexGroups(const std::vector<Vec3>& vertices) {
  CellMap cells;
  std::vector<int> group(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec3& v = vertices[i];
    group[i] = static_cast<int>(i);
    // far-out or non-finite vertices (no grid cell) are not merged
    if (!v.allFinite() || v.lpNorm<Eigen::Infinity>() > kMergeRange) continue;
    const int nearby = NearbyVertex(vertices, cells, v);
    if (nearby >= 0) group[i] = group[nearby];
    cells[CellOf(v)].push_back(static_cast<int>(i));
  }
  return group;
}

// Unnormalized normal (twice the area) of triangle t.
Vec3 AreaNormal(const std::vector<Vec3>& vertices, const Eigen::Vector3i& t) {
  return (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
}

// Unit normals; zero for degenerate triangles, which then constrain no vertex.
std::vector<Vec3> UnitNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals;
  normals.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 n = AreaNormal(mesh.vertices, t);
    const double length = n.norm();
    normals.push_back(length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3::Zero());
  }
  return normals;
}

// The distinct face directions around each merged vertex (indexed by group representative).
std::vector<std::vector<Vec3>> DistinctNormalsPerGroup(const TriangleMesh& mesh,
                                                       const std::vector<int>& group,
                                                       const std::vector<Vec3>& normals) {
  std::vector<std::vector<Vec3>> per_group(mesh.vertices.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (normals[t].isZero()) continue;
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const int g0 = group[tri[0]], g1 = group[tri[1]], g2 = group[tri[2]];
    // a triangle with two corners in one merged vertex has no area once merged
    if (g0 == g1 || g1 == g2 || g2 == g0) continue;
    for (int g : {g0, g1, g2}) {
      std::vector<Vec3>& list = per_group[g];
      const bool seen = std::any_of(list.begin(), list.end(), [&](const Vec3& n) {
        return (n - normals[t]).lpNorm<Eigen::Infinity>() < kSameNormalTolerance;
      });
      if (!seen) list.push_back(normals[t]);
    }
  }
  return per_group;
}

Vec3 AverageNormalDisplacement(const std::vector<Vec3>& normals, double amount) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& n : normals) sum += n;
  return amount * sum / static_cast<double>(normals.size());
}

// Minimum-norm x with n0.x = n1.x = amount: x = C^T (C C^T)^-1 b.
Vec3 TwoPlaneDisplacement(const Vec3& n0, const Vec3& n1, double amount) {
  const double c = n0.dot(n1);
  const double det = 1.0 - c * c;  // Gram determinant of two unit vectors
  if (det < 1e-12) return amount * n0;
  // (C C^T)^-1 (amount, amount) = amount / (1 + c) * (1, 1)
  const Vec3 x = amount / (1.0 + c) * (n0 + n1);
  if (x.norm() > kMaxDisplacementFactor * amount) return amount * 0.5 * (n0 + n1);
  return x;
}

// The x with n0.x = n1.x = n2.x = amount (Cramer's rule); false when the normals are
// (nearly) coplanar.
bool SolveThreePlanes(const Vec3& n0, const Vec3& n1, const Vec3& n2, double amount, Vec3* x) {
  const double det = n0.dot(n1.cross(n2));
  if (std::abs(det) < 1e-12) return false;
  *x = amount * (n1.cross(n2) + n2.cross(n0) + n0.cross(n1)) / det;
  return true;
}

// Klamp't: among all triples, the solution whose shallowest face (capped at amount) moves most.
// Unlike Klamp't, ties are averaged (every face still moves at least as far, the condition
// being linear in x), so a symmetric vertex such as the pole of a UV sphere moves along its axis
// instead of toward whichever triple comes first.
bool DeepestTripleDisplacement(const std::vector<Vec3>& normals, double amount, Vec3* best) {
  const int n = static_cast<int>(normals.size());
  const double tie = 1e-9 * amount;
  double best_depth = 0.0;
  Vec3 sum = Vec3::Zero();
  int ties = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        Vec3 x;
        if (!SolveThreePlanes(normals[i], normals[j], normals[k], amount, &x)) continue;
        double depth = amount;
        for (const Vec3& normal : normals) depth = std::min(depth, normal.dot(x));
        if (depth > best_depth + tie) {
          best_depth = depth;
          sum = x;
          ties = 1;
        } else if (ties > 0 && depth >= best_depth - tie) {
          sum += x;
          ++ties;
        }
      }
    }
  }
  if (ties == 0) return false;
  *best = sum / ties;
  return true;
}

// Along the average normal d, far enough that every face moves at least amount:
// amount / min_i(n_i . d). Exact for the tip of a regular cone.
bool ConeDisplacement(const std::vector<Vec3>& normals, double amount, Vec3* x) {
  Vec3 direction = Vec3::Zero();
  for (const Vec3& n : normals) direction += n;
  if (direction.norm() == 0.0) return false;
  direction.normalize();
  double lowest = 1.0;
  for (const Vec3& n : normals) lowest = std::min(lowest, n.dot(direction));
  if (lowest <= 0.0) return false;
  *x = amount / lowest * direction;
  return true;
}

// The inward displacement of a vertex whose incident faces have these distinct unit normals.
Vec3 InwardDisplacement(const std::vector<Vec3>& normals, double amount) {
  const double limit = kMaxDisplacementFactor * amount;
  switch (normals.size()) {
    case 0:
      return Vec3::Zero();
    case 1:
      return amount * normals[0];
    case 2:
      return TwoPlaneDisplacement(normals[0], normals[1], amount);
    case 3: {
      Vec3 x;
      if (SolveThreePlanes(normals[0], normals[1], normals[2], amount, &x) && x.norm() <= limit) {
        return x;
      }
      return AverageNormalDisplacement(normals, amount);
    }
    default: {
      Vec3 x;
      const bool found = static_cast<int>(normals.size()) <= kMaxNormalsForTripleSearch
                             ? DeepestTripleDisplacement(normals, amount, &x)
                             : ConeDisplacement(normals, amount, &x);
      if (found && x.norm() <= limit) return x;
      return AverageNormalDisplacement(normals, amount);
    }
  }
}

int CountFlippedTriangles(const TriangleMesh& shrunk, const std::vector<Vec3>& normals) {
  int flipped = 0;
  for (size_t t = 0; t < shrunk.triangles.size(); ++t) {
    if (AreaNormal(shrunk.vertices, shrunk.triangles[t]).dot(normals[t]) < 0.0) ++flipped;
  }
  return flipped;
}

// ---------------------------------------------------------------------------------------------
// Geometry

// Where and about what to report.
struct Reporter {
  Diagnostics* diagnostics;
  SourceLocation where;

  void Warn(const std::string& message) const {
    if (diagnostics) diagnostics->Warning(where, message);
  }
};

// `value` reduced by `reduction`, or a small positive remainder (with a warning) when nothing
// would be left.
double Reduced(double value, double reduction, const char* what, const Primitive& primitive,
               double amount, const Reporter& report) {
  const double result = value - reduction;
  if (result > 0.0) return result;
  const double clamped = value * kClampedFraction;
  report.Warn("preshrink by " + ShortNumber(amount) + " m leaves nothing of the " +
              primitive.TypeName() + "'s " + what + " (" + ShortNumber(value) + "); clamped to " +
              ShortNumber(clamped));
  return clamped;
}

// Columns of L (the primitive's axes in the body frame) mutually orthogonal.
bool OrthogonalColumns(const Mat3& L) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(L.col(i).dot(L.col(j))) > kShapeTolerance * L.col(i).norm() * L.col(j).norm()) {
      return false;
    }
  }
  return true;
}

bool SameLength(double a, double b) {
  return std::abs(a - b) <= kShapeTolerance * std::max(a, b);
}

// Shrinks `primitive` (whose own frame maps into the body frame by the linear part L) so that
// its body-frame surface moves inward by `amount`. False when the offset shape is not the
// same kind of primitive under L.
bool ShrinkPrimitive(const Mat3& L, double amount, const Reporter& report, Primitive* primitive) {
  // face i of a box (or the plane's boundary) moves amount * |L^-T e_i| in its own units
  // for each body-frame unit: the row norms of L^-1
  const Mat3 L_inverse = L.inverse();
  const Vec3 s = L.colwise().norm();
  const bool orthogonal = OrthogonalColumns(L);
  switch (primitive->type) {
    case PrimitiveType::kPlane: {
      const double shift = amount * L_inverse.row(2).norm();
      primitive->pose.translation() -= shift * primitive->pose.linear().col(2);
      return true;
    }
    case PrimitiveType::kBox: {
      static const char* const kAxes[] = {"x size", "y size", "z size"};
      for (int i = 0; i < 3; ++i) {
        primitive->size[i] = Reduced(primitive->size[i], 2.0 * amount * L_inverse.row(i).norm(),
                                     kAxes[i], *primitive, amount, report);
      }
      return true;
    }
    case PrimitiveType::kSphere:
    case PrimitiveType::kCapsule:
      // a capsule's surface offset inward is the capsule about the same segment
      if (!orthogonal || !SameLength(s.x(), s.y()) || !SameLength(s.x(), s.z())) return false;
      primitive->radius =
          Reduced(primitive->radius, amount / s.x(), "radius", *primitive, amount, report);
      return true;
    case PrimitiveType::kCylinder:
      if (!orthogonal || !SameLength(s.x(), s.y())) return false;
      primitive->radius =
          Reduced(primitive->radius, amount / s.x(), "radius", *primitive, amount, report);
      primitive->length =
          Reduced(primitive->length, 2.0 * amount / s.z(), "length", *primitive, amount, report);
      return true;
  }
  return false;
}

// `mesh` (outward in its own coordinates) shrunk, as the new mesh of `out`.
void SetShrunkMesh(TriangleMesh mesh, double amount, const Reporter& report, GeometryDesc* out) {
  ShrunkMesh shrunk = ApproximateShrink(mesh, amount);
  if (shrunk.flipped_triangles > 0) {
    report.Warn("preshrink by " + ShortNumber(amount) + " m turned " +
                std::to_string(shrunk.flipped_triangles) + " of " +
                std::to_string(mesh.triangle_count()) +
                " triangles inside out; the padding is large for this mesh's features");
  }
  out->kind = GeometryKind::kMesh;
  out->mesh = std::make_shared<const TriangleMesh>(std::move(shrunk.mesh));
  out->scale = Vec3::Ones();
}

GeometryDesc ShrinkMeshGeometry(const GeometryDesc& geometry, double amount,
                                const Reporter& report) {
  GeometryDesc out = geometry;
  if (!geometry.mesh) return out;
  // distances must be body distances where the mesh is shrunk: bake the scale, and the
  // transform too unless it is rigid (a .rob geomtransform may scale or shear)
  const Mat3 T = geometry.transform.linear();
  const bool rigid = (T.transpose() * T - Mat3::Identity()).norm() < kShapeTolerance;
  Affine bake = Affine::Identity();
  bake.linear() = geometry.scale.asDiagonal();
  if (!rigid) {
    bake = geometry.Matrix();
    out.transform = Affine::Identity();
  }
  TriangleMesh mesh = *geometry.mesh;
  for (Vec3& v : mesh.vertices) v = bake * v;
  if (bake.linear().determinant() < 0.0) {
    // a mirroring bake turns the winding inside out; keep it outward (BakedMesh does the same)
    for (Eigen::Vector3i& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  SetShrunkMesh(std::move(mesh), amount, report, &out);
  return out;
}

GeometryDesc ShrinkPrimitiveGeometry(const GeometryDesc& geometry, double amount,
                                     const Reporter& report) {
  GeometryDesc out = geometry;
  const Mat3 L = (geometry.Matrix() * geometry.primitive.pose).linear();
  if (!(std::abs(L.determinant()) > 0.0)) {
    report.Warn(std::string("cannot preshrink a ") + geometry.primitive.TypeName() +
                " with a singular scale or transform; left as is");
    return out;
  }
  if (ShrinkPrimitive(L, amount, report, &out.primitive)) return out;
  // not the same kind of shape once scaled (an ellipsoid, ...): the simulator collides it as
  // its tessellation, so shrink that
  report.Warn(std::string("preshrink of a non-uniformly scaled ") + geometry.primitive.TypeName() +
              " shrinks its tessellation; the shrunk geometry is a mesh");
  out.transform = Affine::Identity();
  out.primitive = Primitive();
  SetShrunkMesh(BakedMesh(geometry), amount, report, &out);
  return out;
}

}  // namespace

ShrunkMesh ApproximateShrink(const TriangleMesh& mesh, double amount) {
  ShrunkMesh out;
  out.mesh = mesh;
  const std::vector<int> group = MergedVertexGroups(mesh.vertices);
  const std::vector<Vec3> normals = UnitNormals(mesh);
  const std::vector<std::vector<Vec3>> group_normals =
      DistinctNormalsPerGroup(mesh, group, normals);
  std::vector<Vec3> displacement(mesh.vertices.size(), Vec3::Zero());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (group[i] == static_cast<int>(i)) {
      displacement[i] = InwardDisplacement(group_normals[i], amount);
    }
  }
  // every copy of a merged vertex moves as its group does
  for (size_t i = 0; i < mesh.vertices.size(); ++i) out.mesh.vertices[i] -= displacement[group[i]];
  out.flipped_triangles = CountFlippedTriangles(out.mesh, normals);
  return out;
}

GeometryDesc ShrinkGeometry(const GeometryDesc& geometry, double amount, Diagnostics* diagnostics,
                            const SourceLocation& where) {
  Reporter report{diagnostics, where};
  if (report.where.file.empty()) report.where.file = geometry.path;
  if (!std::isfinite(amount) || amount < 0.0) {
    report.Warn("cannot preshrink by " + ShortNumber(amount) + " m; geometry left as is");
    return geometry;
  }
  if (amount == 0.0) return geometry;
  switch (geometry.kind) {
    case GeometryKind::kNone:
      return geometry;
    case GeometryKind::kMesh:
      return ShrinkMeshGeometry(geometry, amount, report);
    case GeometryKind::kPrimitive:
      return ShrinkPrimitiveGeometry(geometry, amount, report);
    case GeometryKind::kPointCloud:
      // points have no surface to move in (Klamp't: unsupported, unchanged)
      report.Warn("cannot preshrink a point cloud (its points have no surface); left as is");
      return geometry;
  }
  return geometry;
}

}  // namespace lamina::core
