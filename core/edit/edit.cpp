// SPDX-License-Identifier: MIT
#include "core/edit/edit.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

#include "core/diagnostics.h"
#include "core/model/params.h"
#include "core/model/world_compare.h"

namespace lamina::core {

namespace {

// exact equality, NaN equal to the same NaN: what undo must reproduce
bool SameBits(const double* a, const double* b, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

bool SameValues(const ParamValue& a, const ParamValue& b) {
  return a.size() == b.size() && SameBits(a.data(), b.data(), a.size());
}

bool SameVector(const VecX& a, const VecX& b) {
  return a.size() == b.size() && SameBits(a.data(), b.data(), static_cast<size_t>(a.size()));
}

bool SamePose(const Pose& a, const Pose& b) {
  return SameBits(a.matrix().data(), b.matrix().data(), 16);
}

bool SameTwist(const Twist& a, const Twist& b) {
  return SameBits(a.linear.data(), b.linear.data(), 3) &&
         SameBits(a.angular.data(), b.angular.data(), 3);
}

const ParamSpec* RowOf(int param, std::string* error) {
  if (param >= 0 && param < static_cast<int>(Params().size())) return &Params()[param];
  FailWith(error, "no parameter row " + std::to_string(param));
  return nullptr;
}

std::string Quoted(const std::string& text) {
  return "'" + text + "'";
}

}  // namespace

// ---- ParamEdit ----------------------------------------------------------------------------

bool ParamEdit::Apply(WorldDocument* document, std::string* error) const {
  const ParamSpec* spec = RowOf(param, error);
  if (spec == nullptr) return false;
  const std::optional<ElementIndex> index = document->Resolve(element, error);
  if (!index) return false;
  const std::optional<ParamValue> current = GetParam(document->desc(), *index, *spec, error);
  if (!current) return false;
  if (!SameValues(*current, before)) {
    return FailWith(error, ElementPath(*index) + "." + std::string(spec->key) +
                               ": the edit expects " + FormatParamValue(*spec, before) +
                               " but the document holds " + FormatParamValue(*spec, *current));
  }
  if (!SetParam(&DocumentAccess::desc(document), *index, *spec, after, error)) return false;
  DocumentAccess::Touch(document);
  return true;
}

// ---- RenameEdit ---------------------------------------------------------------------------

namespace {

const std::string* NameOf(const WorldDesc& world, const ElementIndex& element) {
  switch (element.kind) {
    case ElementKind::kTerrain:
      return &world.terrains[element.index].name;
    case ElementKind::kObject:
      return &world.objects[element.index].name;
    case ElementKind::kRobot:
      return &world.robots[element.index].name;
    default:
      return nullptr;
  }
}

std::string* NameOf(WorldDesc* world, const ElementIndex& element) {
  return const_cast<std::string*>(NameOf(std::as_const(*world), element));
}

}  // namespace

bool RenameEdit::Apply(WorldDocument* document, std::string* error) const {
  const std::optional<ElementIndex> index = document->Resolve(element, error);
  if (!index) return false;
  std::string* name = NameOf(&DocumentAccess::desc(document), *index);
  if (name == nullptr) {
    return FailWith(error, ElementPath(*index) + ": only terrains, objects and robots have names");
  }
  if (*name != before) {
    return FailWith(error, ElementPath(*index) + ".name: the edit expects " + Quoted(before) +
                               " but the document holds " + Quoted(*name));
  }
  *name = after;
  DocumentAccess::Touch(document);
  return true;
}

// ---- adding, removing and moving objects ----------------------------------------------------

namespace {

// every table row of an object, as the readers check it: a world that saves also loads
std::optional<std::string> CheckObjectRows(const RigidObjectDesc& object) {
  WorldDesc alone;
  alone.objects.push_back(object);
  const ElementIndex element = ElementIndex::Object(0);
  for (const ParamSpec* spec : ParamsOf(ElementKind::kObject)) {
    if (auto problem = CheckParamOn(alone, element, *spec, spec->get(alone, element))) {
      return problem;
    }
  }
  return std::nullopt;
}

}  // namespace

RemoveObjectEdit AddObjectEdit::Inverse() const {
  return {object, index};
}

bool AddObjectEdit::Apply(WorldDocument* document, std::string* error) const {
  const int count = static_cast<int>(document->desc().objects.size());
  if (object.uid == 0) return FailWith(error, "add object " + Quoted(object.name) + ": no uid");
  if (document->HasUid(object.uid)) {
    return FailWith(error, "add object " + Quoted(object.name) + ": uid " +
                               std::to_string(object.uid) + " is already in the world");
  }
  if (index < 0 || index > count) {
    return FailWith(error, "add object " + Quoted(object.name) + ": index " +
                               std::to_string(index) + " is not in [0, " + std::to_string(count) +
                               "]");
  }
  if (auto problem = CheckObjectRows(object)) {
    // "objects[0].mass must be ..." of the lone copy: the row without the copy's index
    return FailWith(error, "add object " + Quoted(object.name) + ": " +
                               problem->substr(problem->find('.') + 1));
  }
  WorldDesc& desc = DocumentAccess::desc(document);
  std::vector<int> renumbered(desc.objects.size());
  for (int i = 0; i < count; ++i) renumbered[i] = i < index ? i : i + 1;
  RenumberJointObjects(&desc, renumbered);
  desc.objects.insert(desc.objects.begin() + index, object);
  DocumentAccess::Touch(document);
  return true;
}

namespace {

// the differences between two objects, as CompareWorlds words them
std::vector<std::string> CompareObjects(const RigidObjectDesc& a, const RigidObjectDesc& b) {
  WorldDesc world_a, world_b;
  world_a.objects.push_back(a);
  world_b.objects.push_back(b);
  return CompareWorlds(world_a, world_b, 0.0);
}

// the object at `index` of `document` has `uid`
bool CheckObjectAt(const WorldDocument& document, int index, ElementUid uid, std::string* error) {
  const std::vector<RigidObjectDesc>& objects = document.desc().objects;
  const std::string path = ElementPath(ElementIndex::Object(index));
  if (index < 0 || index >= static_cast<int>(objects.size())) {
    return FailWith(error, path + ": the world has " + std::to_string(objects.size()) + " objects");
  }
  if (objects[index].uid != uid) {
    return FailWith(error, path + " is not object #" + std::to_string(uid) + " (it is #" +
                               std::to_string(objects[index].uid) + ")");
  }
  return true;
}

}  // namespace

bool RemoveObjectEdit::Apply(WorldDocument* document, std::string* error) const {
  if (!CheckObjectAt(*document, index, object.uid, error)) return false;
  std::vector<RigidObjectDesc>& objects = DocumentAccess::desc(document).objects;
  const std::vector<std::string> differences = CompareObjects(objects[index], object);
  if (!differences.empty()) {
    return FailWith(error, ElementPath(ElementIndex::Object(index)) +
                               ": the edit's copy of the object differs from the document's (" +
                               differences.front() + ")");
  }
  WorldDesc& desc = DocumentAccess::desc(document);
  if (const int joint = JointHoldingObject(desc, index); joint >= 0) {
    return FailWith(error, ElementPath(ElementIndex::Object(index)) + ": world joint " +
                               std::to_string(joint) + " holds it; remove the joint first");
  }
  std::vector<int> renumbered(objects.size());
  for (int i = 0; i < static_cast<int>(objects.size()); ++i) {
    renumbered[i] = i < index ? i : (i == index ? -1 : i - 1);
  }
  RenumberJointObjects(&desc, renumbered);
  objects.erase(objects.begin() + index);
  DocumentAccess::Touch(document);
  return true;
}

bool MoveObjectEdit::Apply(WorldDocument* document, std::string* error) const {
  if (!CheckObjectAt(*document, from, uid, error)) return false;
  std::vector<RigidObjectDesc>& objects = DocumentAccess::desc(document).objects;
  if (to < 0 || to >= static_cast<int>(objects.size())) {
    return FailWith(error, "move object #" + std::to_string(uid) + ": index " + std::to_string(to) +
                               " is not in [0, " + std::to_string(objects.size() - 1) + "]");
  }
  std::vector<int> order(objects.size());  // order[k]: the object that ends at index k
  for (int i = 0; i < static_cast<int>(order.size()); ++i) order[i] = i;
  const auto at = [&](int i) { return objects.begin() + i; };
  const auto at_order = [&](int i) { return order.begin() + i; };
  if (from < to) {
    std::rotate(at(from), at(from + 1), at(to + 1));
    std::rotate(at_order(from), at_order(from + 1), at_order(to + 1));
  }
  if (to < from) {
    std::rotate(at(to), at(from), at(from + 1));
    std::rotate(at_order(to), at_order(from), at_order(from + 1));
  }
  std::vector<int> renumbered(order.size());
  for (int k = 0; k < static_cast<int>(order.size()); ++k) renumbered[order[k]] = k;
  RenumberJointObjects(&DocumentAccess::desc(document), renumbered);
  DocumentAccess::Touch(document);
  return true;
}

// ---- InitialStateEdit ---------------------------------------------------------------------

InitialState InitialStateOf(const WorldDesc& world) {
  InitialState state;
  for (const RigidObjectDesc& object : world.objects) {
    state.objects.push_back({object.uid, object.pose, object.initial_velocity});
  }
  for (const RobotDesc& robot : world.robots) {
    state.robots.push_back({robot.uid, robot.config, robot.velocity});
  }
  return state;
}

namespace {

// `value` is accepted by row `key` of `kind` (size `size`); the message names `path`
bool CheckRow(std::string_view key, ElementKind kind, const ParamValue& value, int size,
              const std::string& path, std::string* error) {
  const std::optional<std::string> problem = CheckParam(*FindParam(key, kind), value, size);
  return problem ? FailWith(error, path + "." + *problem) : true;
}

bool CheckObjectState(const WorldDocument& document, const ObjectInitialState& before,
                      const ObjectInitialState& after, std::string* error) {
  const int index = document.ObjectIndex(before.uid);
  if (index < 0 || after.uid != before.uid) {
    return FailWith(error, "initial state: object #" + std::to_string(before.uid) +
                               (index < 0 ? " is not in the world" : " is not the edit's after"));
  }
  const RigidObjectDesc& object = document.desc().objects[index];
  const std::string path = ElementPath(ElementIndex::Object(index));
  if (!SamePose(object.pose, before.pose) || !SameTwist(object.initial_velocity, before.velocity)) {
    return FailWith(error, path + ": the edit's initial state is not the document's");
  }
  return CheckRow("transform", ElementKind::kObject, PoseToValue(after.pose), 12, path, error) &&
         CheckRow("velocity", ElementKind::kObject, TwistToValue(after.velocity), 6, path, error);
}

bool CheckRobotState(const WorldDocument& document, const RobotInitialState& before,
                     const RobotInitialState& after, std::string* error) {
  const int index = document.RobotIndex(before.uid);
  if (index < 0 || after.uid != before.uid) {
    return FailWith(error, "initial state: robot #" + std::to_string(before.uid) +
                               (index < 0 ? " is not in the world" : " is not the edit's after"));
  }
  const RobotDesc& robot = document.desc().robots[index];
  const std::string path = ElementPath(ElementIndex::Robot(index));
  if (!SameVector(robot.config, before.config) || !SameVector(robot.velocity, before.velocity)) {
    return FailWith(error, path + ": the edit's initial state is not the document's");
  }
  return CheckRow("config", ElementKind::kRobot, VectorValue(after.config), robot.dof(), path,
                  error) &&
         CheckRow("velocity", ElementKind::kRobot, VectorValue(after.velocity), robot.dof(), path,
                  error);
}

bool CheckInitialStates(const WorldDocument& document, const InitialState& before,
                        const InitialState& after, std::string* error) {
  if (before.objects.size() != after.objects.size() ||
      before.robots.size() != after.robots.size()) {
    return FailWith(error, "initial state: before and after list different elements");
  }
  for (size_t i = 0; i < before.objects.size(); ++i) {
    if (!CheckObjectState(document, before.objects[i], after.objects[i], error)) return false;
  }
  for (size_t i = 0; i < before.robots.size(); ++i) {
    if (!CheckRobotState(document, before.robots[i], after.robots[i], error)) return false;
  }
  return true;
}

}  // namespace

bool InitialStateEdit::Apply(WorldDocument* document, std::string* error) const {
  if (!CheckInitialStates(*document, before, after, error)) return false;
  WorldDesc& world = DocumentAccess::desc(document);
  for (const ObjectInitialState& object : after.objects) {
    RigidObjectDesc& desc = world.objects[document->ObjectIndex(object.uid)];
    desc.pose = object.pose;
    desc.initial_velocity = object.velocity;
  }
  for (const RobotInitialState& robot : after.robots) {
    RobotDesc& desc = world.robots[document->RobotIndex(robot.uid)];
    desc.config = robot.config;
    desc.velocity = robot.velocity;
  }
  DocumentAccess::Touch(document);
  return true;
}

// ---- the variant --------------------------------------------------------------------------

bool Apply(const Edit& edit, WorldDocument* document, std::string* error) {
  return std::visit([&](const auto& e) { return e.Apply(document, error); }, edit);
}

Edit Inverse(const Edit& edit) {
  return std::visit([](const auto& e) { return Edit(e.Inverse()); }, edit);
}

bool ChangesStructure(const Edit& edit) {
  return !std::holds_alternative<ParamEdit>(edit) &&
         !std::holds_alternative<InitialStateEdit>(edit);
}

namespace {

// a name or, for an unnamed element, its access path
std::string NameOr(const std::string& name, const ElementIndex& element) {
  return name.empty() ? ElementPath(element) : name;
}

// the element as the world names it: "block", "arm link 'elbow'", "arm driver 'shoulder'"
std::string ElementName(const WorldDesc& world, const ElementIndex& e) {
  switch (e.kind) {
    case ElementKind::kSettings:
      return "settings";
    case ElementKind::kTerrain:
      return NameOr(world.terrains[e.index].name, e);
    case ElementKind::kObject:
      return NameOr(world.objects[e.index].name, e);
    case ElementKind::kRobot:
      return NameOr(world.robots[e.index].name, e);
    case ElementKind::kLink:
      return NameOr(world.robots[e.index].name, ElementIndex::Robot(e.index)) + " link " +
             Quoted(world.robots[e.index].links[e.sub].name);
    case ElementKind::kDriver:
      return NameOr(world.robots[e.index].name, ElementIndex::Robot(e.index)) + " driver " +
             Quoted(world.robots[e.index].drivers[e.sub].name);
  }
  return ElementPath(e);
}

struct Describer {
  const WorldDesc* world = nullptr;

  std::string operator()(const ParamEdit& e) const {
    const bool known = e.param >= 0 && e.param < static_cast<int>(Params().size());
    const std::string key = known ? std::string(Params()[e.param].key) : "?";
    const std::optional<ElementIndex> index = world ? ResolveRef(*world, e.element) : std::nullopt;
    return key + " of " + (index ? ElementName(*world, *index) : RefName(e.element));
  }
  std::string operator()(const RenameEdit& e) const {
    return "rename " + Quoted(e.before) + " to " + Quoted(e.after);
  }
  std::string operator()(const AddObjectEdit& e) const {
    return "add object " + Quoted(e.object.name);
  }
  std::string operator()(const RemoveObjectEdit& e) const {
    return "remove object " + Quoted(e.object.name);
  }
  std::string operator()(const MoveObjectEdit& e) const {
    return "move object #" + std::to_string(e.uid) + " to " + std::to_string(e.to);
  }
  std::string operator()(const InitialStateEdit&) const { return "initial state"; }
};

}  // namespace

std::string Describe(const Edit& edit, const WorldDesc* world) {
  return std::visit(Describer{world}, edit);
}

// ---- building edits -----------------------------------------------------------------------

std::optional<ParamEdit> MakeParamEdit(const WorldDocument& document, const ElementRef& ref,
                                       std::string_view key, ParamValue after, std::string* error) {
  const std::optional<ElementIndex> index = document.Resolve(ref, error);
  if (!index) return std::nullopt;
  const ParamSpec* spec = FindParam(key, ref.kind);
  if (spec == nullptr) {
    FailWith(error, ElementPath(*index) + ": no parameter " + std::string(key));
    return std::nullopt;
  }
  std::optional<ParamValue> before = GetParam(document.desc(), *index, *spec, error);
  if (!before) return std::nullopt;
  return ParamEdit{ref, ParamId(*spec), std::move(*before), std::move(after)};
}

std::optional<RenameEdit> MakeRenameEdit(const WorldDocument& document, const ElementRef& ref,
                                         std::string after, std::string* error) {
  const std::optional<ElementIndex> index = document.Resolve(ref, error);
  if (!index) return std::nullopt;
  const std::string* name = NameOf(document.desc(), *index);
  if (name == nullptr) {
    FailWith(error, ElementPath(*index) + ": only terrains, objects and robots have names");
    return std::nullopt;
  }
  return RenameEdit{ref, *name, std::move(after)};
}

AddObjectEdit MakeAddObjectEdit(const WorldDocument& document, RigidObjectDesc object, int index) {
  if (object.uid == 0) object.uid = NewElementUid();
  const int count = static_cast<int>(document.desc().objects.size());
  return {std::move(object), index < 0 ? count : index};
}

std::optional<RemoveObjectEdit> MakeRemoveObjectEdit(const WorldDocument& document, ElementUid uid,
                                                     std::string* error) {
  const std::optional<ElementIndex> index = document.Resolve(ElementRef::Object(uid), error);
  if (!index) return std::nullopt;
  return RemoveObjectEdit{document.desc().objects[index->index], index->index};
}

std::optional<MoveObjectEdit> MakeMoveObjectEdit(const WorldDocument& document, ElementUid uid,
                                                 int to, std::string* error) {
  const std::optional<ElementIndex> index = document.Resolve(ElementRef::Object(uid), error);
  if (!index) return std::nullopt;
  return MoveObjectEdit{uid, index->index, to};
}

InitialStateEdit MakeInitialStateEdit(const WorldDocument& document, InitialState after) {
  return {InitialStateOf(document.desc()), std::move(after)};
}

}  // namespace lamina::core
