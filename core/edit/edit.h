// SPDX-License-Identifier: MIT
// Edits of a world document as values: each kind holds what it changes before and after, so
// that applying its Inverse() undoes it bit for bit. Elements are named by ElementRef (uids), so
// an edit recorded before a reorder, a rename or another element's removal still names the same
// element; one whose element is gone is refused with a message.
//
// Apply(document, &error) checks everything first and changes nothing when it refuses: the
// element must resolve, the `before` values must be what the document holds now (an edit built
// against another state would not undo exactly), and the `after` values must be what the file
// readers accept (the parameter table's CheckParam; the messages name the access path,
// "objects[1].kRestitution must be in [0, 1], got 1.5"). Every applied edit gives the document
// a new revision. The Make* functions build edits from the document's current values.
//
// Unlike MuJoCo's mjSpec edits (which change the spec in place and need mj_recompile), an edit
// here is data: History keeps it, LiveWorld carries it into a running simulation. Klamp't has no
// edit layer (its GUIs set values on the world or the simulator directly). Values are in the
// table's units (SI; poses and twists in Klamp't's component order, see ParamType).
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/edit/document.h"
#include "core/edit/element_ref.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// One row of the parameter table (core/model/params.h) on one element: every tunable,
/// including the initial conditions (`transform`, `velocity`, robots' `config`, `velocity`).
struct ParamEdit {
  ElementRef element;
  int param = -1;  ///< ParamId of the row
  ParamValue before, after;

  bool Apply(WorldDocument* document, std::string* error) const;
  ParamEdit Inverse() const { return {element, param, after, before}; }
};

/// A terrain's, object's or robot's name.
struct RenameEdit {
  ElementRef element;
  std::string before, after;

  bool Apply(WorldDocument* document, std::string* error) const;
  RenameEdit Inverse() const { return {element, after, before}; }
};

struct RemoveObjectEdit;

/// Inserts `object` (whose uid no element of the document may have, and not 0) at `index`
/// (0 ... object count).
struct AddObjectEdit {
  RigidObjectDesc object;
  int index = -1;

  bool Apply(WorldDocument* document, std::string* error) const;
  RemoveObjectEdit Inverse() const;
};

/// Removes the object at `index`, which must be `object` (same uid and content).
struct RemoveObjectEdit {
  RigidObjectDesc object;
  int index = -1;

  bool Apply(WorldDocument* document, std::string* error) const;
  AddObjectEdit Inverse() const { return {object, index}; }
};

/// Moves the object with `uid` from index `from` to index `to` (the others keep their order).
struct MoveObjectEdit {
  ElementUid uid = 0;
  int from = -1, to = -1;

  bool Apply(WorldDocument* document, std::string* error) const;
  MoveObjectEdit Inverse() const { return {uid, to, from}; }
};

/// The initial conditions of objects and robots, keyed by uid.
struct ObjectInitialState {
  ElementUid uid = 0;
  Pose pose = Pose::Identity();  ///< RigidObjectDesc::pose
  Twist velocity;                ///< RigidObjectDesc::initial_velocity
};
struct RobotInitialState {
  ElementUid uid = 0;
  VecX config;    ///< RobotDesc::config, one per link
  VecX velocity;  ///< RobotDesc::velocity, one per link
};
struct InitialState {
  std::vector<ObjectInitialState> objects;
  std::vector<RobotInitialState> robots;
};
/// What `world` starts from: every object and robot.
InitialState InitialStateOf(const WorldDesc& world);

/// "The current state becomes the initial state": the initial conditions of every element in
/// `before` (which must list the same uids as `after`, in the same order) become `after`'s.
/// Poses must be rigid and finite, velocities finite, robot vectors one finite number per link.
struct InitialStateEdit {
  InitialState before, after;

  bool Apply(WorldDocument* document, std::string* error) const;
  InitialStateEdit Inverse() const { return {after, before}; }
};

using Edit = std::variant<ParamEdit, RenameEdit, AddObjectEdit, RemoveObjectEdit, MoveObjectEdit,
                          InitialStateEdit>;

bool Apply(const Edit& edit, WorldDocument* document, std::string* error);
Edit Inverse(const Edit& edit);
/// True for edits that change which elements exist, their order or their names (a running
/// simulation is built anew for them: LiveWorld).
bool ChangesStructure(const Edit& edit);
/// A short label for a history menu: "kFriction of object #4", "rename 'box' to 'crate'",
/// "add object 'box'", "initial state". With `world` (the document before the edit) elements
/// are named as the user knows them: "kFriction of block", "servoP of arm driver 'shoulder'".
std::string Describe(const Edit& edit, const WorldDesc* world = nullptr);

// ---- building edits from a document's current values ------------------------------------

/// Row `key` of `ref`'s kind set to `after`; nullopt with `error` when the element does not
/// resolve or has no such row (the value itself is checked when the edit is applied).
std::optional<ParamEdit> MakeParamEdit(const WorldDocument& document, const ElementRef& ref,
                                       std::string_view key, ParamValue after,
                                       std::string* error = nullptr);
std::optional<RenameEdit> MakeRenameEdit(const WorldDocument& document, const ElementRef& ref,
                                         std::string after, std::string* error = nullptr);
/// Adds `object` at `index` (-1: at the end); an object without a uid (0) gets a fresh one.
AddObjectEdit MakeAddObjectEdit(const WorldDocument& document, RigidObjectDesc object,
                                int index = -1);
std::optional<RemoveObjectEdit> MakeRemoveObjectEdit(const WorldDocument& document, ElementUid uid,
                                                     std::string* error = nullptr);
std::optional<MoveObjectEdit> MakeMoveObjectEdit(const WorldDocument& document, ElementUid uid,
                                                 int to, std::string* error = nullptr);
InitialStateEdit MakeInitialStateEdit(const WorldDocument& document, InitialState after);

}  // namespace lamina::core
