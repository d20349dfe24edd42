// MeshDocument operations (see mesh_document.h for the contracts).
//
// Invariants kept here:
// - An operation is judged by its Check and by mesh.version(): a refusal restores the snapshot only if the
//   version moved, so a well-behaved refusal costs no second copy.
// - The diff is counted before it is formatted; above the cap it is not formatted at all.
#include "ui/mesh_document.h"

#include <algorithm>
#include <cstring>
#include <exception>

#include "core/mesh_error.h"

namespace meshedit {
namespace {

size_t history_depth(const HalfedgeMesh& mesh, const DocumentLimits& limits) {
  const size_t bytes = std::max<size_t>(mesh.memory_bytes(), 1);
  return std::clamp<size_t>(limits.history_budget_bytes / bytes, 4, 256);
}

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Replaces doc.last by the change from `before` to the current mesh; `previous`: `before` is the state the document
// showed until now.
void record_last_change(MeshDocument& doc, std::string label, HalfedgeMesh before, bool previous = true) {
  LastChange last;
  if (previous) last.version_before = before.version();
  last.version_after = doc.mesh.version();
  last.label = std::move(label);
  last.change_count = count_changes(before, doc.mesh, doc.limits.max_listed_changes);
  last.listed = last.change_count <= doc.limits.max_listed_changes;
  if (last.listed) {
    last.changes = diff(before, doc.mesh);
    last.change_count = last.changes.size();
    last.index = ChangeIndex(last.changes);
  }
  last.before = std::move(before);
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
}

std::string change_summary(const MeshDocument& doc) {
  const LastChange& last = doc.last;
  if (last.listed) return last.label + ": " + plural(last.change_count, "field", "fields") + " changed";
  return last.label + ": more than " + plural(doc.limits.max_listed_changes, "field", "fields") +
         " changed (too many to list)";
}

bool same_position(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0; }

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
  doc.history = History(history_depth(mesh, doc.limits));
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
  HalfedgeMesh before = doc.mesh;
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
  if (!check.ok) {
    if (doc.mesh.version() != before.version()) doc.mesh = std::move(before);
    if (check.reason.empty()) check.reason = "refused";
    set_message(doc, severity, label + ": " + check.reason, culprit);
    return check;
  }
  if (doc.mesh.version() == before.version()) {
    set_message(doc, Severity::Info, label + ": nothing changed");
    return check;
  }
  doc.history.record(label, before);
  record_last_change(doc, label, std::move(before));
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
  HalfedgeMesh before = doc.mesh;
  forward ? doc.history.redo(doc.mesh) : doc.history.undo(doc.mesh);
  record_last_change(doc, label, std::move(before));
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
  record_last_change(doc, std::move(label), std::move(before), previous);
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
