// SPDX-License-Identifier: MIT
#include "core/contact/triangle_queries.h"

#include <algorithm>
#include <cmath>

namespace lamina::core::mesh_detail {

namespace {

// closest point of segment ab to p, as the weight of b
double SegmentParameter(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  return length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
}

// the best of the three edges, for triangles without area
TrianglePoint ClosestOnEdges(const Vec3& p, const Triangle3& t) {
  TrianglePoint best;
  double best_distance = kInf;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double s = SegmentParameter(p, t[i], t[j]);
    const Vec3 q = t[i] + s * (t[j] - t[i]);
    const double distance = (q - p).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best.point = q;
      best.barycentric = Vec3::Zero();
      best.barycentric[i] = 1.0 - s;
      best.barycentric[j] = s;
    }
  }
  return best;
}

// Closest points of segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection 5.1.9).
void ClosestSegmentPoints(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3* p,
                          Vec3* q) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0) {
    t = e > 0.0 ? std::clamp(f / e, 0.0, 1.0) : 0.0;
  } else if (e <= 0.0) {
    s = std::clamp(-d1.dot(r) / a, 0.0, 1.0);
  } else {
    const double b = d1.dot(d2), c = d1.dot(r), denominator = a * e - b * b;
    s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1.0) {
      t = 1.0;
      s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  *p = p0 + s * d1;
  *q = q0 + t * d2;
}

TrianglePoint Make(const Triangle3& t, double u, double v, double w) {
  return {u * t[0] + v * t[1] + w * t[2], Vec3(u, v, w)};
}

// One side of a triangle's crossing with a plane: its points on the plane (signed distances
// `d`, exactly one sign change), ordered along `line`.
void PlaneCrossing(const Triangle3& t, const Vec3& d, const Vec3& line, Vec3* low, Vec3* high) {
  Vec3 points[3];
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] == 0.0) points[count++] = t[i];
    if (d[i] * d[j] < 0.0) points[count++] = t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j]));
  }
  *low = points[0];
  *high = points[count - 1];
  if (line.dot(*low) > line.dot(*high)) std::swap(*low, *high);
}

// Signed distances of t's corners from the plane (unit `normal` through `origin`), snapped to
// zero within `epsilon`. True when some corners lie strictly on each side.
bool Straddles(const Triangle3& t, const Vec3& normal, const Vec3& origin, double epsilon,
               Vec3* d) {
  for (int i = 0; i < 3; ++i) {
    const double s = normal.dot(t[i] - origin);
    (*d)[i] = std::abs(s) <= epsilon ? 0.0 : s;
  }
  return d->maxCoeff() > 0.0 && d->minCoeff() < 0.0;
}

double LongestEdge(const Triangle3& t) {
  return std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
}

// nearest surface point of a box (shape frame) to q
SurfacePoint BoxSurfacePoint(const Vec3& half, const Vec3& q) {
  const Vec3 clamped = q.cwiseMax(-half).cwiseMin(half);
  if (clamped != q) {  // outside
    const Vec3 out = q - clamped;
    return {out.norm(), clamped, out.normalized()};
  }
  int axis = 0;
  const Vec3 depth = half - q.cwiseAbs();
  depth.minCoeff(&axis);
  const double side = q[axis] >= 0.0 ? 1.0 : -1.0;
  SurfacePoint s{-depth[axis], q, Vec3::Unit(axis) * side};
  s.point[axis] = side * half[axis];
  return s;
}

// nearest surface point of a cylinder about z (shape frame) to q
SurfacePoint CylinderSurfacePoint(double radius, double half_length, const Vec3& q) {
  const double across = std::hypot(q.x(), q.y());
  const Vec3 radial = across > 0.0 ? Vec3(q.x() / across, q.y() / across, 0.0) : Vec3::UnitX();
  const double side = q.z() >= 0.0 ? 1.0 : -1.0;
  const double beyond_cap = std::abs(q.z()) - half_length, beyond_side = across - radius;
  if (beyond_cap > 0.0 || beyond_side > 0.0) {  // outside
    Vec3 point = std::min(across, radius) * radial;
    point.z() = std::clamp(q.z(), -half_length, half_length);
    const Vec3 out = q - point;
    return {out.norm(), point, out.normalized()};
  }
  if (beyond_cap >= beyond_side) {
    return {beyond_cap, Vec3(q.x(), q.y(), side * half_length), Vec3(0, 0, side)};
  }
  return {beyond_side, Vec3(radius * radial.x(), radius * radial.y(), q.z()), radial};
}

// ---- GJK on the Minkowski difference triangle - shape ----

struct SimplexVertex {
  Vec3 w;         // triangle corner minus shape point
  Vec3 on_shape;  // the shape point
  int corner;     // the triangle corner
};

struct Simplex {
  SimplexVertex vertices[4];
  double weights[4];
  int size = 0;
};

SimplexVertex SupportVertex(const Triangle3& t, const SupportShape& shape, const Vec3& d) {
  int corner = 0;
  for (int k = 1; k < 3; ++k) {
    if (d.dot(t[k]) > d.dot(t[corner])) corner = k;
  }
  const Vec3 s = shape.Support(-d);
  return {t[corner] - s, s, corner};
}

// Keeps the vertices of `chosen` (indices into `simplex`) with positive weight.
void Keep(const int* chosen, const double* weights, int count, Simplex* simplex) {
  Simplex reduced;
  for (int i = 0; i < count; ++i) {
    if (weights[i] <= 0.0) continue;
    reduced.vertices[reduced.size] = simplex->vertices[chosen[i]];
    reduced.weights[reduced.size++] = weights[i];
  }
  *simplex = reduced;
}

// Closest point to the origin of the face (i, j, k) of the simplex: its weights in `weights`.
double FaceClosest(const Simplex& s, const int* face, double* weights) {
  const Triangle3 t = {s.vertices[face[0]].w, s.vertices[face[1]].w, s.vertices[face[2]].w};
  const TrianglePoint p = ClosestPointOnTriangle(Vec3::Zero(), t);
  for (int i = 0; i < 3; ++i) weights[i] = p.barycentric[i];
  return p.point.squaredNorm();
}

// Replaces the simplex by the smallest sub-simplex holding its point closest to the origin.
// False when the origin is inside a full tetrahedron (the shapes intersect).
bool ReduceSimplex(Simplex* s) {
  static constexpr int kSegment[2] = {0, 1};
  static constexpr int kTriangle[3] = {0, 1, 2};
  if (s->size == 2) {
    const double t = SegmentParameter(Vec3::Zero(), s->vertices[0].w, s->vertices[1].w);
    const double weights[2] = {1.0 - t, t};
    Keep(kSegment, weights, 2, s);
  } else if (s->size == 3) {
    double weights[3];
    FaceClosest(*s, kTriangle, weights);
    Keep(kTriangle, weights, 3, s);
  } else if (s->size == 4) {
    static constexpr int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    double best = kInf, best_weights[3] = {1.0, 0.0, 0.0};
    int best_face = -1;
    for (int f = 0; f < 4; ++f) {
      const Vec3& p0 = s->vertices[kFaces[f][0]].w;
      const Vec3 n = (s->vertices[kFaces[f][1]].w - p0).cross(s->vertices[kFaces[f][2]].w - p0);
      const double opposite = n.dot(s->vertices[kFaces[f][3]].w - p0);
      // the origin is outside this face, or the tetrahedron is flat
      if (-n.dot(p0) * opposite >= 0.0 && opposite != 0.0) continue;
      double weights[3];
      const double distance = FaceClosest(*s, kFaces[f], weights);
      if (distance < best) {
        best = distance;
        best_face = f;
        std::copy(weights, weights + 3, best_weights);
      }
    }
    if (best_face < 0) return false;
    Keep(kFaces[best_face], best_weights, 3, s);
  }
  return true;
}

Vec3 ClosestVector(const Simplex& s) {
  Vec3 v = Vec3::Zero();
  for (int i = 0; i < s.size; ++i) v += s.weights[i] * s.vertices[i].w;
  return v;
}

bool Contains(const Simplex& s, const SimplexVertex& vertex) {
  for (int i = 0; i < s.size; ++i) {
    if (s.vertices[i].w == vertex.w) return true;
  }
  return false;
}

TriangleShapeDistanceResult Witnesses(const Triangle3& t, const Simplex& s) {
  TriangleShapeDistanceResult result;
  result.on_triangle.barycentric = Vec3::Zero();
  for (int i = 0; i < s.size; ++i) {
    result.on_triangle.barycentric[s.vertices[i].corner] += s.weights[i];
    result.on_shape += s.weights[i] * s.vertices[i].on_shape;
  }
  const Vec3& b = result.on_triangle.barycentric;
  result.on_triangle.point = b[0] * t[0] + b[1] * t[1] + b[2] * t[2];
  result.distance = (result.on_triangle.point - result.on_shape).norm();
  return result;
}

}  // namespace

TrianglePoint ClosestPointOnTriangle(const Vec3& p, const Triangle3& t) {
  // Voronoi regions of the corners, then the edges, then the face
  const Vec3 ab = t[1] - t[0], ac = t[2] - t[0], ap = p - t[0];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return Make(t, 1, 0, 0);
  const Vec3 bp = p - t[1];
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return Make(t, 0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) {
    const double v = d1 / (d1 - d3);
    return Make(t, 1 - v, v, 0);
  }
  const Vec3 cp = p - t[2];
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return Make(t, 0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) {
    const double w = d2 / (d2 - d6);
    return Make(t, 1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return Make(t, 0, 1 - w, w);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return ClosestOnEdges(p, t);
  const double v = vb / sum, w = vc / sum;
  return Make(t, 1 - v - w, v, w);
}

Vec3 BarycentricCoordinates(const Vec3& p, const Triangle3& t) {
  return BarycentricMap(t)(p);
}

BarycentricMap::BarycentricMap(const Triangle3& t)
    : origin_(t[0]), e0_(t[1] - t[0]), e1_(t[2] - t[0]) {
  d00_ = e0_.dot(e0_);
  d01_ = e0_.dot(e1_);
  d11_ = e1_.dot(e1_);
  denominator_ = d00_ * d11_ - d01_ * d01_;
  degenerate_ = !(denominator_ > 1e-24 * d00_ * d11_);
}

Vec3 BarycentricMap::operator()(const Vec3& p) const {
  if (degenerate_) return Vec3(1.0, 0.0, 0.0);
  const Vec3 q = p - origin_;
  const double d20 = q.dot(e0_), d21 = q.dot(e1_);
  const double v = (d11_ * d20 - d01_ * d21) / denominator_;
  const double w = (d00_ * d21 - d01_ * d20) / denominator_;
  return Vec3(1.0 - v - w, v, w);
}

TrianglePairPoints ClosestPointsOfTriangles(const Triangle3& a, const Triangle3& b) {
  TrianglePairPoints best;
  best.distance = kInf;
  const auto consider = [&best](const Vec3& on_a, const Vec3& on_b) {
    const double distance = (on_a - on_b).norm();
    if (distance < best.distance) best = {distance, on_a, on_b};
  };
  for (int i = 0; i < 3; ++i) {
    consider(a[i], ClosestPointOnTriangle(a[i], b).point);
    consider(ClosestPointOnTriangle(b[i], a).point, b[i]);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Vec3 p, q;
      ClosestSegmentPoints(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], &p, &q);
      consider(p, q);
    }
  }
  return best;
}

bool TrianglesCross(const Triangle3& a, const Triangle3& b, Vec3* midpoint) {
  const Vec3 na = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
  const Vec3 nb = (b[1] - b[0]).cross(b[2] - b[0]).normalized();
  const Vec3 line = na.cross(nb);
  if (!(line.squaredNorm() > 1e-24)) return false;  // parallel or degenerate
  const double epsilon = 1e-12 * std::max(LongestEdge(a), LongestEdge(b));
  Vec3 da, db;
  if (!Straddles(a, nb, b[0], epsilon, &da) || !Straddles(b, na, a[0], epsilon, &db)) {
    return false;
  }
  Vec3 a_low, a_high, b_low, b_high;
  PlaneCrossing(a, da, line, &a_low, &a_high);
  PlaneCrossing(b, db, line, &b_low, &b_high);
  const Vec3& low = line.dot(a_low) > line.dot(b_low) ? a_low : b_low;
  const Vec3& high = line.dot(a_high) < line.dot(b_high) ? a_high : b_high;
  if (line.dot(high - low) <= epsilon * line.norm()) return false;
  *midpoint = 0.5 * (low + high);
  return true;
}

Vec3 SupportShape::Support(const Vec3& direction) const {
  const Vec3 d = pose.linear().transpose() * direction;
  Vec3 local = Vec3::Zero();
  switch (type) {
    case Type::kBox:
      for (int i = 0; i < 3; ++i) local[i] = d[i] >= 0.0 ? half_extents[i] : -half_extents[i];
      break;
    case Type::kSegment:
      local.z() = d.z() >= 0.0 ? half_length : -half_length;
      break;
    case Type::kCylinder: {
      const double across = std::hypot(d.x(), d.y());
      if (across > 0.0) local.head<2>() = radius / across * d.head<2>();
      local.z() = d.z() >= 0.0 ? half_length : -half_length;
      break;
    }
  }
  return pose * local;
}

SurfacePoint ClosestSurfacePoint(const SupportShape& shape, const Vec3& p) {
  const Vec3 q = shape.pose.inverse() * p;
  SurfacePoint s;
  switch (shape.type) {
    case SupportShape::Type::kBox:
      s = BoxSurfacePoint(shape.half_extents, q);
      break;
    case SupportShape::Type::kCylinder:
      s = CylinderSurfacePoint(shape.radius, shape.half_length, q);
      break;
    case SupportShape::Type::kSegment: {
      const double z = std::clamp(q.z(), -shape.half_length, shape.half_length);
      const Vec3 out = q - Vec3(0, 0, z);
      s = {out.norm(), Vec3(0, 0, z), out.normalized()};
      break;
    }
  }
  s.point = shape.pose * s.point;
  s.normal = shape.pose.linear() * s.normal;
  return s;
}

TriangleShapeDistanceResult TriangleShapeDistance(const Triangle3& triangle,
                                                  const SupportShape& shape) {
  constexpr int kMaxIterations = 64;
  constexpr double kRelativeTolerance = 1e-12;
  const double scale = std::max(
      {LongestEdge(triangle), shape.half_extents.norm(), shape.radius + shape.half_length});
  const double tiny2 = 1e-24 * scale * scale;
  Vec3 v = triangle[0] - shape.pose.translation();
  if (v.squaredNorm() <= tiny2) v = Vec3::UnitX();
  Simplex simplex;
  simplex.vertices[0] = SupportVertex(triangle, shape, -v);
  simplex.weights[0] = 1.0;
  simplex.size = 1;
  v = simplex.vertices[0].w;
  TriangleShapeDistanceResult intersecting;
  intersecting.intersecting = true;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double vv = v.squaredNorm();
    if (vv <= tiny2) return intersecting;
    const SimplexVertex w = SupportVertex(triangle, shape, -v);
    if (vv - v.dot(w.w) <= kRelativeTolerance * vv || Contains(simplex, w)) break;
    const Simplex previous = simplex;
    simplex.vertices[simplex.size++] = w;
    if (!ReduceSimplex(&simplex)) return intersecting;
    const Vec3 next = ClosestVector(simplex);
    if (next.squaredNorm() >= vv) {  // no progress left in floating point
      simplex = previous;
      break;
    }
    v = next;
  }
  return Witnesses(triangle, simplex);
}

}  // namespace lamina::core::mesh_detail
