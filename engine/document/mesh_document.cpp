// MeshDocument operations (see mesh_document.h for the contracts).
//
// Invariants kept here:
// - An operation runs under a change journal: a refusal reverts it (contents and version exactly), success keeps a
//   patch (or, when the journal fell back, its snapshot) for the history and `last`. The mesh is copied only for
//   snapshot-sized changes whose diff is listed (last.before, for the renderer); a local change keeps only its patch.
// - A journal that ran out of memory for its snapshot (state_before_lost) leaves nothing to revert or record: the
//   mesh stays as the operation left it, refused or not, the history is cleared, `last` is marked not recorded and
//   the message says so (keep_unrecorded_change). No snapshot or patch is read from such a journal.
// - Whatever allocates is done before the document is changed, or after a change that is kept whatever happens:
//   `last` is built aside and moved in (set_last_change), the operation's edit and the history's step are done
//   before their bookkeeping. So running out of memory part-way leaves one of two states, the one before or the one
//   after, and keep_unrecorded_change is the only way to the second one without a record.
// - Whether an operation changed anything is decided by contents when the journal holds a snapshot (an assigned
//   mesh may carry any version), by version() otherwise (every setter bumps it); a kept change always ends with a
//   version() above the one before.
// - The diff is counted before it is formatted; above the cap it is not formatted at all.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   recording a change              change_summary, set_last_change, record_local_change, record_whole_change,
//                                   keep_unrecorded_change
//   running an operation            run_operation, nothing_changed, record_operation
//   fields, documents and messages  field_name, parse_field, ChangeIndex, make_document, replace_mesh, set_message
//   operations                      detail::apply_check_operation: an operation under a journal
//   undo and redo                   record_step, step_history, undo, redo, show_state
//   counting and caches             count_changes, the version caches (validation, stats)
#include "document/mesh_document.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <new>

#include "core/change_journal.h"
#include "core/mesh_error.h"
#include "core/parallel_for.h"
#include "core/patch_check.h"
#include "core/quick_check.h"
#include "core/translation.h"
#include "document/edge_edit_label.h"

namespace meshedit {
namespace {

// ---- recording a change ----------------------------------------------------------------------------

// A change's label as the status line shows it, in the window's language ("undo flip e5", "Loop subdivision"); the
// label itself stays English, as the history keeps it and the window reads it back (edge_edit_label.h).
std::string shown_label(const std::string& label) {
  std::string_view change = label;
  const char* step = nullptr;  // the undo or redo in front
  if (change.substr(0, 5) == "undo ") step = "undo {change}";
  if (change.substr(0, 5) == "redo ") step = "redo {change}";
  if (step) change.remove_prefix(5);
  std::string shown;
  const std::optional<EdgeEditLabel> edit = read_edge_edit_label(change);
  if (edit && !edit->undone && edge_edit_label(edit->operation, edit->edge) == change) {
    const MessageParts edge = {{"edge", format_id(edit->edge)}};
    switch (edit->operation) {
      case EdgeOperation::Flip: shown = tr_format("flip {edge}", edge); break;
      case EdgeOperation::Split: shown = tr_format("split {edge}", edge); break;
      case EdgeOperation::Collapse: shown = tr_format("collapse {edge}", edge); break;
    }
  } else {
    shown = tr(std::string(change));  // the edits' fixed labels ("Loop subdivision"); others stay as they are
  }
  return step ? tr_format(step, {{"change", shown}}) : shown;
}

// The status line for `last` ("flip e5: 12 fields changed").
std::string change_summary(const LastChange& last, const DocumentLimits& limits) {
  if (last.listed) {
    const MessageParts parts = {{"change", shown_label(last.label)}, {"count", std::to_string(last.change_count)}};
    if (last.change_count == 1) return tr_format("{change}: {count} field changed", parts);
    return tr_format("{change}: {count} fields changed", parts);
  }
  const MessageParts parts = {{"change", shown_label(last.label)},
                              {"count", std::to_string(limits.max_listed_changes)}};
  return tr_format(limits.max_listed_changes == 1 ? "{change}: more than {count} field changed (too many to list)"
                                                  : "{change}: more than {count} fields changed (too many to list)",
                   parts);
}

// The new `last` for a change to the current mesh from the state before it, whose version() was `version_before`:
// given by `patch` when it was local (the diff is then made from the patch alone), by `before` otherwise. `previous`:
// that state is the one the document showed until now. Its `before`, `patch` and `serial` are left for the caller.
// Out of memory, throws std::bad_alloc; the document is not touched.
LastChange describe_change(const MeshDocument& doc, std::string label, uint64_t version_before,
                           const HalfedgeMesh* before, const MeshPatch* patch, bool previous) {
  LastChange last;
  if (previous) last.version_before = version_before;
  last.version_after = doc.mesh.version();
  last.label = std::move(label);
  const size_t limit = doc.limits.max_listed_changes;
  last.change_count = patch ? patch_change_count(*patch, limit) : count_changes(*before, doc.mesh, limit);
  last.listed = last.change_count <= limit;
  if (last.listed) {
    last.changes = patch ? patch_diff(*patch) : diff(*before, doc.mesh);
    last.change_count = last.changes.size();
    last.index = ChangeIndex(last.changes);
  }
  return last;
}

// Makes `last` (built aside) the document's and returns the status line for it. Out of memory, throws std::bad_alloc
// with doc.last as it was.
std::string set_last_change(MeshDocument& doc, LastChange last) {
  std::string summary = change_summary(last, doc.limits);
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
  return summary;
}

// `last` for a local change given by its patch: no copy of the mesh (the renderer and the validation read the state
// before through the patch).
std::string record_local_change(MeshDocument& doc, std::string label, uint64_t version_before, MeshPatch patch) {
  LastChange last = describe_change(doc, std::move(label), version_before, nullptr, &patch, true);
  last.patch = std::move(patch);
  return set_last_change(doc, std::move(last));
}

// `last` for a whole-mesh change from `before`. A copy of the state before is kept only when the diff is listed: the
// renderer rewrites such a change in place from it. Beyond the list nothing reads it, and a copy of a mesh of millions
// of faces costs a second or so in fresh memory. `before` is moved in when given as an rvalue, copied otherwise.
template <class Before>
std::string record_whole_change(MeshDocument& doc, std::string label, Before&& before, bool previous = true) {
  LastChange last = describe_change(doc, std::move(label), before.version(), &before, nullptr, previous);
  if (last.listed) last.before.emplace(std::forward<Before>(before));
  return set_last_change(doc, std::move(last));
}

bool same_position(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0; }

// After a change to doc.mesh that cannot be recorded (memory ran out): the change stays, `last` only names it (not
// recorded), version() moves above `version_before` if the change left it there (the document's versions only
// grow: an operation that assigned an older mesh must not pass for a state a cache already saw), and the history is
// cleared unless `keep_history` (it still ends with this change, or it is not the change's to touch: show_state).
// Allocates nothing but the copy of the label, and does without it when even that fails. The caller sets the
// message.
void keep_unrecorded_change(MeshDocument& doc, const std::string& label, uint64_t version_before, bool keep_history) {
  if (doc.mesh.version() <= version_before) doc.mesh.bump_version_above(version_before);
  if (!keep_history) doc.history.clear();
  LastChange last;
  last.recorded = false;
  last.version_after = doc.mesh.version();
  last.serial = doc.last.serial + 1;
  try {
    last.label = label;
  } catch (const std::bad_alloc&) {
    // `last` without its name rather than no `last`: the message still names the change when it can.
  }
  doc.last = std::move(last);
}

// The message after an operation whose journal lost the state before it (see keep_unrecorded_change).
void report_state_before_lost(MeshDocument& doc, const std::string& label, const Check& check, ElementRef culprit) {
  if (check.ok) {
    set_message_noexcept(doc, Severity::Warning, [&] {
      return tr_format(
          "{change}: done, but memory ran out saving the mesh before it, so it cannot be undone: undo "
          "history cleared",
          {{"change", shown_label(label)}});
    });
  } else {
    set_message_noexcept(
        doc, Severity::Error,
        [&] {
          return tr_format(
              "{change}: {reason}; memory ran out saving the mesh before it, so it could not be undone: "
              "the mesh is as the operation left it, undo history cleared",
              {{"change", shown_label(label)}, {"reason", check.reason}});
        },
        culprit);
  }
}

// ---- running an operation --------------------------------------------------------------------------

// What running an operation gave: its Check, or the refusal an exception became.
struct OperationOutcome {
  Check check;
  Severity severity = Severity::Warning;  // of the message, when refused
  ElementRef culprit;                     // a MeshError's element
  bool out_of_memory = false;             // std::bad_alloc: the reason is kMemoryRanOut
};

// Runs `op`; an exception becomes a refusal whose reason is its message (Error), std::bad_alloc one whose reason is
// kMemoryRanOut, also when memory runs out copying another exception's message. Never throws a std::exception.
OperationOutcome run_operation(detail::OperationRef op, HalfedgeMesh& mesh) {
  OperationOutcome outcome;
  try {
    try {
      outcome.check = op(mesh);
    } catch (const std::bad_alloc&) {
      throw;  // to the handler below
    } catch (const MeshError& error) {
      outcome.severity = Severity::Error;
      outcome.culprit = error.element();
      outcome.check = Check::no(error.what());
    } catch (const std::exception& error) {
      outcome.severity = Severity::Error;
      outcome.check = Check::no(error.what());
    }
  } catch (const std::bad_alloc&) {
    outcome.severity = Severity::Error;
    outcome.culprit = {};
    outcome.out_of_memory = true;
    outcome.check = Check::no(kMemoryRanOut);  // fits std::string's inline buffer: allocates nothing
  }
  return outcome;
}

// True when the operation the journal watched left the mesh as it found it. A snapshot means the mesh was written
// wholesale (an assignment may bring any version, even the old one): then only the contents tell.
bool nothing_changed(const ChangeJournal& journal, const HalfedgeMesh& mesh) {
  if (journal.has_snapshot()) return journal.snapshot().same_as(mesh);
  return mesh.version() == journal.version_before();
}

// Keeps the change the journal watched (`op` succeeded and changed the mesh): the state before goes to the history,
// `last` becomes the diff and the message summarises it. Out of memory, the change is kept without its record (see
// keep_unrecorded_change) and a Warning says what was lost.
void record_operation(MeshDocument& doc, const std::string& label, ChangeJournal& journal) {
  const uint64_t version_before = journal.version_before();
  // An assigned mesh may bring a version the document already had: versions only grow, or caches keyed by version
  // (renderer, validation) would keep describing the old contents.
  if (doc.mesh.version() <= version_before) doc.mesh.bump_version_above(version_before);
  bool in_history = false;
  try {
    std::string summary;
    if (journal.has_snapshot()) {
      // `last` is described before the snapshot moves to the history (so out of memory there, the history is cleared
      // rather than kept), and copies the snapshot only when it keeps it: a long whole-mesh change copies nothing.
      HalfedgeMesh before = journal.take_snapshot();
      LastChange last = describe_change(doc, label, before.version(), &before, nullptr, true);
      if (last.listed) last.before = before;
      doc.history.record(label, std::move(before));
      in_history = true;
      summary = set_last_change(doc, std::move(last));
    } else {
      MeshPatch patch = make_patch(journal, doc.mesh);
      doc.history.record(label, patch, version_before);
      in_history = true;
      summary = record_local_change(doc, label, version_before, std::move(patch));
    }
    set_message(doc, Severity::Info, std::move(summary));
  } catch (const std::bad_alloc&) {
    keep_unrecorded_change(doc, label, version_before, in_history);
    set_message_noexcept(doc, Severity::Warning, [&] {
      const MessageParts parts = {{"change", shown_label(label)}};
      return in_history ? tr_format("{change}: done, but memory ran out listing its changes", parts)
                        : tr_format("{change}: done, but memory ran out recording it: undo history cleared", parts);
    });
  }
}

}  // namespace

// ---- fields, documents and messages ----------------------------------------------------------------

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
  // Nothing here allocates but the message: the mesh and the path are moved in, the history emptied.
  const uint64_t old_version = doc.mesh.version();
  doc.mesh = std::move(mesh);
  doc.mesh.bump_version_above(old_version);  // no cache may take the new mesh for the old one
  doc.history.reset(256, doc.limits.history_budget_bytes);
  doc.path = std::move(path);
  LastChange last;
  last.serial = doc.last.serial + 1;
  doc.last = std::move(last);
  doc.loop = LoopStepper{};
  ++doc.generation;
  set_message_noexcept(doc, Severity::Info, [&] {
    const std::string name = doc.path.empty() ? std::string(tr("new mesh")) : doc.path;
    const size_t vertices = doc.mesh.num_vertices(), faces = doc.mesh.num_faces();
    const MessageParts v = {{"count", std::to_string(vertices)}}, f = {{"count", std::to_string(faces)}};
    return tr_format("opened {file}: {vertices}, {faces}",
                     {{"file", name},
                      {"vertices", tr_format(vertices == 1 ? "{count} vertex" : "{count} vertices", v)},
                      {"faces", tr_format(faces == 1 ? "{count} face" : "{count} faces", f)}});
  });
}

void set_message(MeshDocument& doc, Severity severity, std::string text, ElementRef element) {
  doc.message = DocumentMessage{severity, std::move(text), element};
}

void set_memory_ran_out_message(MeshDocument& doc, Severity severity, ElementRef element) noexcept {
  doc.message.severity = std::max(severity, Severity::Warning);
  doc.message.element = element;
  doc.message.text.assign(kMemoryRanOut);  // shorter than any string's capacity: written in place
}

// ---- operations ------------------------------------------------------------------------------------

namespace detail {

Check apply_check_operation(MeshDocument& doc, const std::string& label, OperationRef op) {
  ChangeJournal journal(doc.mesh);  // allocates nothing until the operation writes
  OperationOutcome outcome = run_operation(op, doc.mesh);
  Check& check = outcome.check;
  journal.detach();
  if (!check.ok && check.reason.empty()) check.reason = "refused";
  if (journal.state_before_lost()) {
    keep_unrecorded_change(doc, label, journal.version_before(), false);
    report_state_before_lost(doc, label, check, outcome.culprit);
    return std::move(check);
  }
  if (!check.ok) {
    journal.revert();
    set_message_noexcept(
        doc, outcome.severity,
        [&] {
          const MessageParts parts = {{"change", shown_label(label)}, {"reason", check.reason}};
          return outcome.out_of_memory ? tr_format("{change}: memory ran out; the mesh is as it was", parts)
                                       : tr_format("{change}: {reason}", parts);
        },
        outcome.culprit);
    return std::move(check);
  }
  if (nothing_changed(journal, doc.mesh)) {
    journal.revert();  // also puts back the version an assignment of the same contents brought
    set_message_noexcept(doc, Severity::Info, [&] {
      return tr_format("{change}: nothing changed", {{"change", shown_label(label)}});
    });
    return std::move(check);
  }
  record_operation(doc, label, journal);
  return std::move(check);
}

}  // namespace detail

// ---- undo and redo ---------------------------------------------------------------------------------

namespace {

// `last` for the undo (redo) step just taken, whose entry now heads the redo (undo) list, from the state before it
// (whose version() was `version`); returns the status line. Out of memory, throws std::bad_alloc with `last` as it
// was.
std::string record_step(MeshDocument& doc, const std::string& label, bool forward, uint64_t version) {
  const MeshPatch* entry_patch = forward ? doc.history.undo_patch() : doc.history.redo_patch();
  if (!entry_patch) {
    // A snapshot entry: it now holds the whole state the step left, with its version.
    const HalfedgeMesh& left = forward ? *doc.history.undo_snapshot() : *doc.history.redo_snapshot();
    return record_whole_change(doc, label, left);
  }
  // The step applied the entry's patch forward (redo) or backward (undo).
  MeshPatch step = forward ? *entry_patch : entry_patch->reversed();
  return record_local_change(doc, label, version, std::move(step));
}

// Undo or redo one step; `last` becomes the diff of the step itself ("undo flip e5"). The step is all or nothing;
// only what comes after it (`last`) may be lost to a lack of memory.
bool step_history(MeshDocument& doc, bool forward) {
  const char* word = forward ? "redo" : "undo";
  if (!(forward ? doc.history.can_redo() : doc.history.can_undo())) {
    set_message_noexcept(doc, Severity::Warning,
                         [&] { return std::string(forward ? tr("nothing to redo") : tr("nothing to undo")); });
    return false;
  }
  std::string label;
  try {
    label = std::string(word) + " " + (forward ? doc.history.redo_label() : doc.history.undo_label());
  } catch (const std::bad_alloc&) {
    set_memory_ran_out_message(doc, Severity::Error);
    return false;
  }
  const uint64_t version = doc.mesh.version();
  try {
    forward ? doc.history.redo(doc.mesh) : doc.history.undo(doc.mesh);
  } catch (const std::bad_alloc&) {
    set_message_noexcept(doc, Severity::Error, [&] {
      const MessageParts parts = {{"change", shown_label(label)}};
      return forward ? tr_format("{change}: memory ran out; nothing was redone, the mesh is as it was", parts)
                     : tr_format("{change}: memory ran out; nothing was undone, the mesh is as it was", parts);
    });
    return false;
  }
  try {
    set_message(doc, Severity::Info, record_step(doc, label, forward, version));
  } catch (const std::bad_alloc&) {
    keep_unrecorded_change(doc, label, version, true);  // the history took the step: it still matches
    set_message_noexcept(doc, Severity::Warning, [&] {
      return tr_format("{change}: done, but memory ran out listing its changes", {{"change", shown_label(label)}});
    });
  }
  return true;
}

}  // namespace

bool undo(MeshDocument& doc) { return step_history(doc, false); }
bool redo(MeshDocument& doc) { return step_history(doc, true); }

void show_state(MeshDocument& doc, HalfedgeMesh mesh, std::string label, std::optional<HalfedgeMesh> from) {
  const bool previous = !from;
  const uint64_t old_version = doc.mesh.version();
  HalfedgeMesh before = from ? std::move(*from) : std::move(doc.mesh);  // replaced anyway: moved, not copied
  doc.mesh = std::move(mesh);
  doc.mesh.bump_version_above(old_version);  // caches keyed by version must not take it for the old state
  try {
    set_message(doc, Severity::Info, record_whole_change(doc, label, std::move(before), previous));
  } catch (const std::bad_alloc&) {
    keep_unrecorded_change(doc, label, old_version, true);  // show_state leaves the history alone
    set_message_noexcept(doc, Severity::Warning, [&] {
      return tr_format("{change}: shown, but memory ran out listing its changes", {{"change", shown_label(label)}});
    });
  }
}

// ---- counting and caches ---------------------------------------------------------------------------

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

// The last change was local and came from the state the validation cache found clean: its patch alone can tell.
bool last_patch_follows_clean(const MeshDocument& doc) {
  const VersionCache<CheckedValidation>& cache = doc.validation;
  return cache.filled && cache.value.clean && cache.generation == doc.generation && doc.last.patch &&
         doc.last.version_before == cache.version && doc.last.version_after == doc.mesh.version();
}

// True when the last change, from a clean state, kept the mesh clean: its patch alone tells (core/patch_check.h).
bool last_patch_kept_clean(MeshDocument& doc) {
  return last_patch_follows_clean(doc) &&
         cached(doc.patch_check, doc, [&] { return edit_keeps_clean(doc.mesh, *doc.last.patch); });
}
}  // namespace

const ValidationReport& cached_validation(MeshDocument& doc) {
  return cached(doc.validation, doc,
                [&] {
                  CheckedValidation checked;
                  if (last_patch_kept_clean(doc)) {
                    checked.clean = checked.from_patch = true;
                  } else {
                    checked.clean = mesh_is_clean(doc.mesh, hardware_threads());
                    if (!checked.clean) checked.report = validate_without_shortcut(doc.mesh, kListedViolations);
                  }
                  return checked;
                })
      .report;
}

const ValidationReport* cached_validation_if_cheap(MeshDocument& doc) {
  const bool cheap = validation_is_current(doc) || doc.mesh.proven_valid_triangles() || last_patch_kept_clean(doc);
  return cheap ? &cached_validation(doc) : nullptr;
}

const MeshStats& cached_stats(MeshDocument& doc) {
  return cached(doc.stats, doc, [&] { return compute_stats(doc.mesh); });
}

bool validation_is_current(const MeshDocument& doc) {
  return doc.validation.filled && doc.validation.generation == doc.generation &&
         doc.validation.version == doc.mesh.version();
}

}  // namespace meshedit
