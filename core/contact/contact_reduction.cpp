// SPDX-License-Identifier: MIT
// Flat contact patches reduced to the corners of their outline (contact_reduction.h).
#include "core/contact/contact_reduction.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace lamina::core {
namespace {

using Vec2 = Eigen::Vector2d;

// twice the signed area of (a, b, c): positive when counter-clockwise
double Cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// The patch in the plane of the first contact's normal, or false when it is not one flat patch.
struct PlanarPatch {
  std::vector<Vec2> points;  ///< each contact's position in the plane's axes
  double extent = 0.0;       ///< the diagonal of the points' bounding box (m)
};

// One normal for all, and finite positions: checked before anything is built (a curved patch,
// the common case, leaves here).
bool OneNormal(const ContactList& contacts) {
  const Vec3& n = contacts[0].normal;
  if (!n.allFinite()) return false;
  const double same_normal = std::cos(kFlatPatchAngle);
  return std::all_of(contacts.begin(), contacts.end(), [&](const Contact& c) {
    return c.normal.dot(n) >= same_normal && c.position.allFinite();
  });
}

bool Flatten(const ContactList& contacts, PlanarPatch* patch) {
  if (!OneNormal(contacts)) return false;
  const Vec3& n = contacts[0].normal;
  const Vec3& origin = contacts[0].position;
  const Vec3 t1 = n.unitOrthogonal();
  const Vec3 t2 = n.cross(t1);
  Eigen::AlignedBox2d box;
  patch->points.clear();
  for (const Contact& c : contacts) {
    const Vec3 d = c.position - origin;
    patch->points.emplace_back(t1.dot(d), t2.dot(d));
    box.extend(patch->points.back());
  }
  patch->extent = box.diagonal().norm();
  const double off_plane = kFlatPatchRelative * patch->extent + kFlatPatchAbsolute;
  for (const Contact& c : contacts) {
    if (std::abs(n.dot(c.position - origin)) > off_plane) return false;
  }
  return patch->extent > 0.0;
}

// The indices of the outline's corners, counter-clockwise (Andrew's monotone chain); points on
// an edge and repeated points are left out. Fewer than 3 when the points are collinear.
std::vector<int> Outline(const std::vector<Vec2>& p, double extent) {
  std::vector<int> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&p](int a, int b) {
    return p[a].x() < p[b].x() || (p[a].x() == p[b].x() && (p[a].y() < p[b].y() || a < b));
  });
  const double collinear = 1e-9 * extent * extent;
  std::vector<int> hull(2 * p.size());
  std::size_t k = 0;
  const auto add = [&](int i, std::size_t floor) {
    while (k >= floor + 2 && Cross(p[hull[k - 2]], p[hull[k - 1]], p[i]) <= collinear) --k;
    hull[k++] = i;
  };
  for (const int i : order) add(i, 0);
  const std::size_t lower = k - 1;
  for (auto it = order.rbegin() + 1; it != order.rend(); ++it) add(*it, lower);
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

// Removes corners of the counter-clockwise outline, the one that cuts the least area first
// (Visvalingam), while more than kOutlineCorners remain and the area cut in all stays within
// kOutlineAreaLoss of the outline's: chamfered or rounded corners of a sole go, its four main
// corners stay.
void Simplify(const std::vector<Vec2>& p, std::vector<int>* corners) {
  if (corners->size() < 3) return;
  double area = 0.0;
  for (std::size_t i = 1; i + 1 < corners->size(); ++i) {
    area += 0.5 * Cross(p[(*corners)[0]], p[(*corners)[i]], p[(*corners)[i + 1]]);
  }
  double budget = kOutlineAreaLoss * area;
  while (corners->size() > static_cast<std::size_t>(kOutlineCorners)) {
    const std::size_t m = corners->size();
    std::size_t best = 0;
    double best_cut = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      const double cut =
          0.5 * Cross(p[(*corners)[(i + m - 1) % m]], p[(*corners)[i]], p[(*corners)[(i + 1) % m]]);
      if (i == 0 || cut < best_cut) {
        best_cut = cut;
        best = i;
      }
    }
    if (best_cut > budget) return;
    budget -= best_cut;
    corners->erase(corners->begin() + static_cast<std::ptrdiff_t>(best));
  }
}

// Wachspress coordinates of `x` in the convex counter-clockwise polygon `corners` of p, in the
// product form w_i = C_i Π_{j ∉ {i-1, i}} A_j (A_j: the area of x with edge j, C_i: the area of
// corner i with its neighbours), which stays finite on the boundary; areas scaled by extent².
std::vector<double> Wachspress(const std::vector<Vec2>& p, const std::vector<int>& corners,
                               const Vec2& x, double extent) {
  const std::size_t m = corners.size();
  const double scale = 1.0 / (extent * extent);
  std::vector<double> edge_area(m), corner_area(m), w(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2& a = p[corners[i]];
    const Vec2& b = p[corners[(i + 1) % m]];
    edge_area[i] = std::max(0.0, scale * Cross(x, a, b));
    corner_area[i] = scale * Cross(p[corners[(i + m - 1) % m]], a, b);
  }
  for (std::size_t i = 0; i < m; ++i) {
    double product = corner_area[i];
    for (std::size_t j = 0; j < m; ++j) {
      if (j != i && j != (i + m - 1) % m) product *= edge_area[j];
    }
    w[i] = product;
  }
  return w;
}

// Weights of the two ends of a line patch: x projected on the segment.
std::vector<double> SegmentWeights(const Vec2& a, const Vec2& b, const Vec2& x) {
  const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return {1.0 - t, t};
}

}  // namespace

bool ReduceFlatPatch(double floor, ContactList* contacts) {
  if (contacts->size() <= 4) return false;
  PlanarPatch patch;
  if (!Flatten(*contacts, &patch)) return false;
  std::vector<int> corners = Outline(patch.points, patch.extent);
  Simplify(patch.points, &corners);
  if (corners.size() < 2 || corners.size() >= contacts->size()) return false;
  double total = 0.0;
  Vec2 centre = Vec2::Zero();
  for (std::size_t i = 0; i < contacts->size(); ++i) {
    const double w = PressureWeight((*contacts)[i], floor);
    total += w;
    centre += w * patch.points[i];
  }
  centre /= total;
  std::vector<double> share =
      corners.size() == 2
          ? SegmentWeights(patch.points[corners[0]], patch.points[corners[1]], centre)
          : Wachspress(patch.points, corners, centre, patch.extent);
  double sum = 0.0;
  for (const double s : share) sum += s;
  if (!(sum > 0.0) || !std::isfinite(sum)) {
    share.assign(corners.size(), 1.0);
    sum = static_cast<double>(corners.size());
  }
  // a zero weight would read as "unset" (depth²): a corner always keeps a sliver
  for (std::size_t i = 0; i < corners.size(); ++i) {
    (*contacts)[corners[i]].weight = std::max(total * share[i] / sum, total * 1e-12);
  }
  // the corners, in their input order, move to the front (corners[i] >= i: nothing is overwritten
  // before it is read)
  std::sort(corners.begin(), corners.end());
  for (std::size_t i = 0; i < corners.size(); ++i) (*contacts)[i] = (*contacts)[corners[i]];
  contacts->resize(corners.size());
  return true;
}

}  // namespace lamina::core
