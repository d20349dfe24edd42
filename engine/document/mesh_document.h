// MeshDocument: the mesh the window edits, its undo history, what the last operation changed, and the one
// message line the status bar shows.
//
// Invariants:
// - Every change to `mesh` goes through apply_operation(), undo(), redo(), replace_mesh() or show_state(); code that
//   assigns `mesh` directly must call replace_mesh() instead, or the caches below may describe another mesh.
// - A local edit costs time proportional to the edit, not the mesh: apply_operation watches the edit with a change
//   journal (core/change_journal.h) and keeps it as a patch (core/mesh_patch.h) in the history and in `last`. No
//   copy of the mesh is kept for it: whoever needs the state before reads it through the patch (core/state_before.h:
//   the renderer's in-place update, the validation). Only snapshot-sized changes (a whole-mesh pass such as Loop
//   subdivision, an assignment of the whole mesh, a huge script) and undo/redo of their snapshot entries copy the
//   mesh, and `last.before` keeps a copy only when their diff is listed (a small mesh), so L on a big mesh, its undo
//   and its redo copy nothing beyond the history's own snapshot.
// - A refused or throwing operation leaves `mesh`, `history` and `last` exactly as they were (same contents,
//   same version()); only `message` changes, memory running out included. The one exception is losing the
//   state before (apply_operation).
// - Out of memory: the document layer's rule of docs/ARCHITECTURE.md (Memory running out). No function here throws
//   std::bad_alloc, except the caches' computations (cached_validation, cached_stats); apply_operation, undo, redo
//   and show_state say what they keep when memory runs out. A message that cannot be built for lack of memory is
//   kMemoryRanOut, as a Warning or worse.
// - `last` always describes the most recent change to `mesh` (an operation, an undo or a redo): its diff goes
//   from the state before (`last.patch`'s, or `last.before`) to the current mesh, unless the change was not recorded
//   (then it only names it). `last.serial` grows by one each time `last` is replaced, so views that index the diff
//   rebuild their index once per change, not once per frame.
// - The validation and stats caches are keyed by (generation, mesh.version()): validate() and compute_stats() run
//   at most once per mesh state, however many frames ask. After a local change from a state the cache found clean,
//   the new state is validated from `last.patch` alone (core/patch_check.h), in time proportional to the change; the
//   answer is the whole-mesh check's.
// - Nothing here draws or touches ImGui: the document is plain data, tested without a window.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_patch.h"
#include "core/mesh_stats.h"
#include "core/validate.h"

namespace meshedit {

enum class Severity { Info, Warning, Error };

// The status line: the outcome of the last action ("flip e5: 12 fields changed"), a refusal reason, or an
// error (a file that would not open). `element` is the culprit to offer for selection, when there is one.
struct DocumentMessage {
  Severity severity = Severity::Info;
  std::string text;
  ElementRef element;
};

// The pointer fields a diff names (core/history.h FieldChange::field), as a small enum for O(1) lookups.
enum class MeshField : uint8_t { Next, Twin, Vertex, Edge, Face, Halfedge, Position, Alive };
inline constexpr int kMeshFieldCount = 8;
const char* field_name(MeshField field);                      // "next", ..., "alive"
std::optional<MeshField> parse_field(std::string_view name);  // the inverse; nullopt for anything else

// Which (element, field) cells and which elements a diff touches. Built once per change; lookups are O(1).
class ChangeIndex {
 public:
  ChangeIndex() = default;
  explicit ChangeIndex(const std::vector<FieldChange>& changes);

  bool contains(ElementRef element, MeshField field) const { return cells_.contains(key(element, field)); }
  bool contains(ElementRef element) const { return element_set_.contains(element); }
  // Every element with at least one changed field, in diff order, each once (what the renderer highlights).
  const std::vector<ElementRef>& elements() const { return elements_; }
  size_t cell_count() const { return cells_.size(); }

 private:
  static uint64_t key(ElementRef element, MeshField field) {
    return (uint64_t(element.kind) << 40) | (uint64_t(field) << 32) | element.index;
  }
  std::unordered_set<uint64_t> cells_;
  std::unordered_set<ElementRef> element_set_;
  std::vector<ElementRef> elements_;
};

// What the most recent change did, for highlighted cells and the Before/After view.
struct LastChange {
  std::string label;                 // "flip e5", "undo flip e5"; empty before the first change
  std::vector<FieldChange> changes;  // diff(before, mesh); empty when `listed` is false
  size_t change_count = 0;           // fields that changed; when not listed, only "more than the cap"
  bool listed = true;                // false when the diff was larger than DocumentLimits::max_listed_changes
  ChangeIndex index;                 // built from `changes`
  // The change as a patch from the state before to the mesh, when it was local (the state before is read through it:
  // core/state_before.h). Absent for snapshot-sized changes.
  std::optional<MeshPatch> patch;
  // A copy of the mesh before a snapshot-sized change whose diff is listed, for the renderer's in-place update;
  // absent otherwise (before the first change, with a patch, or a diff too long to list: nothing would read it).
  std::optional<HalfedgeMesh> before;
  uint64_t serial = 0;  // +1 every time this struct is replaced
  // False when the change happened but could not be recorded (memory ran out saving the state before it, or
  // recording the change): no `before`, `patch` or `changes`, and views say so rather than show an empty diff.
  bool recorded = true;
  // mesh.version() just before and after the change, when the state before is exactly the one the document showed
  // until then (not after show_state with a `from`): a renderer that showed that version can apply `changes`
  // in place instead of rebuilding. Absent otherwise.
  std::optional<uint64_t> version_before;
  uint64_t version_after = 0;
};

struct DocumentLimits {
  // A diff with more fields than this is counted but not listed (a Loop subdivision of a million triangles
  // changes tens of millions of fields; formatting them all would take gigabytes).
  size_t max_listed_changes = 200000;
  // The history keeps at most this many bytes of undo entries (History: at least 4 steps, at most 256). Whole-mesh
  // changes cost a snapshot of the mesh each, local edits only the slots they touched.
  size_t history_budget_bytes = size_t(2) << 30;
};

// Loop subdivision one phase per key press (core/loop_subdivision.h): which phase runs next and the state
// phases 1-3 computed. The state is only trusted while the mesh is the one the last phase left.
struct LoopStepper {
  int next_phase = 1;  // 1..4
  LoopState state;
  uint64_t generation = 0;  // document generation and mesh version after the last phase ran
  uint64_t version = 0;
};

template <class T>
struct VersionCache {
  bool filled = false;
  uint64_t generation = 0;
  uint64_t version = 0;
  size_t computations = 0;  // how many times the value was computed (tests count them)
  T value{};
};

// The validation of one mesh state, and whether the quick check accepted it (quick_check.h's mesh_is_clean): then
// the next change, when local, is validated from its patch alone (core/patch_check.h).
struct CheckedValidation {
  ValidationReport report;
  bool clean = false;
  bool from_patch = false;  // validated from the last change's patch alone
};

struct MeshDocument {
  std::string path;  // the file the mesh came from ("" for a generated mesh)
  HalfedgeMesh mesh;
  History history;
  LastChange last;
  DocumentMessage message;
  DocumentLimits limits;
  LoopStepper loop;
  // +1 whenever the mesh is replaced wholesale (replace_mesh), so caches keyed by version cannot confuse two
  // different meshes whose version counters happen to agree.
  uint64_t generation = 0;
  VersionCache<CheckedValidation> validation;
  VersionCache<bool> patch_check;  // edit_keeps_clean for the last change, when it followed a clean state
  VersionCache<MeshStats> stats;
};

// A document for `mesh` (read from `path`, or "" when generated). History depth follows limits.
MeshDocument make_document(HalfedgeMesh mesh, std::string path = {}, DocumentLimits limits = {});
// Replaces the mesh (opening another file): empties history and `last`, bumps generation, keeps `limits`. Always
// replaces it, memory running out included.
void replace_mesh(MeshDocument& doc, HalfedgeMesh mesh, std::string path);

void set_message(MeshDocument& doc, Severity severity, std::string text, ElementRef element = {});

// The message when memory ran out even for the message: 14 characters, which every std::string holds without
// allocating (its inline buffer has room for 15).
inline constexpr char kMemoryRanOut[] = "memory ran out";
// Sets kMemoryRanOut as the message (at least a Warning), allocating nothing.
void set_memory_ran_out_message(MeshDocument& doc, Severity severity, ElementRef element = {}) noexcept;
// set_message with the text `make_text()` returns; when that throws (memory ran out building the text), the message
// is kMemoryRanOut instead. Never throws: what reports a failure must not fail.
template <class MakeText>
void set_message_noexcept(MeshDocument& doc, Severity severity, MakeText&& make_text,
                          ElementRef element = {}) noexcept {
  try {
    set_message(doc, severity, make_text(), element);
  } catch (const std::exception&) {
    set_memory_ran_out_message(doc, severity, element);
  }
}

namespace detail {
// A borrowed operation, called without being copied: std::function may allocate to hold a copy, and nothing may
// allocate before the operation's journal is attached.
class OperationRef {
 public:
  template <class Op>
  explicit OperationRef(Op& op)
      : op_(&op), call_([](void* any, HalfedgeMesh& mesh) -> Check { return (*static_cast<Op*>(any))(mesh); }) {}
  Check operator()(HalfedgeMesh& mesh) const { return call_(op_, mesh); }

 private:
  void* op_;
  Check (*call_)(void*, HalfedgeMesh&);
};

Check apply_check_operation(MeshDocument& doc, const std::string& label, OperationRef op);
}  // namespace detail

// Runs `op` on doc.mesh. `op` returns a Check or an OpResult<T> (the core's operations do).
// Success and the mesh changed: the state before goes to history under `label`, `last` becomes the diff, and the
//   message says how many fields changed.
// Success and nothing changed: nothing is recorded, the mesh keeps its version and the message says so. When the
//   journal fell back to a snapshot (an assignment, direct array writes) that is decided by contents, since an
//   assigned mesh may bring any version; a change always ends with version() above the one before.
// Refusal, or an exception (MeshError, std::exception): the mesh is restored if `op` touched it, history and
//   `last` are untouched, and the message (Warning for a refusal, Error for an exception) gives the reason;
//   an exception becomes a refused Check whose reason is its message (kMemoryRanOut for std::bad_alloc). Putting
//   the mesh back allocates nothing (the journal's snapshot is moved back, or its log written back), so an `op`
//   that runs out of memory (std::bad_alloc from itself or from its journal's log) is refused so too ("flip e5:
//   memory ran out; the mesh is as it was", Error).
// Memory ran out saving the state before (the journal's snapshot; a mesh of millions of faces): nothing crashes and
//   nothing `op` did is thrown away. The mesh stays as `op` left it, refused or not (there is no state to put back),
//   version() moves above the one before, the history is cleared (its entries start from a state the mesh may no
//   longer be in), `last` is marked not recorded, and the message says undo history was cleared because memory ran
//   out (Warning on success, Error with the refusal's reason otherwise); the Check is `op`'s, as above. Later
//   edits, undo and redo work as on a freshly opened mesh.
// Memory ran out recording a success (its patch, the state before, the history entry, `last`): the edit is kept all
//   the same, version() moves above the one before, `last` is marked not recorded and a Warning says what was lost;
//   the Check is `op`'s. Without its history entry the history is cleared (undo would start from a state the mesh
//   is no longer in): "flip e5: done, but memory ran out recording it: undo history cleared". With it (only `last`
//   failed) the history still ends with the edit and is kept: "flip e5: done, but memory ran out listing its
//   changes".
// A local edit (setters only, fewer writes than the journal's cap) costs time proportional to the edit: no copy of
// the mesh, the diff made from the patch. A snapshot-sized one (MeshStorage's direct writes, assigning the mesh)
// costs a copy of the mesh (two when its diff is listed) and a pass over every slot.
template <class Op>
auto apply_operation(MeshDocument& doc, const std::string& label, Op&& op) {
  using Result = std::invoke_result_t<Op&, HalfedgeMesh&>;
  if constexpr (std::is_same_v<Result, Check>) {
    auto run = [&op](HalfedgeMesh& mesh) { return op(mesh); };
    return detail::apply_check_operation(doc, label, detail::OperationRef(run));
  } else {
    Result result{};
    auto run = [&](HalfedgeMesh& mesh) {
      result = op(mesh);
      return std::move(result.check);  // moved, not copied: a copy of the reason could run out of memory
    };
    result.check = detail::apply_check_operation(doc, label, detail::OperationRef(run));
    return result;
  }
}

// Undo/redo the last operation; `last` becomes the diff of the undo (or redo) itself, labelled
// "undo flip e5" / "redo flip e5". Return false and set a message when there is nothing to undo/redo, or when
// memory ran out before the step was taken. All or nothing (History::undo): when memory runs out before or during
// the step, mesh, history and `last` stay as they were ("undo flip e5: memory ran out; nothing was undone, the mesh
// is as it was", Error); when it runs out after the step (making `last`), the step is kept, the history too (it
// matches), `last` is marked not recorded and a Warning says so ("undo flip e5: done, but memory ran out listing its
// changes").
bool undo(MeshDocument& doc);
bool redo(MeshDocument& doc);

// Shows `mesh` in the document without touching history (the exercise replay steps through a recorded
// operation this way): the mesh is replaced, its version moves above the old one, and `last` becomes the diff
// from `from` (default: the mesh shown until now, moved there rather than copied) to `mesh`, labelled `label`.
// generation and history stay. Always shows `mesh`; when memory runs out making `last`, `last` is marked not
// recorded and a Warning says so.
void show_state(MeshDocument& doc, HalfedgeMesh mesh, std::string label,
                std::optional<HalfedgeMesh> from = std::nullopt);

// How many fields differ between the two states (the rules of core diff(), so it equals diff().size()), or
// some number above `limit` once the count passes it (it stops early). O(slots); allocates nothing.
size_t count_changes(const HalfedgeMesh& before, const HalfedgeMesh& after, size_t limit);

// validate() / compute_stats() of the current mesh, computed at most once per (generation, version) (validate() on
// a million triangles takes ~15 ms on two threads, ~130 ms at 1.6M faces after Loop). The one place here that
// throws std::bad_alloc, with the cache as it was: their callers (the status bar, scripted checks) run under the
// frame or action guard.
const ValidationReport& cached_validation(MeshDocument& doc);
const MeshStats& cached_stats(MeshDocument& doc);
// True when cached_validation() would return without running validate().
bool validation_is_current(const MeshDocument& doc);
// cached_validation() when it costs no whole-mesh pass: it is current, the mesh is vouched valid, or the last change
// was local, from a state the cache found clean, and its patch shows it kept the mesh clean (checked at most once
// per state). nullptr when only a whole-mesh pass can tell (a big mesh then waits for the user to ask).
const ValidationReport* cached_validation_if_cheap(MeshDocument& doc);

}  // namespace meshedit
