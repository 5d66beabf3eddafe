// SPDX-License-Identifier: MIT
// The parameter table: one row per tunable of a world — its key, label, unit, the elements it
// belongs to, its valid range, a widget hint, how an edit takes effect and a line of help.
//
// Every consumer reads its description from here and nowhere else: the world, `.obj` and `.rob`
// readers validate with ParamAccepts (and say ParamRule when they refuse), the writer and the
// world comparison walk the rows, `info` prints them, the simulator's setters refuse what
// CheckParam refuses, `--set` parses with ParseParamValue, undo records name a row, and the
// editor's panels and the batch samplers are generated from it. A value a setter accepts is
// therefore always one the reader accepts, and the reverse (tests/unit/params_test.cpp proves
// it row by row).
//
// Values are lists of doubles (ParamValue): a bool is 0 or 1, a choice its index, an integer a
// whole number; vectors, ranges, poses and inertias are their components (layouts at ParamType).
// This is MuJoCo simulate's `mjuiDef` rows and Jolt's documented `PhysicsSettings` fields in one
// place; unlike MuJoCo's per-geom contact parameters (recompile, state reset) every surface row
// applies live.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/element.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// The components of a value (see ParamType for each layout).
using ParamValue = std::vector<double>;

enum class ParamType {
  kReal,     ///< one number
  kInteger,  ///< one whole number
  kBool,     ///< 0 or 1
  kChoice,   ///< index into ParamSpec::choices
  kVec3,     ///< x, y, z
  kRange,    ///< min, max with min <= max
  kPose,     ///< Klamp't se3 order: rotation column-major (9), then translation (3)
  kTwist,    ///< Klamp't order: angular (3, rad/s), then linear (3, m/s)
  kInertia,  ///< 3x3 row-major, symmetric positive semi-definite (kg·m²)
  kVector,   ///< one number per robot link
};

/// How an edit of the row reaches a running simulation.
enum class ParamApply {
  kLive,              ///< from the next step, the state kept
  kRebuildGeometry,   ///< the body's collision geometry is rebuilt, the state kept
  kRebuildSimulator,  ///< the simulation is rebuilt from the description, its state restored
  kOnReset,           ///< an initial condition: the description changes, the running state not
};

struct ParamSpec {
  std::string_view key;    ///< access-path member, JSON and CLI key; the file attribute where
                           ///< the world file has one ("kFriction", "timestep", "servoP")
  std::string_view label;  ///< short text for a panel ("friction")
  std::string_view unit;   ///< "", "m", "N/m", "N·m/rad", ... (per component)
  unsigned kinds;          ///< KindBit()s of the elements it belongs to
  ParamType type;
  double min;          ///< smallest component (inclusive unless min_exclusive)
  double max;          ///< largest component (inclusive); +inf: no bound
  bool min_exclusive;  ///< "> min" (stiffness, timestep)
  bool allow_inf;      ///< components may be +inf (ranges: also -inf); inf = rigid / no limit
  bool log_scale;      ///< widget hint: spans decades
  ParamApply apply;
  /// True for Klamp't's own attributes (always written); false for Lamina's additions, which the
  /// writer leaves out while they hold their default.
  bool klampt;
  std::string_view help;                      ///< one line
  std::span<const std::string_view> choices;  ///< kChoice: names by index
  ParamValue (*get)(const WorldDesc& world, const ElementIndex& element);
  /// Writes without checking (callers check first with CheckParam or SetParam).
  void (*set)(WorldDesc* world, const ElementIndex& element, const ParamValue& value);

  bool AppliesTo(ElementKind kind) const { return (kinds & KindBit(kind)) != 0; }
};

/// Every row, in a fixed order (settings, body surface and padding, object and link mass
/// properties, initial conditions, joint limits, drivers).
std::span<const ParamSpec> Params();
/// The row with `key` for elements of `kind`, or null. Keys are unique per kind (objects' and
/// robots' "velocity" are different rows).
const ParamSpec* FindParam(std::string_view key, ElementKind kind);
/// Position of `spec` in Params() (stable within a build; undo records use it).
int ParamId(const ParamSpec& spec);
/// A body's padding and surface rows (they belong to terrains, objects and links alike).
inline bool IsBodyParam(const ParamSpec& spec) {
  return spec.AppliesTo(ElementKind::kTerrain);
}
/// Every row that belongs to elements of `kind`.
std::vector<const ParamSpec*> ParamsOf(ElementKind kind);

/// Number of components a value of `spec` has on `element` of `world` (kVector: the robot's
/// link count).
int ParamSize(const ParamSpec& spec, const WorldDesc& world, const ElementIndex& element);

/// The rule a value must follow, as a reader or a panel states it: "must be in [0, 1]",
/// "must be > 0 (inf allowed)", "must be 3 finite numbers", ...
std::string ParamRule(const ParamSpec& spec);
/// True when `value` has `size` components that the row allows (ranges ordered, poses rigid,
/// inertias symmetric positive semi-definite, integers whole, choices in range; never NaN).
bool ParamAccepts(const ParamSpec& spec, const ParamValue& value, int size);
/// None when accepted; otherwise "<key> must be in [0, 1], got 1.5".
std::optional<std::string> CheckParam(const ParamSpec& spec, const ParamValue& value, int size);

/// The row's value on `element`; nullopt when the element does not exist or the row does not
/// belong to it (`error` says which, naming the path).
std::optional<ParamValue> GetParam(const WorldDesc& world, const ElementIndex& element,
                                   const ParamSpec& spec, std::string* error = nullptr);
/// CheckParam on `element` of `world`, plus what depends on the element: a non-affine driver's
/// torque limits are symmetric (a .rob gives it ±torqueMax of its link). None when accepted;
/// otherwise the message naming the path. The element must exist and have the row.
std::optional<std::string> CheckParamOn(const WorldDesc& world, const ElementIndex& element,
                                        const ParamSpec& spec, const ParamValue& value);
/// Checks the element, the row and the value, then writes it; false with `error` naming the path
/// ("objects[1].kRestitution: must be in [0, 1], got 1.5") and nothing changed otherwise.
bool SetParam(WorldDesc* world, const ElementIndex& element, const ParamSpec& spec,
              const ParamValue& value, std::string* error);

/// Text to value: numbers separated by commas ("0,0,-9.8", "inf"), "true"/"false"/"1"/"0" for
/// bools, a choice's name or index, 3 (diagonal) or 9 numbers for an inertia. Only the syntax
/// is checked here (CheckParam checks the range); nullopt with `error` on bad text.
std::optional<ParamValue> ParseParamValue(const ParamSpec& spec, std::string_view text,
                                          std::string* error);
/// Value to text that ParseParamValue reads back exactly ("0,0,-9.8", "quick", "true").
std::string FormatParamValue(const ParamSpec& spec, const ParamValue& value);

/// Pose <-> kPose value; twist <-> kTwist value (Klamp't orders).
ParamValue PoseToValue(const Pose& pose);
Pose ValueToPose(const ParamValue& value);
ParamValue TwistToValue(const Twist& twist);
Twist ValueToTwist(const ParamValue& value);
/// A vector <-> a kVector value (a robot's configuration, gains), element for element.
ParamValue VectorValue(const VecX& v);
VecX ValueVector(const ParamValue& value);

}  // namespace lamina::core
