// SPDX-License-Identifier: MIT
// Internal to the robot loaders: the statements of a `.rob` file, each read and checked on its
// own but not yet combined into a robot (rob_statements.cpp, rob_statement_parts.cpp), the
// steps that build the RobotDesc from them (rob_links.cpp, rob_joints.cpp, rob_mount.cpp,
// rob_file.cpp), and what the URDF reader shares with them (self-collision pairs, mounting).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/io/load_context.h"
#include "core/io/text_statements.h"
#include "core/math_types.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"

namespace lamina::core::rob {

/// Numbers given by one per-link or per-driver keyword, possibly over several statements.
struct NumberList {
  std::string keyword;         ///< as first written, for messages ("qMinDeg")
  int line = 0;                ///< line of the first statement
  std::vector<double> values;  ///< as written (degrees not yet converted)
  std::vector<int> lines;      ///< line of each value
  std::vector<bool> degrees;   ///< per value: given by a `...deg` keyword

  bool empty() const { return values.empty(); }
  int size() const { return static_cast<int>(values.size()); }
};

/// Words given by `links`, `drivers`, `geometry` or `jointtype`.
struct WordList {
  std::string keyword;
  int line = 0;
  std::vector<std::string> values;

  bool empty() const { return values.empty(); }
  int size() const { return static_cast<int>(values.size()); }
};

struct JointStatement {
  JointDesc joint;
  int line = 0;
};

struct DriverStatement {
  DriverDesc driver;
  int line = 0;
};

/// `mount link file [12 numbers] [as prefix]`.
struct MountStatement {
  std::string link;  ///< name or index, as written
  std::string file;  ///< as written
  Pose transform = Pose::Identity();
  std::string prefix;
  int line = 0;
};

/// One `selfcollision` / `noselfcollision` pair, links as written (name or index).
struct PairStatement {
  std::string first, second;
  int line = 0;
};

/// `geomtransform link m11 ... m44`.
struct GeomTransformStatement {
  int link = 0;
  Affine matrix = Affine::Identity();
  int line = 0;
};

struct PropertyStatement {
  std::string name, value;
  int line = 0;
};

/// Everything a `.rob` file says, in file order within each keyword.
struct RobStatements {
  // per-link vectors (length N, decided by voting)
  NumberList parents, q, q_min, q_max, velocity_min, velocity_max, acceleration_max, torque_max,
      power_max, mass, com, inertia, inertia_diag, alpha, a, d, theta, tparent, axis;
  WordList link_names, joint_types, geometry_files;
  // one value for all links, or one per link
  NumberList geom_scale, geom_margin;
  // per-driver vectors
  NumberList servo_p, servo_i, servo_d, dry_friction, viscous_friction;
  WordList driver_names;

  std::optional<std::pair<Vec3, int>> translation;  ///< value, line
  std::optional<std::pair<Mat3, int>> rotation;
  bool automass = false;
  int automass_line = 0;
  double surface_fraction = 1.0;
  double autotorque = 0.0;
  std::vector<GeomTransformStatement> geom_transforms;
  std::vector<JointStatement> joints;
  std::vector<DriverStatement> drivers;
  std::vector<MountStatement> mounts;
  std::vector<PairStatement> self_collision, no_self_collision;
  std::vector<PropertyStatement> properties;
};

/// Reads every statement of `text` into `out`, reporting bad statements as it goes.
void ReadRobStatements(const std::string& text, const std::string& path, Diagnostics& diagnostics,
                       RobStatements* out);

/// Readers of the structured statements `joint`, `driver` and `mount`
/// (rob_statement_parts.cpp); each appends to `out` or reports why it cannot.
void ReadJointStatement(const Statement& statement, const std::string& path,
                        Diagnostics& diagnostics, RobStatements& out);
void ReadDriverStatement(const Statement& statement, const std::string& path,
                         Diagnostics& diagnostics, RobStatements& out);
void ReadMountStatement(const Statement& statement, const std::string& path,
                        Diagnostics& diagnostics, RobStatements& out);

/// The files being loaded, outermost first, so that a robot that mounts itself is caught.
using RobotFileStack = std::vector<std::string>;

/// What the assembly steps share.
struct RobBuild {
  const RobStatements& statements;
  const std::string& path;  ///< the `.rob` file, for messages and relative file names
  LoadContext& context;
  RobotFileStack& stack;
  RobotDesc& robot;
  int link_count = 0;

  SourceLocation At(int line) const { return {path, line, 0}; }
  void Error(int line, std::string message) const {
    context.diagnostics.Error(At(line), std::move(message));
  }
  void Warning(int line, std::string message) const {
    context.diagnostics.Warning(At(line), std::move(message));
  }
  /// Checks `value` against the table's row `key` for elements of `kind` (one component of a
  /// per-link vector counts as the whole when the row is a kVector); a refusal is reported at
  /// `line` as "<what> <rule>, got '<value>'". True when accepted.
  bool CheckRow(int line, const std::string& what, std::string_view key, ElementKind kind,
                const ParamValue& value) const;
};

/// Decides the link count by Klamp't's voting rule and checks every per-link vector against
/// it. Returns 0 (with errors) when the counts disagree or no link is defined.
int VoteLinkCount(const RobStatements& statements, const std::string& path,
                  Diagnostics& diagnostics);
/// Links: names, tree, frames, axes, limits (degrees converted) and mass properties.
void BuildLinks(RobBuild& build);
/// Loads each link's geometry file with its scale, margin and geomtransforms.
void LoadLinkGeometry(RobBuild& build);
/// `autotorque`: Klamp't's torque-limit heuristic from the masses below each link.
void ApplyAutotorque(RobBuild& build);
/// Joints (explicit or one per link) and their checks.
void BuildJoints(RobBuild& build);
/// Drivers (explicit or one per normal/spin joint), their limits, names and servo vectors.
void BuildDrivers(RobBuild& build);
/// `mount` of mesh files onto links (before automass, as Klamp't).
void MountGeometry(RobBuild& build, const std::vector<int>& mount_links);
/// `automass`: COM and inertia from each link's geometry where the file gave none.
void ApplyAutomass(RobBuild& build);
/// `mount` of `.rob` / `.urdf` sub-robots.
void MountRobots(RobBuild& build, const std::vector<int>& mount_links);

/// The link named or numbered `reference` in `robot` (the number is not range-checked);
/// false when `reference` is neither an integer nor a link name.
bool FindLink(const RobotDesc& robot, const std::string& reference, int* index);

/// "1 value", "2 values".
inline std::string CountOf(int count, const std::string& singular) {
  return std::to_string(count) + " " + singular + (count == 1 ? "" : "s");
}

/// "'KEYWORD' link 9 is out of range (robot has 7 links)".
std::string OutOfRangeMessage(const std::string& keyword, int link, int count);

/// Resolves the link pairs of `keyword` (names or indices) against `robot` into `out`. With
/// `final` every pair must resolve (errors otherwise); without, the pairs naming links that
/// are not there yet (mounted later) are returned.
std::vector<PairStatement> ResolvePairs(const RobotDesc& robot,
                                        const std::vector<PairStatement>& pairs,
                                        const std::string& keyword, bool final,
                                        const std::string& path, Diagnostics& diagnostics,
                                        std::vector<std::pair<int, int>>* out);

/// Appends `sub` to `robot` with its roots attached to link `link` (-1 = world) through
/// `transform`, names prefixed "prefix:" when `prefix` is not empty.
void MountSubRobot(const RobotDesc& sub, int link, const Pose& transform, const std::string& prefix,
                   RobotDesc* robot);

/// A driver's position, velocity, torque and acceleration limits from its link, as Klamp't
/// sets them for normal, translation and rotation drivers.
void CopyLinkLimits(const LinkDesc& link, DriverDesc* driver);

/// The loaders behind LoadRobotFile / ParseRob / ParseUrdf, with the stack of open files.
bool LoadRobotFileNested(const std::string& path, const SourceLocation& where, LoadContext& context,
                         RobotFileStack& stack, RobotDesc* out);
bool ParseRobNested(const std::string& text, const std::string& path, LoadContext& context,
                    RobotFileStack& stack, RobotDesc* out);
bool ParseUrdfNested(const std::string& text, const std::string& path, LoadContext& context,
                     RobotFileStack& stack, RobotDesc* out);

}  // namespace lamina::core::rob
