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
#include "core/history.h"

#include <type_traits>
#include <utility>

#include "core/field_diff.h"
#include "core/mesh_storage.h"

namespace meshedit {
namespace {

// Appends the change of one field of one slot. `a`/`b` are null when the slot does not exist in that mesh.
template <class Get>
void compare(std::vector<FieldChange>& out, ElementRef element, const char* field, const HalfedgeMesh* a,
             const HalfedgeMesh* b, Get get) {
  using T = std::decay_t<decltype(get(*a))>;
  if (a && b) {
    const T before = get(*a);
    const T after = get(*b);
    field_diff::compare(out, element, field, &before, &after);
  } else if (b) {
    const T after = get(*b);
    field_diff::compare<T>(out, element, field, nullptr, &after);
  } else if (a) {
    const T before = get(*a);
    field_diff::compare<T>(out, element, field, &before, nullptr);
  }
}

// Calls fn(slot, in_before, in_after) for every slot of one kind that exists in either mesh.
template <class Fn>
void for_each_slot(const HalfedgeMesh& before, const HalfedgeMesh& after, ElementKind kind, Fn&& fn) {
  const uint32_t a = before.capacity(kind), b = after.capacity(kind);
  for (uint32_t i = 0; i < std::max(a, b); ++i) fn(i, i < a ? &before : nullptr, i < b ? &after : nullptr);
}

}  // namespace

std::vector<FieldChange> diff(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::vector<FieldChange> out;
  for_each_slot(before, after, ElementKind::Vertex, [&](uint32_t i, const HalfedgeMesh* a, const HalfedgeMesh* b) {
    const VertexId v(i);
    compare(out, v, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(v); });
    compare(out, v, "position", a, b, [&](const HalfedgeMesh& m) { return m.position(v); });
    compare(out, v, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(v); });
  });
  for_each_slot(before, after, ElementKind::Halfedge, [&](uint32_t i, const HalfedgeMesh* a, const HalfedgeMesh* b) {
    const HalfedgeId h(i);
    compare(out, h, "next", a, b, [&](const HalfedgeMesh& m) { return m.next(h); });
    compare(out, h, "twin", a, b, [&](const HalfedgeMesh& m) { return m.twin(h); });
    compare(out, h, "vertex", a, b, [&](const HalfedgeMesh& m) { return m.vertex(h); });
    compare(out, h, "edge", a, b, [&](const HalfedgeMesh& m) { return m.edge(h); });
    compare(out, h, "face", a, b, [&](const HalfedgeMesh& m) { return m.face(h); });
    compare(out, h, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(h); });
  });
  for_each_slot(before, after, ElementKind::Edge, [&](uint32_t i, const HalfedgeMesh* a, const HalfedgeMesh* b) {
    const EdgeId e(i);
    compare(out, e, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(e); });
    compare(out, e, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(e); });
  });
  for (const bool boundary : {false, true}) {
    const ElementKind kind = boundary ? ElementKind::Boundary : ElementKind::Face;
    for_each_slot(before, after, kind, [&](uint32_t i, const HalfedgeMesh* a, const HalfedgeMesh* b) {
      const FaceId f = boundary ? FaceId::boundary(i) : FaceId::face(i);
      compare(out, f, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(f); });
      compare(out, f, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(f); });
    });
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

void History::step(Entry& entry, HalfedgeMesh& mesh, bool forward) {
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
  Entry entry = std::move(undo_.back());
  undo_.pop_back();
  step(entry, mesh, false);
  redo_.push_back(std::move(entry));
  return true;
}

bool History::redo(HalfedgeMesh& mesh) {
  if (redo_.empty()) return false;
  Entry entry = std::move(redo_.back());
  redo_.pop_back();
  step(entry, mesh, true);
  undo_.push_back(std::move(entry));
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

}  // namespace meshedit
