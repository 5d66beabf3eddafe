// SPDX-License-Identifier: MIT
// Box-box and box-plane contacts. Box-box tests the 15 separating axes (3 face normals of each
// box, 9 edge-edge cross products); the axis of largest separation decides the contact: for a
// face axis the other box's most anti-parallel face is clipped against the reference face
// (Sutherland-Hodgman), giving up to 8 points, each with its own depth, less those lying on the
// segment between two others; for an edge axis the two supporting edges give one point. Where the
// axes do not locate the nearest points (corners or edges meeting off each other's faces, or the
// incident box's lowest point overhanging the reference face) one more contact comes from the
// nearest point over all edges of both boxes.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/contact/primitive_pairs.h"

namespace lamina::core::primitive_detail {
namespace {

// |e_a x e_b| of unit edge directions below this: parallel edges, covered by the face axes.
constexpr double kParallelEdgeSine = 1e-6;
// An edge axis must separate the boxes by this much more than the best face axis to be used
// (m): they tie on face-on-face contact, where the face gives the multi-point contact.
constexpr double kEdgeAxisPreference = 1e-6;
// A quad clipped by 4 planes has at most 8 vertices; the spare room absorbs rounding.
constexpr int kMaxPolygonSize = 16;
// A clipped vertex this close to the segment between its neighbours, as a fraction of the
// polygon's diameter, is dropped. Nearly aligned faces (a settled stack) cross each other's edges
// near their middles, adding vertices that bend the outline by about the relative yaw: they add
// nothing to the support but make the LCP nearly degenerate and slower out of proportion. The
// fraction merges such crossings up to a yaw of about 5e-3 rad and moves the outline by at most
// 0.14 mm on a 0.1 m box, far less than the boundary layer blurs it; it merges coincident
// vertices too.
constexpr double kRedundantVertexFraction = 1e-3;

struct Polygon {
  std::array<Vec3, kMaxPolygonSize> vertices;
  int size = 0;

  void Push(const Vec3& vertex) {
    if (size < kMaxPolygonSize) vertices[size++] = vertex;
  }
};

/// The axes of largest separation, by family.
struct SeparatingAxes {
  double face_separation = -kInf;  ///< m
  int face = 0;                    ///< 0..2: axis of box a, 3..5: axis (face - 3) of box b
  double edge_separation = -kInf;  ///< m
  int edge_a = 0;                  ///< edge axis of box a
  int edge_b = 0;                  ///< edge axis of box b
  Vec3 edge_axis = Vec3::UnitZ();  ///< unit edge_a x edge_b
};

/// The boxes' relative placement in the frame of box a: the centre offset on each box's axes and
/// c(i, j) = a_i · b_j. The gaps along the 15 axes come from these (Gottschalk's OBB test) at a
/// sixth of the cost of projecting both boxes on each world axis.
struct RelativePlacement {
  Vec3 half_a, half_b;
  Vec3 offset_a, offset_b;  ///< (centre a − centre b) · a_i, · b_j
  Mat3 c, abs_c;

  RelativePlacement(const PlacedPrimitive& a, const PlacedPrimitive& b)
      : half_a(a.HalfSize()), half_b(b.HalfSize()) {
    const Vec3 offset = a.Center() - b.Center();
    offset_a = a.X_WS.linear().transpose() * offset;
    offset_b = b.X_WS.linear().transpose() * offset;
    c = a.X_WS.linear().transpose() * b.X_WS.linear();
    abs_c = c.cwiseAbs();
  }
  /// gap along face axis `face` (0..2: a's axes, 3..5: b's), negative where they overlap (m)
  double FaceGap(int face) const {
    if (face < 3) return std::abs(offset_a[face]) - half_a[face] - half_b.dot(abs_c.row(face));
    const int j = face - 3;
    return std::abs(offset_b[j]) - half_a.dot(abs_c.col(j)) - half_b[j];
  }
  /// gap along a_i × b_j times its length `sine` (a_i × b_j = c(i1,j) a_i2 − c(i2,j) a_i1 for
  /// the next axes i1, i2 of a; the signs of a's handedness fall under the absolute values)
  double EdgeGapTimesSine(int i, int j) const {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const double distance = c(i1, j) * offset_a[i2] - c(i2, j) * offset_a[i1];
    const double reach_a = half_a[i1] * abs_c(i2, j) + half_a[i2] * abs_c(i1, j);
    const double reach_b = half_b[j1] * abs_c(i, j2) + half_b[j2] * abs_c(i, j1);
    return std::abs(distance) - reach_a - reach_b;
  }
};

/// Fills `axes`; false as soon as an axis separates the boxes by `tolerance` or more (then the
/// boxes are at least that far apart).
bool FindAxes(const PlacedPrimitive& a, const PlacedPrimitive& b, double tolerance,
              SeparatingAxes* axes) {
  const RelativePlacement placement(a, b);
  for (int face = 0; face < 6; ++face) {
    const double separation = placement.FaceGap(face);
    if (separation >= tolerance) return false;
    if (separation > axes->face_separation) {
      axes->face_separation = separation;
      axes->face = face;
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 cross = a.Axis(i).cross(b.Axis(j));
      const double sine = cross.norm();
      if (sine < kParallelEdgeSine) continue;
      const double separation = placement.EdgeGapTimesSine(i, j) / sine;
      if (separation >= tolerance) return false;
      if (separation > axes->edge_separation) {
        *axes = SeparatingAxes{axes->face_separation, axes->face, separation, i, j, cross / sine};
      }
    }
  }
  return true;
}

/// Keeps the part of the convex `polygon` where normal . p <= offset.
void ClipPolygon(const Vec3& normal, double offset, Polygon* polygon) {
  Polygon clipped;
  for (int i = 0; i < polygon->size; ++i) {
    const Vec3& current = polygon->vertices[i];
    const Vec3& next = polygon->vertices[(i + 1) % polygon->size];
    const double current_excess = normal.dot(current) - offset;
    const double next_excess = normal.dot(next) - offset;
    if (current_excess <= 0.0) clipped.Push(current);
    if ((current_excess <= 0.0) != (next_excess <= 0.0)) {
      clipped.Push(current + current_excess / (current_excess - next_excess) * (next - current));
    }
  }
  *polygon = clipped;
}

/// The face of `box` whose outward normal is most opposed to `direction`, as a quad.
Polygon IncidentFace(const PlacedPrimitive& box, const Vec3& direction) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(box.Axis(k).dot(direction)) > std::abs(box.Axis(axis).dot(direction))) axis = k;
  }
  const Vec3 half = box.HalfSize();
  const Vec3 centre =
      box.Center() - SignOf(box.Axis(axis).dot(direction)) * half[axis] * box.Axis(axis);
  const Vec3 u = half[(axis + 1) % 3] * box.Axis((axis + 1) % 3);
  const Vec3 v = half[(axis + 2) % 3] * box.Axis((axis + 2) % 3);
  Polygon face;
  for (const Vec3& corner :
       {Vec3(centre + u + v), Vec3(centre - u + v), Vec3(centre - u - v), Vec3(centre + u - v)}) {
    face.Push(corner);
  }
  return face;
}

/// The clipped incident face within the boundary layer: its vertices in order with their heights
/// over the reference face.
struct SupportPolygon {
  std::array<Vec3, kMaxPolygonSize> points;
  std::array<double, kMaxPolygonSize> heights;
  int size = 0;

  void Push(const Vec3& point, double height) {
    points[size] = point;
    heights[size] = height;
    ++size;
  }
  void Erase(int index) {
    for (int i = index; i + 1 < size; ++i) {
      points[i] = points[i + 1];
      heights[i] = heights[i + 1];
    }
    --size;
  }
};

/// Largest distance between two vertices of `polygon` (m).
double Diameter(const SupportPolygon& polygon) {
  double diameter = 0.0;
  for (int i = 0; i < polygon.size; ++i) {
    for (int j = i + 1; j < polygon.size; ++j) {
      diameter = std::max(diameter, (polygon.points[i] - polygon.points[j]).norm());
    }
  }
  return diameter;
}

/// Whether vertex `index` lies within `tolerance` of the segment between its neighbours (of the
/// other vertex, for two), measured along the reference face (unit `normal`).
bool LiesBetweenNeighbours(const SupportPolygon& polygon, int index, const Vec3& normal,
                           double tolerance) {
  const auto along_face = [&normal](const Vec3& v) { return Vec3(v - normal.dot(v) * normal); };
  const Vec3& previous = polygon.points[(index + polygon.size - 1) % polygon.size];
  const Vec3& next = polygon.points[(index + 1) % polygon.size];
  const Vec3 chord = along_face(next - previous);
  const Vec3 offset = along_face(polygon.points[index] - previous);
  const double chord_squared = chord.squaredNorm();
  const double t =
      chord_squared > 0.0 ? std::clamp(offset.dot(chord) / chord_squared, 0.0, 1.0) : 0.0;
  return (offset - t * chord).norm() <= tolerance;
}

/// Whether dropping vertex `index` keeps the deepest contact: it is not level with the least
/// height `lowest` (m), or another vertex is.
bool KeepsTheDeepest(const SupportPolygon& polygon, int index, double lowest) {
  const double level = lowest + kLevelTolerance;
  if (polygon.heights[index] > level) return true;
  for (int i = 0; i < polygon.size; ++i) {
    if (i != index && polygon.heights[i] <= level) return true;
  }
  return false;
}

/// Drops the vertices lying on the segment between their neighbours, earliest first, until no
/// such vertex is left. The outline is convex, so every drop only shaves a sliver off it.
void DropRedundantVertices(const Vec3& normal, SupportPolygon* polygon) {
  const double tolerance = kRedundantVertexFraction * Diameter(*polygon);
  const double lowest =
      *std::min_element(polygon->heights.begin(), polygon->heights.begin() + polygon->size);
  int index = 0;
  while (polygon->size > 1 && index < polygon->size) {
    if (LiesBetweenNeighbours(*polygon, index, normal, tolerance) &&
        KeepsTheDeepest(*polygon, index, lowest)) {
      polygon->Erase(index);
      index = 0;  // the neighbours of earlier vertices may have changed
    } else {
      ++index;
    }
  }
}

/// Clips the incident face of `incident` against the face of `reference` on its local `axis`
/// that faces it and adds a contact per clipped vertex within the boundary layer, but for those
/// on the segment between two others. Returns the lowest height of a clipped vertex over the
/// reference face (infinite when none is left).
double FaceContacts(const PlacedPrimitive& reference, int axis, const PlacedPrimitive& incident,
                    bool reference_is_a, ContactSink* sink) {
  const Vec3 half = reference.HalfSize();
  const Vec3 normal = SignOf(reference.Axis(axis).dot(incident.Center() - reference.Center())) *
                      reference.Axis(axis);
  const Vec3 face_centre = reference.Center() + half[axis] * normal;
  Polygon polygon = IncidentFace(incident, normal);
  // the four side planes of the reference face
  for (int k = 1; k <= 2; ++k) {
    const Vec3 tangent = reference.Axis((axis + k) % 3);
    const double centre_offset = tangent.dot(reference.Center());
    ClipPolygon(tangent, centre_offset + half[(axis + k) % 3], &polygon);
    ClipPolygon(-tangent, -centre_offset + half[(axis + k) % 3], &polygon);
  }
  double lowest = kInf;
  SupportPolygon support;
  for (int i = 0; i < polygon.size; ++i) {
    const double height = normal.dot(polygon.vertices[i] - face_centre);
    lowest = std::min(lowest, height);
    // the sink's own test, written so that a NaN height is left out
    if (height < sink->tolerance()) support.Push(polygon.vertices[i], height);
  }
  if (support.size == 0) return lowest;
  DropRedundantVertices(normal, &support);
  for (int i = 0; i < support.size; ++i) {
    const Vec3& point = support.points[i];
    const Vec3 on_face = point - support.heights[i] * normal;
    if (reference_is_a) {
      sink->Add(on_face, point, -normal, support.heights[i]);
    } else {
      sink->Add(point, on_face, normal, support.heights[i]);
    }
  }
  return lowest;
}

/// One contact between the supporting edges of the edge axis; false when their closest points
/// fall outside either edge (the axis then does not describe the contact).
bool EdgeContact(const PlacedPrimitive& a, const PlacedPrimitive& b, const SeparatingAxes& axes,
                 ContactSink* sink) {
  const Vec3 normal = SignOf(axes.edge_axis.dot(a.Center() - b.Center())) * axes.edge_axis;
  const Vec3 half_a = a.HalfSize();
  const Vec3 half_b = b.HalfSize();
  // the edge of a facing b and the edge of b facing a, each through its midpoint
  Vec3 mid_a = a.Center();
  Vec3 mid_b = b.Center();
  for (int k = 0; k < 3; ++k) {
    if (k != axes.edge_a) mid_a -= SignOf(normal.dot(a.Axis(k))) * half_a[k] * a.Axis(k);
    if (k != axes.edge_b) mid_b += SignOf(normal.dot(b.Axis(k))) * half_b[k] * b.Axis(k);
  }
  // closest points of the two edge lines
  const Vec3 direction_a = a.Axis(axes.edge_a);
  const Vec3 direction_b = b.Axis(axes.edge_b);
  const Vec3 offset = mid_a - mid_b;
  const double cosine = direction_a.dot(direction_b);
  const double along_a = direction_a.dot(offset);
  const double along_b = direction_b.dot(offset);
  const double denominator = 1.0 - cosine * cosine;
  const double s = (cosine * along_b - along_a) / denominator;
  const double u = (along_b - cosine * along_a) / denominator;
  if (std::abs(s) > half_a[axes.edge_a] || std::abs(u) > half_b[axes.edge_b]) return false;
  const Vec3 p_a = mid_a + s * direction_a;
  const Vec3 p_b = mid_b + u * direction_b;
  sink->Add(p_a, p_b, normal, normal.dot(p_a - p_b));
  return true;
}

/// A lower bound (m) on the signed distance from segment p0 p1 to `box` (distance is negative
/// inside): along each box axis no point of the segment is nearer the slab than the segment's
/// least |coordinate|, and a point's signed distance is at least its largest excess over the
/// half sizes (outside: the Euclidean distance is at least any one axis's; inside: the nearest
/// face's excess).
double SegmentBoxLowerBound(const Vec3& p0_W, const Vec3& p1_W, const PlacedPrimitive& box) {
  const Vec3 p0 = box.ToLocal(p0_W);
  const Vec3 p1 = box.ToLocal(p1_W);
  const Vec3 half = box.HalfSize();
  double bound = -kInf;
  for (int k = 0; k < 3; ++k) {
    const double least = p0[k] * p1[k] <= 0.0 ? 0.0 : std::min(std::abs(p0[k]), std::abs(p1[k]));
    bound = std::max(bound, least - half[k]);
  }
  return bound;
}

/// An edge of one box against the other (the solid): which box carries it, its index, its ends
/// and a lower bound on its distance to the solid.
struct EdgeCandidate {
  bool on_a = true;
  int edge = 0;
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  double bound = 0.0;  ///< m
};

/// The 24 edges of both boxes in the order a's 0..11, b's 0..11, each with its bound.
std::array<EdgeCandidate, 24> EdgeCandidates(const PlacedPrimitive& a, const PlacedPrimitive& b) {
  std::array<EdgeCandidate, 24> candidates;
  for (int i = 0; i < 24; ++i) {
    EdgeCandidate& candidate = candidates[i];
    candidate.on_a = i < 12;
    candidate.edge = i % 12;
    (candidate.on_a ? a : b).BoxEdge(candidate.edge, &candidate.start, &candidate.end);
    candidate.bound = SegmentBoxLowerBound(candidate.start, candidate.end, candidate.on_a ? b : a);
  }
  return candidates;
}

/// One contact at the nearest point of any edge of either box to the other box, if nearer than
/// `below` (m). The edges are searched in the order of their lower bounds and an edge whose bound
/// exceeds the best distance found (or `below`) by more than rounding is left out: it cannot be
/// nearer. Ties go to the earlier edge (a's before b's), as a search over all edges in order.
void NearestEdgeContact(const PlacedPrimitive& a, const PlacedPrimitive& b, double below,
                        ContactSink* sink) {
  // far above the rounding of a bound or a distance at robot scales, far below any layer
  constexpr double kBoundSlack = 1e-9;
  std::array<EdgeCandidate, 24> candidates = EdgeCandidates(a, b);
  std::array<int, 24> order;
  for (int i = 0; i < 24; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&candidates](int i, int j) { return candidates[i].bound < candidates[j].bound; });
  SegmentNearest best;
  best.closest.distance = kInf;
  int best_index = -1;
  for (const int i : order) {
    const EdgeCandidate& candidate = candidates[i];
    if (candidate.bound - kBoundSlack > std::min(best.closest.distance, below)) break;
    const SegmentNearest nearest =
        NearestOnSegment(candidate.start, candidate.end, candidate.on_a ? b : a);
    if (nearest.closest.distance < best.closest.distance ||
        (nearest.closest.distance == best.closest.distance && i < best_index)) {
      best = nearest;
      best_index = i;
    }
  }
  if (best_index < 0 || !(best.closest.distance < below)) return;
  const EdgeCandidate& edge = candidates[best_index];
  const PlacedPrimitive& edge_box = edge.on_a ? a : b;
  const PlacedPrimitive& solid = edge.on_a ? b : a;
  sink->AddBall(edge.on_a, best.point, 0.0,
                QueryPoint(solid, best.point, EdgeOutward(edge_box, edge.edge, best.point)));
}

}  // namespace

void BoxBoxContacts(const PlacedPrimitive& box_a, const PlacedPrimitive& box_b, ContactSink* sink) {
  SeparatingAxes axes;
  if (!FindAxes(box_a, box_b, sink->tolerance(), &axes)) return;
  if (axes.edge_separation > axes.face_separation + kEdgeAxisPreference) {
    if (!EdgeContact(box_a, box_b, axes, sink)) NearestEdgeContact(box_a, box_b, kInf, sink);
    return;
  }
  const bool reference_is_a = axes.face < 3;
  const PlacedPrimitive& reference = reference_is_a ? box_a : box_b;
  const PlacedPrimitive& incident = reference_is_a ? box_b : box_a;
  const double lowest = FaceContacts(reference, axes.face % 3, incident, reference_is_a, sink);
  // the incident box's lowest corner (at the separation) overhangs the reference face: the
  // nearest points lie on edges outside the clipped face
  if (lowest > axes.face_separation + kLevelTolerance) {
    NearestEdgeContact(box_a, box_b, lowest - kLevelTolerance, sink);
  }
}

void BoxPlaneContacts(const PlacedPrimitive& box, const PlacedPrimitive& plane, ContactSink* sink) {
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 point = box.BoxCorner(corner);
    sink->AddBall(true, point, 0.0, QueryPoint(plane, point));
  }
}

}  // namespace lamina::core::primitive_detail
