// diff() and History (see history.h for the contracts).
//
// Invariants kept here:
// - diff() compares raw values (positions bit for bit, so -0 vs 0 and NaN payloads count as changes) and
//   formats only what differs; it reads a slot only below that mesh's capacity, so two unrelated meshes,
//   or the arguments swapped, give a longer list but never a crash.
// - History never holds more than max_depth undo entries, nor more than max_bytes in them unless that would leave
//   fewer than kMinDepth; after undo/redo the mesh's version is above
//   every version it had before, so caches keyed by version refresh. A patch entry ends with the version a snapshot
//   entry would give: max(the restored state's recorded version, the version before the step) + 1.
// - undo() and redo() make room in the list the entry moves to before they step, and a step fails (out of memory)
//   only in MeshPatch::apply, before it writes; so a failed undo or redo leaves mesh and lists as they were.
#include "core/history.h"

#include <algorithm>
#include <utility>

#include "core/field_diff.h"
#include "core/mesh_storage.h"

namespace meshedit {

std::vector<FieldChange> diff(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::vector<FieldChange> out;
  for (int k = 0; k < kElementKindCount; ++k) {
    const auto kind = static_cast<ElementKind>(k);
    const uint32_t in_before = before.capacity(kind), in_after = after.capacity(kind);
    for (uint32_t slot = 0; slot < std::max(in_before, in_after); ++slot) {
      SlotValues a, b;
      if (slot < in_before) a = read_slot(before, kind, slot);
      if (slot < in_after) b = read_slot(after, kind, slot);
      field_diff::for_each_field(kind, slot, slot < in_before ? &a : nullptr, slot < in_after ? &b : nullptr,
                                 [&](ElementRef element, const char* name, const auto* x, const auto* y) {
                                   field_diff::compare(out, element, name, x, y);
                                 });
    }
  }
  return out;
}

void History::record(std::string label, HalfedgeMesh before) {
  redo_.clear();
  Entry entry;
  entry.label = std::move(label);
  entry.version = before.version();
  entry.mesh = std::move(before);
  undo_.push_back(std::move(entry));
  trim();
}

void History::record(std::string label, MeshPatch patch, uint64_t version_before) {
  redo_.clear();
  Entry entry;
  entry.label = std::move(label);
  entry.version = version_before;
  entry.patch = std::move(patch);
  undo_.push_back(std::move(entry));
  trim();
}

std::vector<std::string> History::undo_labels() const {
  std::vector<std::string> labels;
  labels.reserve(undo_.size());
  for (const Entry& entry : undo_) labels.push_back(entry.label);
  return labels;
}

const std::string& History::undo_label() const {
  static const std::string kNone;
  return undo_.empty() ? kNone : undo_.back().label;
}

const std::string& History::redo_label() const {
  static const std::string kNone;
  return redo_.empty() ? kNone : redo_.back().label;
}

const MeshPatch* History::undo_patch() const {
  return undo_.empty() || !undo_.back().patch ? nullptr : &*undo_.back().patch;
}

const MeshPatch* History::redo_patch() const {
  return redo_.empty() || !redo_.back().patch ? nullptr : &*redo_.back().patch;
}

const HalfedgeMesh* History::undo_snapshot() const {
  return undo_.empty() || !undo_.back().mesh ? nullptr : &*undo_.back().mesh;
}

const HalfedgeMesh* History::redo_snapshot() const {
  return redo_.empty() || !redo_.back().mesh ? nullptr : &*redo_.back().mesh;
}

void History::step(Entry& entry, HalfedgeMesh& mesh, bool forward) {
  // Only apply() may fail (out of memory), and it fails before it changes anything: the entry is updated after it.
  const uint64_t seen = mesh.version();
  if (entry.mesh) {
    std::swap(*entry.mesh, mesh);  // the entry now holds the state left, with its version
  } else {
    entry.patch->apply(mesh, forward);
    MeshStorage::set_versions(mesh, entry.version, MeshStorage::proven_version(mesh));
  }
  entry.version = seen;
  mesh.bump_version_above(seen);
}

bool History::undo(HalfedgeMesh& mesh) {
  if (undo_.empty()) return false;
  // Room in the redo list first: after the step, nothing may fail.
  if (redo_.size() == redo_.capacity()) redo_.reserve(std::max<size_t>(8, 2 * redo_.capacity()));
  step(undo_.back(), mesh, false);
  redo_.push_back(std::move(undo_.back()));
  undo_.pop_back();
  return true;
}

bool History::redo(HalfedgeMesh& mesh) {
  if (redo_.empty()) return false;
  undo_.emplace_back();  // room first (a deque cannot reserve): after the step, nothing may fail
  try {
    step(redo_.back(), mesh, true);
  } catch (...) {
    undo_.pop_back();
    throw;
  }
  undo_.back() = std::move(redo_.back());
  redo_.pop_back();
  trim();
  return true;
}

size_t History::bytes_of(const Entry& entry) {
  if (entry.mesh) return entry.mesh->memory_bytes();
  return entry.patch ? entry.patch->slots.capacity() * sizeof(SlotChange) : 0;
}

void History::trim() {
  while (undo_.size() > max_depth_) undo_.pop_front();
  size_t total = 0;
  for (const Entry& entry : undo_) total += bytes_of(entry);
  while (total > max_bytes_ && undo_.size() > kMinDepth) {
    total -= bytes_of(undo_.front());
    undo_.pop_front();
  }
}

void History::clear() {
  undo_.clear();
  redo_.clear();
}

void History::reset(size_t max_depth, size_t max_bytes) {
  clear();
  max_depth_ = max_depth;
  max_bytes_ = max_bytes;
}

}  // namespace meshedit
