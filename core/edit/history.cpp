// SPDX-License-Identifier: MIT
#include "core/edit/history.h"

#include <utility>

#include "core/diagnostics.h"
namespace lamina::core {

namespace {

// `next` continues `last` (the same row of the same element) and can be merged into it
bool Coalesces(const Edit& last, const Edit& next) {
  const auto* a = std::get_if<ParamEdit>(&last);
  const auto* b = std::get_if<ParamEdit>(&next);
  return a != nullptr && b != nullptr && a->element == b->element && a->param == b->param;
}

}  // namespace

bool History::Do(EditTarget& target, const Edit& edit, std::string* error) {
  const bool opens = !(group_depth_ > 0 && group_has_entry_);
  HistoryEntry entry;
  if (opens) {
    entry.label = group_depth_ > 0 && !group_label_.empty()
                      ? group_label_
                      : Describe(edit, &target.document().desc());
    entry.revision_before = target.document().revision();
    target.BeginStep(entry, HistoryStep::kDo);
  }
  if (!target.Apply(edit, error)) return false;
  if (opens) {
    redo_.clear();
    undo_.push_back(std::move(entry));
    group_has_entry_ = group_depth_ > 0;
  }
  Record(edit);
  undo_.back().revision_after = target.document().revision();
  target.EndStep(undo_.back(), HistoryStep::kDo);
  return true;
}

// appends `edit` to the open entry, or merges it into the entry's last edit inside a group
void History::Record(const Edit& edit) {
  std::vector<Edit>& edits = undo_.back().edits;
  if (group_depth_ > 0 && !edits.empty() && Coalesces(edits.back(), edit)) {
    std::get<ParamEdit>(edits.back()).after = std::get<ParamEdit>(edit).after;
  } else {
    edits.push_back(edit);
  }
}

// the entry's edits (or their inverses, last first); on a refusal, those applied are taken back
bool History::ApplyAll(EditTarget& target, const HistoryEntry& entry, bool inverse,
                       std::string* error) {
  const int count = static_cast<int>(entry.edits.size());
  const auto edit = [&](int k, bool invert) {
    const Edit& e = entry.edits[invert ? count - 1 - k : k];
    return invert ? Inverse(e) : e;
  };
  for (int k = 0; k < count; ++k) {
    if (target.Apply(edit(k, inverse), error)) continue;
    std::string ignored;
    for (int j = k - 1; j >= 0; --j) target.Apply(Inverse(edit(j, inverse)), &ignored);
    DocumentAccess::SetRevision(&target.document(),
                                inverse ? entry.revision_after : entry.revision_before);
    return false;
  }
  return true;
}

bool History::Undo(EditTarget& target, std::string* error) {
  CloseGroups();
  if (undo_.empty()) return FailWith(error, "nothing to undo");
  HistoryEntry& entry = undo_.back();
  target.BeginStep(entry, HistoryStep::kUndo);
  if (!ApplyAll(target, entry, true, error)) return false;
  DocumentAccess::SetRevision(&target.document(), entry.revision_before);
  target.EndStep(entry, HistoryStep::kUndo);
  redo_.push_back(std::move(entry));
  undo_.pop_back();
  return true;
}

bool History::Redo(EditTarget& target, std::string* error) {
  CloseGroups();
  if (redo_.empty()) return FailWith(error, "nothing to redo");
  HistoryEntry& entry = redo_.back();
  target.BeginStep(entry, HistoryStep::kRedo);
  if (!ApplyAll(target, entry, false, error)) return false;
  DocumentAccess::SetRevision(&target.document(), entry.revision_after);
  target.EndStep(entry, HistoryStep::kRedo);
  undo_.push_back(std::move(entry));
  redo_.pop_back();
  return true;
}

bool History::Do(WorldDocument* document, const Edit& edit, std::string* error) {
  DocumentTarget target(document);
  return Do(target, edit, error);
}

bool History::Undo(WorldDocument* document, std::string* error) {
  DocumentTarget target(document);
  return Undo(target, error);
}

bool History::Redo(WorldDocument* document, std::string* error) {
  DocumentTarget target(document);
  return Redo(target, error);
}

void History::BeginGroup(std::string label) {
  if (group_depth_++ == 0) {
    group_label_ = std::move(label);
    group_has_entry_ = false;
  }
}

void History::EndGroup() {
  if (group_depth_ == 0) return;
  if (--group_depth_ == 0) group_has_entry_ = false;
}

void History::CloseGroups() {
  group_depth_ = 0;
  group_has_entry_ = false;
}

void History::Clear() {
  undo_.clear();
  redo_.clear();
  CloseGroups();
}

}  // namespace lamina::core
