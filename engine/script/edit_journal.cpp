// EditJournal (see edit_journal.h for the contract).
//
// Invariant kept here: undo and redo build the new state completely before assigning it to the mesh, so an edit
// that fails to replay (which would mean a bug) leaves the mesh as it was and drops the journal.
#include "script/internal/edit_journal.h"

#include <algorithm>
#include <span>
#include <utility>

namespace meshedit {

void EditJournal::drop() {
  base_.reset();
  edits_.clear();
  operations_.clear();
  redo_.clear();
  applied_ = 0;
}

bool EditJournal::follows(const HalfedgeMesh& mesh) {
  if (active() && mesh.version() != version_) drop();
  return active();
}

void EditJournal::before_change(const HalfedgeMesh& mesh, bool operation) {
  if (follows(mesh) || !operation) return;
  base_ = std::make_unique<HalfedgeMesh>(mesh);
  version_ = mesh.version();
}

void EditJournal::after_change(const HalfedgeMesh& mesh, RecordedEdit edit) {
  if (!active()) return;
  if (applied_ < edits_.size()) {
    edits_.resize(applied_);
    operations_.erase(std::lower_bound(operations_.begin(), operations_.end(), applied_), operations_.end());
  }
  redo_.clear();
  if (edits_.size() >= max_edits_) {
    drop();
    return;
  }
  if (edit.what == EditKind::Operation) operations_.push_back(edits_.size());
  edits_.push_back(std::move(edit));
  applied_ = edits_.size();
  version_ = mesh.version();
}

std::optional<std::string> EditJournal::undo(HalfedgeMesh& mesh) {
  if (!follows(mesh)) return std::nullopt;
  const auto last = std::lower_bound(operations_.begin(), operations_.end(), applied_);
  if (last == operations_.begin()) return std::nullopt;
  const size_t op = *(last - 1);
  std::string label = describe(edits_[op]);
  HalfedgeMesh state;
  try {
    state = replay(*base_, edits_, op);
  } catch (...) {
    drop();
    throw;
  }
  mesh.replace_with(std::move(state));
  redo_.push_back(applied_);
  applied_ = op;
  version_ = mesh.version();
  return label;
}

std::optional<std::string> EditJournal::redo(HalfedgeMesh& mesh) {
  if (!follows(mesh) || redo_.empty()) return std::nullopt;
  const size_t target = redo_.back();
  std::string label = describe(edits_[applied_]);
  HalfedgeMesh state = mesh;
  try {
    for (size_t i = applied_; i < target; ++i) apply_edit(state, edits_[i]);
  } catch (...) {
    drop();
    throw;
  }
  mesh.replace_with(std::move(state));
  redo_.pop_back();
  applied_ = target;
  version_ = mesh.version();
  return label;
}

}  // namespace meshedit
