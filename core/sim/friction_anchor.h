// SPDX-License-Identifier: MIT
// Friction anchors: positional correction of static friction.
//
// ODE's friction rows are velocity constraints: a contact that sticks gets zero relative
// tangential velocity, but whatever the solver leaves unconverged (ODE's QuickStep on a chain of
// light links: ATHLETE creeps 18 mm in 2 s) or rounds away is never taken back, so a body held
// by static friction can creep without bound. ERP corrects the same error along the normal.
// An anchor remembers where body a sat relative to body b when the pair started to stick; each
// step every contact's friction rows ask for the tangential velocity that takes back a fraction
// of the drift since then. The rows keep their friction bound (μ N), so an anchor can never
// hold what friction cannot: sliding and rolling re-anchor (the drift or the relative rotation
// outgrows a small limit) and then the rows act exactly as without anchors. The same idea as
// PhysX's and Bullet's friction anchors and Box2D's relax-free static friction.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// Where body a sat in body b's frame when the pair started to stick (ODE body frames, at the
/// centres of mass; a static body's frame is the world).
struct FrictionAnchor {
  int a = -1;  ///< world ids as in ContactPair
  int b = -1;
  Mat3 rotation = Mat3::Identity();  ///< a's axes in b's frame
  Vec3 position = Vec3::Zero();      ///< a's origin in b's frame (m)

  bool operator==(const FrictionAnchor& other) const {
    return a == other.a && b == other.b && rotation == other.rotation && position == other.position;
  }
};

/// A body frame in the world (an ODE body's, or the identity for a static body).
struct BodyFrame {
  Mat3 rotation = Mat3::Identity();
  Vec3 position = Vec3::Zero();
};

/// Relative rotation beyond which a pair counts as rolling or tipping and is re-anchored (rad):
/// the contact point of a rolling body moves over its surface, and the drift measured for the
/// new contact point (a cycloid, r φ³/6) stays below 2e-7 r.
inline constexpr double kAnchorMaxRotation = 0.01;
/// Drift below which nothing is corrected (m): rounding, not creep.
inline constexpr double kAnchorMinDrift = 1e-9;
/// Fastest tangential correction (m/s).
inline constexpr double kAnchorMaxCorrectionSpeed = 0.05;

/// The anchor of pair (a, b) at the bodies' current frames.
FrictionAnchor MakeAnchor(int a, int b, const BodyFrame& frame_a, const BodyFrame& frame_b);

/// Angle of a's rotation relative to b since the anchor was taken (rad).
double AnchorRotation(const FrictionAnchor& anchor, const BodyFrame& frame_a,
                      const BodyFrame& frame_b);

/// Tangential displacement (world, m) since the anchor was taken of the point of body a that is
/// now at `point`, relative to body b, with its component along `normal` removed.
Vec3 AnchorDrift(const FrictionAnchor& anchor, const BodyFrame& frame_a, const BodyFrame& frame_b,
                 const Vec3& point, const Vec3& normal);

/// Relative tangential velocity (a minus b, m/s) that takes back the fraction `gain` of `drift`
/// in one step of `step` seconds, no faster than kAnchorMaxCorrectionSpeed. (The gain and the
/// drift beyond which a pair re-anchors, SimSettings::friction_anchor_gain and
/// friction_anchor_slip, are rows of the parameter table: a body that comes to rest after
/// sliding is pulled back by at most that slip.)
Vec3 AnchorCorrectionVelocity(const Vec3& drift, double step, double gain);

/// The anchor of (a, b) in `anchors` (sorted by a, then b), or nullptr.
const FrictionAnchor* FindAnchor(const std::vector<FrictionAnchor>& anchors, int a, int b);

/// Sorts anchors by (a, b) for FindAnchor.
void SortAnchors(std::vector<FrictionAnchor>* anchors);

/// Removes every anchor that involves body `id`.
void ForgetAnchors(std::vector<FrictionAnchor>* anchors, int id);

}  // namespace lamina::core
