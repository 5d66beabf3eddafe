// SPDX-License-Identifier: MIT
// Reducing a pair's contacts to at most `max_contacts` representatives, deterministically.
#pragma once

#include "core/contact/contact.h"

namespace lamina::core {

/// Reduces `contacts` in place to at most `max_contacts` by k-means clustering (Lloyd) in the
/// 7-D feature space (position, normal_scale * normal, depth), as Klamp't does, but with a
/// deterministic initialisation, no random restarts, a uniform-stride subsample when the input
/// is very large, and the cluster depth taken as the deepest member (not the mean). Each output
/// contact: the centre of its members' pressure (positions weighted by PressureWeight, i.e.
/// depth²; Klamp't takes the plain centroid), their summed weight, the renormalized mean
/// normal, the max depth, penetrating if any member is. Fewer contacts than `max_contacts` are
/// left untouched. Same input, same output.
void ClusterContacts(int max_contacts, double normal_scale, ContactList* contacts);

/// Klamp't's default weight of normals against positions in the clustering features.
inline constexpr double kDefaultClusterNormalScale = 0.1;

}  // namespace lamina::core

namespace lamina::core {

/// Merges contacts that lie within `radius` of an earlier contact and whose normals agree within
/// about 15 degrees into that earlier contact (keeping the larger depth and the penetrating
/// flag): both meshes report a shared corner, and a corner is also the end of edge contacts.
/// Deterministic; keeps the order of the survivors.
void MergeCoincidentContacts(double radius, ContactList* contacts);

}  // namespace lamina::core
