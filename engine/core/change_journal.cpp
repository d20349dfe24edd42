// ChangeJournal and the mesh's JournalLink hooks (see change_journal.h for the invariants).
#include "core/change_journal.h"

#include <algorithm>
#include <new>
#include <utility>

#include "core/mesh_storage.h"

namespace meshedit {

void JournalLink::note_write(ElementKind kind, uint32_t slot) { journal_->note_write(kind, slot); }
void JournalLink::fall_back() noexcept { journal_->fall_back(); }

namespace {
size_t default_cap(const MeshShape& shape) {
  size_t slots = 0;
  for (const uint32_t c : shape.capacity) slots += c;
  return std::max<size_t>(4096, slots / 2);
}

HalfedgeMesh copy_of(const HalfedgeMesh& mesh) { return mesh; }
}  // namespace

ChangeJournal::SnapshotCopier ChangeJournal::snapshot_copier = copy_of;

ChangeJournal::ChangeJournal(HalfedgeMesh& mesh, std::optional<size_t> max_entries)
    : mesh_(&mesh),
      shape_before_(shape_of(mesh)),
      version_before_(mesh.version()),
      proven_before_(MeshStorage::proven_version(mesh)),
      max_entries_(max_entries ? *max_entries : default_cap(shape_before_)) {
  // A journal already attached (an edit nested in another) could not see this one's writes: it takes its snapshot.
  if (ChangeJournal* outer = MeshStorage::journal(mesh)) outer->fall_back();
  MeshStorage::set_journal(mesh, this);
}

ChangeJournal::~ChangeJournal() { detach(); }

bool ChangeJournal::attached() const { return MeshStorage::journal(*mesh_) == this; }

void ChangeJournal::detach() {
  if (attached()) MeshStorage::set_journal(*mesh_, nullptr);
}

void ChangeJournal::note_write(ElementKind kind, uint32_t slot) {
  if (slot >= shape_before_.capacity[static_cast<int>(kind)]) return;  // appended by this edit
  log_.push_back({kind, slot, read_slot(*mesh_, kind, slot)});
  if (log_.size() > max_entries_) fall_back();
}

void ChangeJournal::fall_back() noexcept {
  if (!attached()) return;
  detach();  // first: the copy and the undo below must not report to this journal
  try {
    snapshot_.emplace(snapshot_copier(*mesh_));
    undo_log(*snapshot_);
  } catch (const std::bad_alloc&) {
    // Out of memory for the copy (or for the undo on it). Only the copy was written: drop it, whole or half made.
    snapshot_.reset();
    state_before_lost_ = true;
  }
  std::vector<Entry>().swap(log_);  // frees the log without allocating (shrink_to_fit may allocate)
}

HalfedgeMesh ChangeJournal::take_snapshot() {
  HalfedgeMesh snapshot = std::move(*snapshot_);
  snapshot_.reset();
  return snapshot;
}

void ChangeJournal::undo_log(HalfedgeMesh& target) const {
  // A journal that follows writes slot by slot never sees an array shrink, so every logged slot is below the
  // target's capacities; the slots appended by the edit go last, with set_shape.
  for (auto it = log_.rbegin(); it != log_.rend(); ++it) write_slot(target, it->kind, it->slot, it->old);
  set_shape(target, shape_before_);
  MeshStorage::set_versions(target, version_before_, proven_before_);
}

bool ChangeJournal::revert() {
  detach();
  if (state_before_lost_) return false;
  if (snapshot_) {
    *mesh_ = take_snapshot();
    return true;
  }
  undo_log(*mesh_);
  log_.clear();
  return true;
}

}  // namespace meshedit
