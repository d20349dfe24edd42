// MeshDocument operations (see mesh_document.h for the contracts).
//
// Invariants kept here:
// - An operation runs under a change journal: a refusal reverts it (contents and version exactly), success keeps a
//   patch (or, when the journal fell back, its snapshot) for the history and `last`. The mesh is copied only for
//   snapshot-sized changes and when last.before cannot be rolled forward (see state_before).
// - A journal that ran out of memory for its snapshot (state_before_lost) leaves nothing to revert or record: the
//   mesh stays as the operation left it, refused or not, the history is cleared, `last` is marked not recorded and
//   the message says so (keep_unrecorded_change). No snapshot or patch is read from such a journal.
// - The diff is counted before it is formatted; above the cap it is not formatted at all.
#include "ui/mesh_document.h"

#include <algorithm>
#include <cstring>
#include <exception>

#include "core/change_journal.h"
#include "core/mesh_error.h"
#include "core/mesh_storage.h"

namespace meshedit {
namespace {

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Replaces doc.last by the change from `before` to the current mesh, given by `patch` when it was local (then the
// diff is made from the patch alone); `previous`: `before` is the state the document showed until now.
void record_last_change(MeshDocument& doc, std::string label, HalfedgeMesh before, std::optional<MeshPatch> patch,
                        bool previous = true) {
  LastChange last;
  if (previous) last.version_before = before.version();
  last.version_after = doc.mesh.version();
  last.label = std::move(label);
  const size_t limit = doc.limits.max_listed_changes;
  last.change_count = patch ? patch_change_count(*patch, limit) : count_changes(before, doc.mesh, limit);
  last.listed = last.change_count <= limit;
  if (last.listed) {
    last.changes = patch ? patch_diff(*patch) : diff(before, doc.mesh);
    last.change_count = last.changes.size();
    last.index = ChangeIndex(last.changes);
  }
  last.before = std::move(before);
  last.patch = std::move(patch);
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
}

// The mesh as it was just before the change `patch` made to doc.mesh (whose version() and proven version were then
// `version` and `proven`). Rolls last.before forward with last.patch when those describe exactly that state (time
// proportional to both edits; last.before is used up, the caller replaces `last`); otherwise copies the mesh and
// applies `patch` backward.
HalfedgeMesh state_before(MeshDocument& doc, const MeshPatch& patch, uint64_t version, uint64_t proven) {
  HalfedgeMesh before;
  if (doc.last.before && doc.last.patch && doc.last.version_after == version) {
    before = std::move(*doc.last.before);
    doc.last.before.reset();
    doc.last.patch->apply(before, true);
  } else {
    before = doc.mesh;
    patch.apply(before, false);
  }
  MeshStorage::set_versions(before, version, proven);
  return before;
}

std::string change_summary(const MeshDocument& doc) {
  const LastChange& last = doc.last;
  if (last.listed) return last.label + ": " + plural(last.change_count, "field", "fields") + " changed";
  return last.label + ": more than " + plural(doc.limits.max_listed_changes, "field", "fields") +
         " changed (too many to list)";
}

bool same_position(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0; }

// After an operation whose journal lost the state before it (memory ran out for its snapshot): nothing can put the
// mesh back, so it stays as the operation left it, whether `check` accepted or refused. The history is cleared (its
// entries start from a state the mesh may no longer be in), `last` says a change happened that was not recorded, and
// the message gives the outcome and why undo history is gone. `version_before`: the mesh's version() before.
void keep_unrecorded_change(MeshDocument& doc, const std::string& label, const Check& check, ElementRef culprit,
                            uint64_t version_before) {
  // The document's versions only grow: an operation that assigned an older mesh must not pass for a state that a
  // cache (validation, renderer) already saw.
  if (doc.mesh.version() <= version_before) doc.mesh.bump_version_above(version_before);
  doc.history.clear();
  LastChange last;
  last.label = label;
  last.recorded = false;
  last.version_after = doc.mesh.version();
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
  const std::string cause = "memory ran out saving the mesh before it, so ";
  if (check.ok) {
    set_message(doc, Severity::Warning, label + ": done, but " + cause + "it cannot be undone: undo history cleared");
  } else {
    set_message(doc, Severity::Error,
                label + ": " + check.reason + "; " + cause +
                    "it could not be undone: the mesh is as the operation left it, undo history cleared",
                culprit);
  }
}

}  // namespace

const char* field_name(MeshField field) {
  switch (field) {
    case MeshField::Next: return "next";
    case MeshField::Twin: return "twin";
    case MeshField::Vertex: return "vertex";
    case MeshField::Edge: return "edge";
    case MeshField::Face: return "face";
    case MeshField::Halfedge: return "halfedge";
    case MeshField::Position: return "position";
    case MeshField::Alive: return "alive";
  }
  return "?";
}

std::optional<MeshField> parse_field(std::string_view name) {
  for (int i = 0; i < kMeshFieldCount; ++i) {
    const auto field = static_cast<MeshField>(i);
    if (name == field_name(field)) return field;
  }
  return std::nullopt;
}

ChangeIndex::ChangeIndex(const std::vector<FieldChange>& changes) {
  cells_.reserve(changes.size());
  for (const FieldChange& change : changes) {
    if (const auto field = parse_field(change.field)) cells_.insert(key(change.element, *field));
    if (element_set_.insert(change.element).second) elements_.push_back(change.element);
  }
}

MeshDocument make_document(HalfedgeMesh mesh, std::string path, DocumentLimits limits) {
  MeshDocument doc;
  doc.limits = limits;
  replace_mesh(doc, std::move(mesh), std::move(path));
  return doc;
}

void replace_mesh(MeshDocument& doc, HalfedgeMesh mesh, std::string path) {
  doc.history = History(256, doc.limits.history_budget_bytes);
  const uint64_t old_version = doc.mesh.version();
  doc.mesh = std::move(mesh);
  doc.mesh.bump_version_above(old_version);  // no cache may take the new mesh for the old one
  doc.path = std::move(path);
  LastChange last;
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
  doc.loop = LoopStepper{};
  ++doc.generation;
  const std::string name = doc.path.empty() ? std::string("new mesh") : doc.path;
  set_message(doc, Severity::Info,
              "opened " + name + ": " + plural(doc.mesh.num_vertices(), "vertex", "vertices") + ", " +
                  plural(doc.mesh.num_faces(), "face", "faces"));
}

void set_message(MeshDocument& doc, Severity severity, std::string text, ElementRef element) {
  doc.message = DocumentMessage{severity, std::move(text), element};
}

namespace detail {

Check apply_check_operation(MeshDocument& doc, const std::string& label,
                            const std::function<Check(HalfedgeMesh&)>& op) {
  ChangeJournal journal(doc.mesh);
  Check check;
  Severity severity = Severity::Warning;
  ElementRef culprit;
  try {
    check = op(doc.mesh);
  } catch (const MeshError& error) {
    check = Check::no(error.what());
    severity = Severity::Error;
    culprit = error.element();
  } catch (const std::exception& error) {
    check = Check::no(error.what());
    severity = Severity::Error;
  }
  journal.detach();
  if (!check.ok && check.reason.empty()) check.reason = "refused";
  if (journal.state_before_lost()) {
    keep_unrecorded_change(doc, label, check, culprit, journal.version_before());
    return check;
  }
  if (!check.ok) {
    journal.revert();
    set_message(doc, severity, label + ": " + check.reason, culprit);
    return check;
  }
  const uint64_t version_before = journal.version_before();
  if (doc.mesh.version() == version_before) {
    set_message(doc, Severity::Info, label + ": nothing changed");
    return check;
  }
  if (journal.has_snapshot()) {
    HalfedgeMesh before = journal.take_snapshot();
    doc.history.record(label, before);
    record_last_change(doc, label, std::move(before), std::nullopt);
  } else {
    MeshPatch patch = make_patch(journal, doc.mesh);
    HalfedgeMesh before = state_before(doc, patch, version_before, journal.proven_version_before());
    doc.history.record(label, patch, version_before);
    record_last_change(doc, label, std::move(before), std::move(patch));
  }
  set_message(doc, Severity::Info, change_summary(doc));
  return check;
}

}  // namespace detail

namespace {

// Undo or redo one step; `last` becomes the diff of the step itself ("undo flip e5").
bool step_history(MeshDocument& doc, bool forward) {
  const char* word = forward ? "redo" : "undo";
  if (!(forward ? doc.history.can_redo() : doc.history.can_undo())) {
    set_message(doc, Severity::Warning, std::string("nothing to ") + word);
    return false;
  }
  const std::string label = std::string(word) + " " + (forward ? doc.history.redo_label() : doc.history.undo_label());
  const MeshPatch* entry_patch = forward ? doc.history.redo_patch() : doc.history.undo_patch();
  if (!entry_patch) {
    // A snapshot entry: the whole mesh is swapped, so the diff needs the whole state before.
    HalfedgeMesh before = doc.mesh;
    forward ? doc.history.redo(doc.mesh) : doc.history.undo(doc.mesh);
    record_last_change(doc, label, std::move(before), std::nullopt);
  } else {
    // This step applies the entry's patch forward (redo) or backward (undo).
    MeshPatch step = forward ? *entry_patch : entry_patch->reversed();
    const uint64_t version = doc.mesh.version(), proven = MeshStorage::proven_version(doc.mesh);
    forward ? doc.history.redo(doc.mesh) : doc.history.undo(doc.mesh);
    HalfedgeMesh before = state_before(doc, step, version, proven);
    record_last_change(doc, label, std::move(before), std::move(step));
  }
  set_message(doc, Severity::Info, change_summary(doc));
  return true;
}

}  // namespace

bool undo(MeshDocument& doc) { return step_history(doc, false); }
bool redo(MeshDocument& doc) { return step_history(doc, true); }

void show_state(MeshDocument& doc, HalfedgeMesh mesh, std::string label, std::optional<HalfedgeMesh> from) {
  const bool previous = !from;
  HalfedgeMesh before = from ? std::move(*from) : doc.mesh;
  const uint64_t old_version = doc.mesh.version();
  doc.mesh = std::move(mesh);
  doc.mesh.bump_version_above(old_version);  // caches keyed by version must not take it for the old state
  record_last_change(doc, std::move(label), std::move(before), std::nullopt, previous);
  set_message(doc, Severity::Info, change_summary(doc));
}

size_t count_changes(const HalfedgeMesh& before, const HalfedgeMesh& after, size_t limit) {
  size_t count = 0;
  // Slots present in only one of the two meshes: every field of theirs counts (diff lists them all).
  auto one_sided = [&](ElementKind kind, size_t fields) {
    const uint32_t a = before.capacity(kind), b = after.capacity(kind);
    count += size_t(std::max(a, b) - std::min(a, b)) * fields;
    return std::min(a, b);
  };
  const uint32_t vertices = one_sided(ElementKind::Vertex, 3);
  const uint32_t halfedges = one_sided(ElementKind::Halfedge, 6);
  const uint32_t edges = one_sided(ElementKind::Edge, 2);
  const uint32_t faces = one_sided(ElementKind::Face, 2);
  const uint32_t boundaries = one_sided(ElementKind::Boundary, 2);
  if (count > limit) return count;
  for (uint32_t i = 0; i < vertices; ++i) {
    const VertexId v(i);
    count += (before.halfedge(v) != after.halfedge(v)) + !same_position(before.position(v), after.position(v)) +
             (before.alive(v) != after.alive(v));
    if (count > limit) return count;
  }
  for (uint32_t i = 0; i < halfedges; ++i) {
    const HalfedgeId h(i);
    count += (before.next(h) != after.next(h)) + (before.twin(h) != after.twin(h)) +
             (before.vertex(h) != after.vertex(h)) + (before.edge(h) != after.edge(h)) +
             (before.face(h) != after.face(h)) + (before.alive(h) != after.alive(h));
    if (count > limit) return count;
  }
  for (uint32_t i = 0; i < edges; ++i) {
    const EdgeId e(i);
    count += (before.halfedge(e) != after.halfedge(e)) + (before.alive(e) != after.alive(e));
    if (count > limit) return count;
  }
  for (const bool boundary : {false, true}) {
    const uint32_t n = boundary ? boundaries : faces;
    for (uint32_t i = 0; i < n; ++i) {
      const FaceId f = boundary ? FaceId::boundary(i) : FaceId::face(i);
      count += (before.halfedge(f) != after.halfedge(f)) + (before.alive(f) != after.alive(f));
      if (count > limit) return count;
    }
  }
  return count;
}

namespace {
template <class T, class Compute>
const T& cached(VersionCache<T>& cache, const MeshDocument& doc, Compute&& compute) {
  if (!cache.filled || cache.generation != doc.generation || cache.version != doc.mesh.version()) {
    cache.value = compute();
    cache.filled = true;
    cache.generation = doc.generation;
    cache.version = doc.mesh.version();
    ++cache.computations;
  }
  return cache.value;
}
}  // namespace

const ValidationReport& cached_validation(MeshDocument& doc) {
  return cached(doc.validation, doc, [&] { return validate(doc.mesh); });
}

const MeshStats& cached_stats(MeshDocument& doc) {
  return cached(doc.stats, doc, [&] { return compute_stats(doc.mesh); });
}

bool validation_is_current(const MeshDocument& doc) {
  return doc.validation.filled && doc.validation.generation == doc.generation &&
         doc.validation.version == doc.mesh.version();
}

}  // namespace meshedit
