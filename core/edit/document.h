// SPDX-License-Identifier: MIT
// WorldDocument: the world as the user edits and saves it — a WorldDesc (initial conditions,
// not the running state), the file it is saved to, and a revision that names its content.
//
// The document is the only thing that is saved. Runtime state never enters it except through an
// explicit edit (InitialStateEdit, "the current state becomes the initial state"); this is the
// difference from Klamp't's RobotWorld, which is at once the model and the current frame.
//
// Revisions identify content: every applied edit gives a new revision (a process-wide counter),
// and undo/redo give the document back the revision that content had, so dirty() — revision()
// differs from the revision last saved or loaded — is false again after undoing back to the
// saved state. Edits change the description through DocumentAccess (core/edit only); the
// description is otherwise read-only.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/edit/element_ref.h"
#include "core/model/element.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Names a document's content (see the file comment); never 0.
using Revision = std::uint64_t;

class WorldDocument {
 public:
  /// An empty world, clean, without a file.
  WorldDocument();
  /// `world` as a clean document that Save writes to `path` ("": SaveAs first). Every terrain,
  /// object and robot whose uid is 0 or repeats an earlier one gets a fresh uid; a robot's
  /// `config`/`velocity` that is not one finite number per link becomes what the simulator
  /// starts from anyway (RobotDesc::InitialConfig, InitialVelocity: zeros), so that every edit
  /// of those rows can be undone bit for bit.
  explicit WorldDocument(WorldDesc world, std::string path = "");

  /// Loads the world file at `path` (LoadWorldFile; problems go to `diagnostics` as
  /// `file:line: error: ...`). On success the document is that world, clean, saved to `path`;
  /// on any error it is left unchanged and false is returned.
  bool Load(const std::string& path, Diagnostics& diagnostics);
  /// Saves to path() (SaveWorldFile, with the robot files). A failed save (no path, a missing
  /// directory, a file that cannot be written) reports through `diagnostics` and leaves dirty().
  bool Save(Diagnostics& diagnostics);
  /// Saves to `path`, which becomes path() when the save succeeds.
  bool SaveAs(const std::string& path, Diagnostics& diagnostics);

  const WorldDesc& desc() const { return desc_; }
  const std::string& path() const { return path_; }
  Revision revision() const { return revision_; }
  Revision saved_revision() const { return saved_revision_; }
  bool dirty() const { return revision_ != saved_revision_; }

  /// Where `ref` is now; nullopt with `error` ("object #12 is not in the world (removed)",
  /// "robot #3 driver 9: robot 'athlete' has 6 drivers") when it does not resolve.
  std::optional<ElementIndex> Resolve(const ElementRef& ref, std::string* error = nullptr) const;
  /// The stable reference of an element by position; nullopt with `error` naming the path
  /// when the element does not exist.
  std::optional<ElementRef> RefOf(const ElementIndex& element, std::string* error = nullptr) const;
  /// Index of the terrain / object / robot with `uid`, or -1.
  int TerrainIndex(ElementUid uid) const;
  int ObjectIndex(ElementUid uid) const;
  int RobotIndex(ElementUid uid) const;
  /// True when a terrain, object or robot of the document has `uid`.
  bool HasUid(ElementUid uid) const;

 private:
  friend struct DocumentAccess;

  WorldDesc desc_;
  std::string path_;
  Revision revision_;
  Revision saved_revision_;
};

/// WorldDocument::Resolve and RefOf on any description with uids (a document's earlier copy, the
/// file as last saved): where `ref` is in `world`, and the reference of an element by position.
std::optional<ElementIndex> ResolveRef(const WorldDesc& world, const ElementRef& ref,
                                       std::string* error = nullptr);
std::optional<ElementRef> RefOfElement(const WorldDesc& world, const ElementIndex& element,
                                       std::string* error = nullptr);

/// What edits and histories (core/edit only) change in a document.
struct DocumentAccess {
  static WorldDesc& desc(WorldDocument* document) { return document->desc_; }
  /// The content changed: a fresh revision.
  static void Touch(WorldDocument* document);
  /// Undo/redo: the revision the content now restored had.
  static void SetRevision(WorldDocument* document, Revision revision) {
    document->revision_ = revision;
  }
};

/// A revision no document of this process has had. Thread-safe.
Revision NewRevision();

}  // namespace lamina::core
