// SPDX-License-Identifier: MIT
// History: undo and redo of edits, with groups so that one slider drag is one undo step.
//
// Do applies an edit and records it (and clears the redo stack); Undo applies the inverses of
// the last entry's edits, last first, and gives the document back the revision it had before
// the entry, so dirty() is exact; Redo applies the edits again and gives back the revision they
// made. Between BeginGroup and the matching EndGroup (groups nest; the outermost label names
// the entry) every Do joins one entry, and consecutive ParamEdits of the same element and row
// coalesce into one (the first `before`, the last `after`). Undo and Redo end any open group
// first. An entry whose edits cannot all be applied leaves everything as it was.
//
// The edits reach their target through EditTarget: a document alone (the Do/Undo/Redo taking
// a WorldDocument), or LiveWorld, which also carries them into a running simulation and keeps
// simulation states with each entry (HistoryEntry::record). ImGui's IsItemActivated /
// IsItemDeactivatedAfterEdit are the natural BeginGroup / EndGroup of a widget. Klamp't's GUIs
// have no undo; MuJoCo Studio keeps whole spec copies per step (this keeps edits and inverses).
#pragma once

#include <any>
#include <string>
#include <vector>

#include "core/edit/document.h"
#include "core/edit/edit.h"

namespace lamina::core {

/// One undo step.
struct HistoryEntry {
  std::string label;
  std::vector<Edit> edits;       ///< in the order they were applied
  Revision revision_before = 0;  ///< the document's before the first edit
  Revision revision_after = 0;   ///< and after the last
  std::any record;               ///< what the target keeps with the entry (LiveWorld: states)
};

enum class HistoryStep { kDo, kUndo, kRedo };

/// What a history's edits are applied to.
class EditTarget {
 public:
  virtual ~EditTarget() = default;
  virtual WorldDocument& document() = 0;
  /// Applies one edit, or changes nothing and returns false with `error`.
  virtual bool Apply(const Edit& edit, std::string* error) = 0;
  /// Before the first edit of a new entry (kDo), or before an entry is undone or redone.
  virtual void BeginStep(HistoryEntry& /*entry*/, HistoryStep /*step*/) {}
  /// After every edit done into the entry (kDo), or after the whole entry was undone or redone.
  virtual void EndStep(HistoryEntry& /*entry*/, HistoryStep /*step*/) {}
};

/// A document alone as the target.
class DocumentTarget : public EditTarget {
 public:
  explicit DocumentTarget(WorldDocument* document) : document_(document) {}
  WorldDocument& document() override { return *document_; }
  bool Apply(const Edit& edit, std::string* error) override {
    return core::Apply(edit, document_, error);
  }

 private:
  WorldDocument* document_;
};

class History {
 public:
  /// Applies `edit` to `target` and records it; false with `error` (nothing recorded or
  /// changed) when the edit is refused.
  bool Do(EditTarget& target, const Edit& edit, std::string* error = nullptr);
  /// Undoes the last entry; false with `error` when there is none or it cannot be undone.
  bool Undo(EditTarget& target, std::string* error = nullptr);
  bool Redo(EditTarget& target, std::string* error = nullptr);
  /// The same on a document alone.
  bool Do(WorldDocument* document, const Edit& edit, std::string* error = nullptr);
  bool Undo(WorldDocument* document, std::string* error = nullptr);
  bool Redo(WorldDocument* document, std::string* error = nullptr);

  bool CanUndo() const { return !undo_.empty(); }
  bool CanRedo() const { return !redo_.empty(); }
  int undo_count() const { return static_cast<int>(undo_.size()); }
  int redo_count() const { return static_cast<int>(redo_.size()); }
  /// The entries, oldest first (Undo applies undo_stack().back(), Redo redo_stack().back()).
  const std::vector<HistoryEntry>& undo_stack() const { return undo_; }
  const std::vector<HistoryEntry>& redo_stack() const { return redo_; }
  /// Label of the entry Undo / Redo would apply ("" when none).
  std::string UndoLabel() const { return undo_.empty() ? "" : undo_.back().label; }
  std::string RedoLabel() const { return redo_.empty() ? "" : redo_.back().label; }

  /// Opens a group (nesting allowed); `label` names the entry when this is the outermost.
  void BeginGroup(std::string label);
  /// Closes the innermost group; unmatched calls are ignored.
  void EndGroup();
  bool in_group() const { return group_depth_ > 0; }

  /// Forgets every entry (a newly loaded document).
  void Clear();

 private:
  bool ApplyAll(EditTarget& target, const HistoryEntry& entry, bool inverse, std::string* error);
  void Record(const Edit& edit);
  void CloseGroups();

  std::vector<HistoryEntry> undo_, redo_;
  int group_depth_ = 0;
  std::string group_label_;
  bool group_has_entry_ = false;  ///< the open group's entry is undo_.back()
};

}  // namespace lamina::core
