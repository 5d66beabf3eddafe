// SPDX-License-Identifier: MIT
// The transform attributes of Klamp't world XML, read and written: `translation|position`,
// `rotateRPY`, `rotateMoment`, `rotateX/Y/Z` and, for geometry, `scale`.
#pragma once

#include <string>
#include <vector>

#include "core/geometry/geometry_desc.h"
#include "core/io/xml_element_reader.h"

namespace lamina::core {

/// Attribute names of a rigid transform.
inline constexpr const char* kTransformAttributes[] = {
    "translation", "position", "rotateRPY", "rotateMoment", "rotateX", "rotateY", "rotateZ"};

/// The pose given by the transform attributes of the element, as Klamp't reads them:
/// R = rotateRPY (Rz·Ry·Rx) or rotateMoment (which replaces it), then R <- Rx·R, Ry·R, Rz·R.
/// Returns false when the element has none of them (pose = identity).
bool ReadPose(const XmlElementReader& reader, Pose* pose);
/// `scale` as a 3-vector (one number means uniform). False when absent.
bool ReadScale(const XmlElementReader& reader, Vec3* scale);
/// Applies the element's scale and transform after the geometry's current placement.
void ApplyGeometryTransform(const XmlElementReader& reader, GeometryDesc* geometry);

/// Attribute (name, value) pairs that ReadPose turns back into `pose`.
std::vector<std::pair<std::string, std::string>> PoseAttributes(const Pose& pose);
/// Attribute pairs for a geometry placement (scale, translation, rotateMoment); false (and no
/// attributes) when the matrix has shear and cannot be written as scale-then-rigid.
bool GeometryTransformAttributes(const GeometryDesc& geometry,
                                 std::vector<std::pair<std::string, std::string>>* attributes);

}  // namespace lamina::core
