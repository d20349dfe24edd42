// BindingState: the C++ side of the `meshedit` module that belongs to one Lua state (internal to
// engine/script): its limits, the C++ memory its scripts' mesh copies hold, the undo journal of each mesh it
// changed, and the recorders listening to it. Every change a script makes passes through begin_change and
// end_change below, so the journals and recorders see all of them; the touch recorders also hear of every handle made.
//
// Invariants:
// - One BindingState per state, owned by a userdata in the registry: it dies with lua_close, and then
//   detaches the recorders still listening (they stop; they never touch a closed state).
// - A journal is keyed by its mesh and holds a weak_ptr to it: a mesh that died (and any new mesh that reuses
//   its address) never finds the old journal.
// - Storage: every mesh copy a script makes (copy, snapshot, load, primitives, from_polygons) is charged to the
//   state while it lives (the charge is released by the shared_ptr's deleter, wherever the copy ends up).
//   A copy that would pass limits.storage_bytes first triggers a full garbage collection (dropped snapshots
//   release their charge), then raises a Lua error. C++ mesh storage is outside Lua's allocator, so this is
//   what keeps `while true do t[#t + 1] = m:snapshot() end` from exhausting the machine.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"
#include "script/internal/edit_journal.h"
#include "script/mesh_bindings.h"

struct lua_State;

namespace meshedit {

class EditRecorder;
class TouchRecorder;

struct StorageAccount {
  size_t used = 0;
};

struct BindingState {
  struct JournalSlot {
    std::weak_ptr<HalfedgeMesh> mesh;
    EditJournal journal;
  };

  MeshLimits limits;
  std::shared_ptr<StorageAccount> storage = std::make_shared<StorageAccount>();
  std::vector<EditRecorder*> recorders;         // recording now, oldest first
  std::vector<TouchRecorder*> touch_recorders;  // counting touches now (touch_recorder.h), oldest first
  std::unordered_map<const HalfedgeMesh*, JournalSlot> journals;

  BindingState() = default;
  BindingState(const BindingState&) = delete;
  BindingState& operator=(const BindingState&) = delete;
  ~BindingState();
};

// Creates the state's BindingState (open_mesh_bindings calls it).
void open_binding_state(lua_State* L);
// nullptr when open_binding_state never ran on L's state.
BindingState* find_binding_state(lua_State* L);
// Raises a Lua error when open_binding_state never ran.
BindingState& binding_state(lua_State* L);

// The state's undo journal of `mesh`; created on demand, else nullptr when there is none.
EditJournal* find_journal(BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, bool create);

// Raises "meshes and snapshots made by this script would hold 13 KB; the limit is 12 KB" unless `bytes` more
// fit in the storage budget (collecting garbage first when they do not).
void reserve_storage(lua_State* L, size_t bytes);
// Takes `mesh` over as a script-made copy, charged to the budget (reserve_storage first).
std::shared_ptr<HalfedgeMesh> own_mesh(lua_State* L, HalfedgeMesh&& mesh);
// A charged copy of `source`, checked against the budget before copying.
std::shared_ptr<HalfedgeMesh> copy_mesh(lua_State* L, const HalfedgeMesh& source);

// Raises "<what>: the mesh already has N <kind> ids; scripts may make at most N" unless `count` more ids of
// `kind` fit under limits.elements_per_kind.
void check_room(lua_State* L, const HalfedgeMesh& mesh, ElementKind kind, size_t count, const char* what);
// The same test as a sentence for a refused operation; empty when there is room for `count` of every kind.
std::string room_refusal(lua_State* L, const HalfedgeMesh& mesh, size_t count);

// Before any change to `mesh` from Lua; `operation` marks an undo point (flip ... restore). Raises when a
// recorder listening to the mesh is full.
void begin_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, bool operation);
// After the change: hands its record to the journal and to the recorders listening to `mesh` (filling
// `where` for them), and tells the touch recorders watching it.
void end_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit);
// True when a recorder listens to `mesh` (so an edit worth a copy of the mesh is worth making).
bool recorded(lua_State* L, const HalfedgeMesh* mesh);
// Hands the edit to the recorders listening to `mesh` only: for undo and redo, which the journal makes itself.
void record_only(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit);
// begin_change, apply_edit, end_change: how Set, Create and Delete edits are made.
void make_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit);
// The same with L's BindingState already at hand (field writes keep it in their closure).
void make_change(lua_State* L, BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit);

// "flip.lua:12": the file name (without folders) and line of the innermost Lua function running on L; empty
// when no Lua function with a line is on the stack.
std::string script_where(lua_State* L);

}  // namespace meshedit
