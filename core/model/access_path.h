// SPDX-License-Identifier: MIT
// Access paths: text that names one tunable or state item of a world or of a running simulation,
// in the syntax of Klamp't's `klampt.model.access` where it has one: `settings.gravity`,
// `objects[block].kFriction`, `robots[0].drivers[3].servoP`, `robots[ATHLETE].config[3]`,
// `controllers[0].commandedConfig`.
//
// Grammar: segments separated by '.', each an identifier followed by zero or more
// `[selector]`; a selector is a whole number (an index) or a name, unquoted up to ']' or quoted
// with ' or " (a quoted selector is always a name, so an element named "0" is `objects['0']`).
// Roots: `settings`, `terrains[i|name]`, `objects[i|name]` (alias `rigidObjects`),
// `robots[i|name]` with `links[i|name]` and `drivers[i|name]` below it, and on a running
// simulation also `controllers[i|name]` and `time`. The last segment is the item: a row of the
// parameter table (params.h; its key, plus `kP`, `kI`, `kD` for servoP, servoI, servoD) or, on a
// simulation, a state item (StateItem). A trailing `[k]` on a vector-valued item selects one
// component; setting one is read-modify-write.
//
// Values are ParamValues in the rows' layouts (ParamType): poses in Klamp't's se3 order (rotation
// column-major, then translation, m), twists angular (rad/s) then linear (m/s), robot vectors one
// number per link (rad or m). On a WorldDesc (AccessContext::kDescription) objects' `transform`
// and `velocity` and robots' `config` and `velocity` are the initial-condition rows; on a
// simulation (kSimulation) the same names are the current state.
//
// Differences from Klamp't: paths are parsed, never evaluated (Klamp't runs eval/exec on them);
// a name that several elements share is refused rather than resolved to the first; the table's
// rows are members of the element they belong to (`robots[0].links[2].jointLimits`, not the
// robot's qmin/qmax lists); every set is checked by the table's rules and a refused set changes
// nothing. Klamp't's generic getX/setX fallback does not exist: only the names listed here do.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/element.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// One `[selector]` of a segment.
struct AccessSelector {
  bool is_index = false;  ///< an unquoted whole number
  int index = -1;         ///< is_index: the number
  std::string name;       ///< otherwise the name (quotes removed)
  size_t end = 0;         ///< offset just past its ']' in AccessPath::text
};

/// `identifier[selector]...`
struct AccessSegment {
  std::string name;
  std::vector<AccessSelector> selectors;
  size_t end = 0;  ///< offset just past the identifier in AccessPath::text
};

struct AccessPath {
  std::string text;  ///< as written (surrounding blanks removed)
  std::vector<AccessSegment> segments;

  /// The text up to `end` ("objects[blok]" of "objects[blok].kFriction"), for messages.
  std::string Prefix(size_t end) const { return text.substr(0, end); }
};

/// Parses the syntax only (no world needed); nullopt with `error` naming the path, what is wrong
/// and the 1-based column ("robots[0: expected ']' at column 9").
std::optional<AccessPath> ParseAccessPath(std::string_view text, std::string* error);

/// What a path can mean: the description (rows only) or a running simulation (rows, and the
/// current state under the initial conditions' names).
enum class AccessContext { kDescription, kSimulation };

/// The simulation-only items a path can name (all on AccessContext::kSimulation).
enum class StateItem {
  kNone,               ///< not a state item: a row of the parameter table
  kTime,               ///< `time`: simulated time (s), read-only
  kObjectTransform,    ///< `objects[i].transform`: current pose (se3 layout), settable (teleport)
  kObjectVelocity,     ///< `objects[i].velocity`: current twist (angular, linear), settable
  kRobotConfig,        ///< `robots[r].config` / `actualConfig`: joint values, settable
  kRobotVelocity,      ///< `robots[r].velocity` / `actualVelocity`: joint rates, settable
  kRobotTorques,       ///< `robots[r].torques` / `actualTorques`: driver efforts, read-only
  kLinkTransform,      ///< `robots[r].links[j].transform`: link frame, read-only
  kLinkVelocity,       ///< `robots[r].links[j].velocity`: link twist, read-only
  kCommandedConfig,    ///< `controllers[r].commandedConfig`, read-only
  kCommandedVelocity,  ///< `controllers[r].commandedVelocity`, read-only
  kSensedConfig,       ///< `controllers[r].sensedConfig`, read-only
  kSensedVelocity,     ///< `controllers[r].sensedVelocity`, read-only
};

/// A resolved path.
struct AccessTarget {
  std::string path;      ///< as written (with the component), for messages
  ElementIndex element;  ///< controllers: the robot; time: the settings
  StateItem state = StateItem::kNone;
  /// The row (state == kNone), or the row whose value layout the state item shares (objects'
  /// transform and velocity rows, robots' config row); parses and formats values.
  const ParamSpec* row = nullptr;
  int component = -1;  ///< a trailing [k]: that component only; -1: the whole value
  bool read_only = false;
};

/// Resolves `path` against the elements and rows of `world`; nullopt with one line in `error`
/// naming the path as written and what is wrong ("objects[blok]: no object is named 'blok' (did
/// you mean 'block'?)", "robots[3]: the world has 1 robot", "objects[0].kFrction: objects have no
/// 'kFrction' (did you mean 'kFriction'?)").
std::optional<AccessTarget> ResolveAccessPath(const WorldDesc& world, const AccessPath& path,
                                              AccessContext context, std::string* error);
/// ParseAccessPath then ResolveAccessPath.
std::optional<AccessTarget> ResolveAccessPath(const WorldDesc& world, std::string_view path,
                                              AccessContext context, std::string* error);

/// Number of components of the target's whole value (12 for a pose, the link count for a robot
/// vector, the driver count for torques), ignoring the component selector.
int AccessValueSize(const WorldDesc& world, const AccessTarget& target);
/// Text to value with the target's row ("0,0,-9.8", "inf", "true", "quick"); a component takes
/// one number. Syntax only (SetPath checks the range); nullopt with `error` naming the path.
std::optional<ParamValue> ParseAccessValue(const AccessTarget& target, std::string_view text,
                                           std::string* error);
/// Value to text that ParseAccessValue reads back exactly.
std::string FormatAccessValue(const AccessTarget& target, const ParamValue& value);

/// The one component `target.component` of `whole`, or `whole` itself without a component.
ParamValue SelectComponent(const AccessTarget& target, const ParamValue& whole);
/// `whole` with `value` (one number) written into the selected component, or `value` itself
/// without a component (read-modify-write of component sets).
ParamValue ReplaceComponent(const AccessTarget& target, ParamValue whole, const ParamValue& value);
/// None when `whole` is a value of the target's row on `world` (its rule and size); otherwise
/// "<path> must be in [0, 1], got 1.5" with the path as written.
std::optional<std::string> CheckAccessValue(const WorldDesc& world, const AccessTarget& target,
                                            const ParamValue& whole);

/// The value a resolved description target names (a row; kDescription targets only).
std::optional<ParamValue> GetPath(const WorldDesc& world, const AccessTarget& target,
                                  std::string* error);
/// The value `path` names on `world`: a row, or one component of it.
std::optional<ParamValue> GetPath(const WorldDesc& world, std::string_view path,
                                  std::string* error);
/// Checks with the table and writes; false with `error` naming the path and nothing changed.
bool SetPath(WorldDesc* world, const AccessTarget& target, const ParamValue& value,
             std::string* error);
bool SetPath(WorldDesc* world, std::string_view path, const ParamValue& value, std::string* error);
/// SetPath with the value as text (ParseAccessValue).
bool SetPathText(WorldDesc* world, std::string_view path, std::string_view value_text,
                 std::string* error);

/// "PATH=VALUE" split at the first '=' outside a selector ("objects['a=b'].kFriction=1" has the
/// path "objects['a=b'].kFriction"); false with `error` when there is no '=' or either side is
/// empty.
bool SplitAssignment(std::string_view text, std::string* path, std::string* value,
                     std::string* error);

}  // namespace lamina::core
