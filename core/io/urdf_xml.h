// SPDX-License-Identifier: MIT
// Internal to the URDF reader: what urdfdom does not give us. The document is first read with
// tinyxml2 for line numbers, the checks urdfdom would report without a line (XML errors,
// links named by joints but not defined), Klamp't's `<klampt>` extension, and the
// resolution of mesh file names (relative, file://, package://).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "core/diagnostics.h"
#include "core/io/rob_statements.h"
#include "core/math_types.h"

namespace lamina::core::urdf_io {

/// The URDF document with its elements by name, for line numbers.
struct UrdfXml {
  tinyxml2::XMLDocument document;
  int robot_line = 0;
  std::map<std::string, const tinyxml2::XMLElement*> links;
  std::map<std::string, const tinyxml2::XMLElement*> joints;

  /// Line of `<link name=...>`, or of `<robot>` when unknown.
  int LinkLine(const std::string& name) const;
  int JointLine(const std::string& name) const;
  /// Lines of the shape element (`<mesh>`, `<box>`, ...) of each `<collision>` or `<visual>`
  /// (`kind`) of link `name`, in file order.
  std::vector<int> GeometryLines(const std::string& name, const char* kind) const;
};

/// Reads `text` into `out`; false (with errors) for bad XML, a root that is not `<robot>`,
/// nameless or duplicate links, and joints naming links that do not exist.
bool ReadUrdfXml(const std::string& text, const std::string& path, Diagnostics& diagnostics,
                 UrdfXml* out);

/// Per-link settings of `<klampt><link name=...>`.
struct KlamptLinkSettings {
  int line = 0;
  bool physical = true;
  std::optional<double> servo_p, servo_i, servo_d, dry_friction, viscous_friction;
  std::optional<double> acceleration_max;
};

/// Klamp't's `<klampt>` element of a URDF (Klamp't `Robot::LoadURDF`).
struct KlamptExtras {
  std::string world_frame = "world";  ///< a root link of this name is the fixed world
  bool use_visual_geometry = false;
  bool freeze_root_link = false;
  std::string package_root;            ///< absolute; "" = search for packages
  double default_acc_max = 10.0;       ///< rad/s² (or m/s²) of every moving joint
  std::optional<double> default_mass;  ///< of links without `<inertial>`
  std::optional<Mat3> default_inertia;
  std::map<std::string, KlamptLinkSettings> links;
  std::vector<rob::PairStatement> self_collision, no_self_collision;
  std::vector<rob::MountStatement> mounts;
  std::map<std::string, std::string> properties;  ///< `sensors`, `controller`
  /// Where the `sensors` text starts: its file's line 1, or the `<sensors>` element's line
  /// (the element's problems are all reported there).
  SourceLocation sensors_at;
};

/// Reads `<robot><klampt>` (if any) into `out`; unknown attributes and elements are warnings.
void ReadKlamptExtras(const UrdfXml& xml, const std::string& path, Diagnostics& diagnostics,
                      KlamptExtras* out);

/// The absolute file a URDF mesh `filename` names: relative to `urdf_dir`, `file://...`, or
/// `package://NAME/rest` with NAME found under `package_root` when given, else by searching
/// upward from `urdf_dir` for a directory NAME or one whose package.xml names NAME. Empty with
/// `*error` set when the package cannot be found.
std::string ResolveMeshFile(const std::string& filename, const std::string& urdf_dir,
                            const std::string& package_root, std::string* error);

}  // namespace lamina::core::urdf_io
