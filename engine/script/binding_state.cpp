// BindingState: creation in the registry, journals, the storage budget and the change path (see
// binding_state.h for the invariants).
#include "script/internal/binding_state.h"

#include <new>
#include <string_view>

#include <lua.hpp>

#include "core/value_format.h"
#include "script/edit_recorder.h"
#include "script/lua_runtime.h"
#include "script/touch_recorder.h"

namespace meshedit {
namespace {

// The registry key of the BindingState userdata (its address is the key).
const char kStateKey = 0;

int state_gc(lua_State* L) {
  static_cast<BindingState*>(lua_touserdata(L, 1))->~BindingState();
  return 0;
}

// Appends `edit` to every recorder listening to `mesh`, with `where` found once for all of them.
void notify_recorders(BindingState& state, lua_State* L, const HalfedgeMesh* mesh, RecordedEdit& edit) {
  bool where_known = false;
  for (EditRecorder* recorder : state.recorders) {
    if (!recorder->watches(mesh)) continue;
    if (!where_known) edit.where = script_where(L);
    where_known = true;
    recorder->append(edit);
  }
}

void begin_change(lua_State* L, BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, bool operation) {
  for (const EditRecorder* recorder : state.recorders) {
    if (recorder->watches(mesh.get()) && recorder->full()) {
      LuaRuntime::note_cap(L);
      luaL_error(L, "more than %d changes recorded; is there a loop that never ends?", int(recorder->max_edits()));
    }
  }
  if (!operation && state.journals.empty()) return;
  if (EditJournal* journal = find_journal(state, mesh, operation)) journal->before_change(*mesh, operation);
}

void end_change(lua_State* L, BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit) {
  if (!state.touch_recorders.empty()) note_change(state, mesh.get(), edit);
  if (!state.recorders.empty()) notify_recorders(state, L, mesh.get(), edit);
  if (state.journals.empty()) return;
  if (EditJournal* journal = find_journal(state, mesh, false)) journal->after_change(*mesh, std::move(edit));
}

}  // namespace

BindingState::~BindingState() {
  for (EditRecorder* recorder : recorders) recorder->detach();
  for (TouchRecorder* recorder : touch_recorders) recorder->detach();
}

void open_binding_state(lua_State* L) {
  if (find_binding_state(L)) return;
  void* memory = lua_newuserdatauv(L, sizeof(BindingState), 0);
  new (memory) BindingState();
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, state_gc);
  lua_setfield(L, -2, "__gc");
  lua_setmetatable(L, -2);
  lua_rawsetp(L, LUA_REGISTRYINDEX, &kStateKey);
}

BindingState* find_binding_state(lua_State* L) {
  lua_rawgetp(L, LUA_REGISTRYINDEX, &kStateKey);
  auto* state = static_cast<BindingState*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  return state;
}

BindingState& binding_state(lua_State* L) {
  BindingState* state = find_binding_state(L);
  if (!state) luaL_error(L, "the meshedit module is not open in this Lua state");
  return *state;
}

void set_mesh_limits(lua_State* L, const MeshLimits& limits) {
  if (BindingState* state = find_binding_state(L)) state->limits = limits;
}

EditJournal* find_journal(BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, bool create) {
  const auto same = [&](const std::weak_ptr<HalfedgeMesh>& w) {
    return !w.owner_before(mesh) && !mesh.owner_before(w) && !w.expired();
  };
  auto it = state.journals.find(mesh.get());
  if (it != state.journals.end() && same(it->second.mesh)) return &it->second.journal;
  if (!create) return nullptr;
  // Journals of meshes that died go now: journals never outnumber the live meshes by more than one.
  std::erase_if(state.journals, [](const auto& entry) { return entry.second.mesh.expired(); });
  auto& slot = state.journals[mesh.get()];
  slot = BindingState::JournalSlot{mesh, EditJournal()};
  return &slot.journal;
}

void reserve_storage(lua_State* L, size_t bytes) {
  BindingState& state = binding_state(L);
  const auto fits = [&] { return state.storage->used + bytes <= state.limits.storage_bytes; };
  if (fits()) return;
  lua_gc(L, LUA_GCCOLLECT);
  if (fits()) return;
  const std::string total = format_bytes(state.storage->used + bytes);
  const std::string limit = format_bytes(state.limits.storage_bytes);
  luaL_error(L, "meshes and snapshots made by this script would hold %s; the limit is %s", total.c_str(),
             limit.c_str());
}

std::shared_ptr<HalfedgeMesh> own_mesh(lua_State* L, HalfedgeMesh&& mesh) {
  const size_t bytes = mesh.memory_bytes();
  reserve_storage(L, bytes);
  std::shared_ptr<StorageAccount> account = binding_state(L).storage;
  auto* owned = new HalfedgeMesh(std::move(mesh));
  account->used += bytes;
  return std::shared_ptr<HalfedgeMesh>(owned, [account, bytes](HalfedgeMesh* m) {
    account->used -= bytes;
    delete m;
  });
}

std::shared_ptr<HalfedgeMesh> copy_mesh(lua_State* L, const HalfedgeMesh& source) {
  reserve_storage(L, source.memory_bytes());
  return own_mesh(L, HalfedgeMesh(source));
}

void check_room(lua_State* L, const HalfedgeMesh& mesh, ElementKind kind, size_t count, const char* what) {
  const uint32_t cap = binding_state(L).limits.elements_per_kind;
  if (size_t(mesh.capacity(kind)) + count > cap) {
    LuaRuntime::note_cap(L);
    luaL_error(L, "%s: the mesh already has %d %s ids; scripts may make at most %d", what, int(mesh.capacity(kind)),
               kind_name(kind), int(cap));
  }
}

std::string room_refusal(lua_State* L, const HalfedgeMesh& mesh, size_t count) {
  const uint32_t cap = binding_state(L).limits.elements_per_kind;
  for (ElementKind kind : {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face}) {
    if (size_t(mesh.capacity(kind)) + count > cap) {
      return "the mesh already has " + std::to_string(mesh.capacity(kind)) + " " + kind_name(kind) +
             " ids; scripts may make at most " + std::to_string(cap);
    }
  }
  return {};
}

void begin_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, bool operation) {
  begin_change(L, binding_state(L), mesh, operation);
}

bool recorded(lua_State* L, const HalfedgeMesh* mesh) {
  for (const EditRecorder* recorder : binding_state(L).recorders) {
    if (recorder->watches(mesh)) return true;
  }
  return false;
}

void record_only(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit) {
  notify_recorders(binding_state(L), L, mesh.get(), edit);
}

void end_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit) {
  end_change(L, binding_state(L), mesh, std::move(edit));
}

void make_change(lua_State* L, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit) {
  make_change(L, binding_state(L), mesh, std::move(edit));
}

void make_change(lua_State* L, BindingState& state, const std::shared_ptr<HalfedgeMesh>& mesh, RecordedEdit edit) {
  begin_change(L, state, mesh, false);
  apply_edit(*mesh, edit);
  end_change(L, state, mesh, std::move(edit));
}

std::string script_where(lua_State* L) {
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0) continue;
    std::string_view name = ar.short_src;
    if (ar.source && ar.source[0] == '@') {
      name = ar.source + 1;
      if (const size_t slash = name.find_last_of("/\\"); slash != std::string_view::npos) name.remove_prefix(slash + 1);
    }
    return std::string(name) + ":" + std::to_string(ar.currentline);
  }
  return {};
}

}  // namespace meshedit
