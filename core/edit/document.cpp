// SPDX-License-Identifier: MIT
#include "core/edit/document.h"

#include <atomic>
#include <set>
#include <utility>

#include "core/io/load_context.h"
#include "core/io/world_file.h"

namespace lamina::core {

namespace {

// a fresh uid for every element whose uid is 0 or was seen before
void GiveUids(WorldDesc* world) {
  std::set<ElementUid> seen;
  const auto give = [&seen](ElementUid* uid) {
    if (*uid == 0 || seen.count(*uid) > 0) *uid = NewElementUid();
    seen.insert(*uid);
  };
  for (TerrainDesc& terrain : world->terrains) give(&terrain.uid);
  for (RigidObjectDesc& object : world->objects) give(&object.uid);
  for (RobotDesc& robot : world->robots) give(&robot.uid);
}

// config and velocity as the simulator reads them (one finite number per link)
void NormalizeInitialConditions(WorldDesc* world) {
  for (RobotDesc& robot : world->robots) {
    robot.config = robot.InitialConfig();
    robot.velocity = robot.InitialVelocity();
  }
}

template <typename Element>
int IndexOfUid(const std::vector<Element>& elements, ElementUid uid) {
  for (size_t i = 0; i < elements.size(); ++i) {
    if (elements[i].uid == uid) return static_cast<int>(i);
  }
  return -1;
}

std::optional<ElementIndex> FailIndex(std::string* error, std::string message) {
  if (error) *error = std::move(message);
  return std::nullopt;
}

}  // namespace

Revision NewRevision() {
  static std::atomic<Revision> next{1};
  return next.fetch_add(1);
}

void DocumentAccess::Touch(WorldDocument* document) {
  document->revision_ = NewRevision();
}

WorldDocument::WorldDocument() : WorldDocument(WorldDesc()) {}

WorldDocument::WorldDocument(WorldDesc world, std::string path)
    : desc_(std::move(world)),
      path_(std::move(path)),
      revision_(NewRevision()),
      saved_revision_(revision_) {
  GiveUids(&desc_);
  NormalizeInitialConditions(&desc_);
}

bool WorldDocument::Load(const std::string& path, Diagnostics& diagnostics) {
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  WorldDesc world;
  if (!LoadWorldFile(path, context, &world)) return false;
  *this = WorldDocument(std::move(world), path);
  return true;
}

bool WorldDocument::Save(Diagnostics& diagnostics) {
  if (path_.empty()) {
    diagnostics.Error({}, "cannot save: the document has no file yet (save it as a file first)");
    return false;
  }
  return SaveAs(path_, diagnostics);
}

bool WorldDocument::SaveAs(const std::string& path, Diagnostics& diagnostics) {
  if (!SaveWorldFile(desc_, path, diagnostics)) return false;
  path_ = path;
  saved_revision_ = revision_;
  return true;
}

int WorldDocument::TerrainIndex(ElementUid uid) const {
  return IndexOfUid(desc_.terrains, uid);
}

int WorldDocument::ObjectIndex(ElementUid uid) const {
  return IndexOfUid(desc_.objects, uid);
}

int WorldDocument::RobotIndex(ElementUid uid) const {
  return IndexOfUid(desc_.robots, uid);
}

bool WorldDocument::HasUid(ElementUid uid) const {
  return TerrainIndex(uid) >= 0 || ObjectIndex(uid) >= 0 || RobotIndex(uid) >= 0;
}

std::optional<ElementIndex> WorldDocument::Resolve(const ElementRef& ref,
                                                   std::string* error) const {
  return ResolveRef(desc_, ref, error);
}

std::optional<ElementRef> WorldDocument::RefOf(const ElementIndex& element,
                                               std::string* error) const {
  return RefOfElement(desc_, element, error);
}

std::optional<ElementIndex> ResolveRef(const WorldDesc& world, const ElementRef& ref,
                                       std::string* error) {
  int index = -1;
  const char* what = "robot";
  switch (ref.kind) {
    case ElementKind::kSettings:
      return ElementIndex::Settings();
    case ElementKind::kTerrain:
      index = IndexOfUid(world.terrains, ref.uid);
      what = "terrain";
      break;
    case ElementKind::kObject:
      index = IndexOfUid(world.objects, ref.uid);
      what = "object";
      break;
    default:
      index = IndexOfUid(world.robots, ref.uid);
      break;
  }
  if (index < 0) {
    return FailIndex(error, std::string(what) + " #" + std::to_string(ref.uid) +
                                " is not in the world (removed)");
  }
  const ElementIndex element{ref.kind, index, ref.sub};
  const bool has_sub = ref.kind == ElementKind::kLink || ref.kind == ElementKind::kDriver;
  if (const auto problem = has_sub ? CheckElement(world, element) : std::nullopt) {
    return FailIndex(error, RefName(ref) + ": " + *problem);
  }
  return has_sub ? element : ElementIndex{ref.kind, index, -1};
}

std::optional<ElementRef> RefOfElement(const WorldDesc& world, const ElementIndex& element,
                                       std::string* error) {
  if (const auto problem = CheckElement(world, element)) {
    if (error) *error = *problem;
    return std::nullopt;
  }
  switch (element.kind) {
    case ElementKind::kSettings:
      return ElementRef::Settings();
    case ElementKind::kTerrain:
      return ElementRef::Terrain(world.terrains[element.index].uid);
    case ElementKind::kObject:
      return ElementRef::Object(world.objects[element.index].uid);
    case ElementKind::kRobot:
      return ElementRef::Robot(world.robots[element.index].uid);
    default:
      return ElementRef{element.kind, world.robots[element.index].uid, element.sub};
  }
}

}  // namespace lamina::core
