// SPDX-License-Identifier: MIT
// Reducing a flat contact patch to the corners of its outline, before clustering.
//
// A foot, a box or any flat face resting on a flat face touches at many points with one normal:
// a mesh sole on a plane gives 10 or more after merging (every sole vertex and triangle pair).
// For the solver those interior points are redundant: a force f inside the cone of the common
// normal n, applied at a point p that is a convex combination Σ λ_j p_j of outline corners, has
// the same wrench (f, p × f) as the forces λ_j f at the corners, each inside the same cone. So
// the corners of the patch's convex outline span exactly the wrenches the whole patch can carry
// (rigid contact), and the LCP needs only their rows. dWorldStep's cost grows with the square of
// the rows (and the cube, counting the pivots), so a humanoid standing on two soles solves about
// half the contact rows it otherwise would.
//
// Soft contacts share their pair's spring force by pressure weight (contact_rows.h): each corner
// is given the weight that keeps the patch's total weight and its centre of pressure (the
// Wachspress coordinates of the centre in the outline polygon, smooth and positive inside a
// convex polygon), so a soft patch still pushes with the same force through the same point.
//
// Differences from Klamp't: Klamp't clusters every pair with k-means to at most maxContacts
// representatives (contact_clustering.h), whose centres lie inside the patch and so shrink its
// support polygon; Lamina keeps the outline where it is. Patches that are not flat (normals more
// than kFlatPatchAngle apart, or points off a common plane) are left to the clustering.
#pragma once

#include "core/contact/contact.h"

namespace lamina::core {

/// Normals within this angle of the first contact's count as one (rad).
inline constexpr double kFlatPatchAngle = 1e-3;
/// Points within this distance of the first contact's plane (relative to the patch's extent, plus
/// kFlatPatchAbsolute) count as coplanar: a point h off the plane turns a tangential force f_t
/// into a moment h·f_t the corners do not have, 1 % of the patch's size at most (HRP-2's soles
/// have bevelled rims whose contacts sit 0.5 mm above the rest, 0.2 % of the sole).
inline constexpr double kFlatPatchRelative = 1e-2;
inline constexpr double kFlatPatchAbsolute = 1e-7;  ///< m

/// The outline keeps at least this many corners ...
inline constexpr int kOutlineCorners = 4;
/// ... and loses at most this fraction of its area when its least important corners are dropped
/// (a sole's chamfers: HRP-2's soles have 8 corners, 4 of them cut off by chamfers).
inline constexpr double kOutlineAreaLoss = 0.02;

/// When `contacts` (one pair's, merged) is a flat patch of more than 4 contacts whose outline has
/// fewer corners than the patch has points, replaces it by the outline's corners (in their order
/// in the input, collinear points dropped, corners that cut off less than kOutlineAreaLoss of the
/// outline in all dropped down to kOutlineCorners) weighted as above; `floor` is the depth the
/// pair's pressure weights are floored at (PressureWeight). True when it reduced.
bool ReduceFlatPatch(double floor, ContactList* contacts);

}  // namespace lamina::core
