// Snapshots, restore, undo and redo, and diff, as mesh methods.
//
//   mesh:snapshot() -> snapshot (a copy of the mesh now; tostring "snapshot (8 vertices, 18 edges, 12 faces)")
//   mesh:restore(snapshot)  the mesh becomes the snapshot again, ids included (an undo point)
//   mesh:undo() / mesh:redo() -> what was undone or redone ("flip e3", "restore") | nil when there is nothing
//   mesh:diff(snapshot_or_mesh) -> {{element="h3", field="next", before="h4", after="h7"}, ...}: the argument
//       is before, this mesh after; the order and texts of core diff() (history.h)
// Invariants: a snapshot is restored only into the mesh it was taken of (ids mean nothing in another one);
// snapshots are charged to the storage budget; diff writes each change straight into Lua tables, so a huge diff
// meets Lua's memory cap instead of building an unbounded C++ list first, and it reads a slot only below that
// mesh's capacity (any two meshes, however broken, can be diffed).
#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include <lua.hpp>

#include "core/edit_log.h"
#include "core/value_format.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/touch_recorder.h"

namespace meshedit {
namespace {

constexpr const char* kSnapshotType = "snapshot";

struct Snapshot {
  std::shared_ptr<const HalfedgeMesh> state;
  std::weak_ptr<HalfedgeMesh> origin;
};

Snapshot* test_snapshot(lua_State* L, int index) {
  return static_cast<Snapshot*>(luaL_testudata(L, index, kSnapshotType));
}

int snapshot_gc(lua_State* L) {
  static_cast<Snapshot*>(lua_touserdata(L, 1))->~Snapshot();
  return 0;
}

int snapshot_tostring(lua_State* L) {
  const HalfedgeMesh& m = *static_cast<Snapshot*>(luaL_checkudata(L, 1, kSnapshotType))->state;
  lua_pushfstring(L, "snapshot (%d vertices, %d edges, %d faces)", int(m.num_vertices()), int(m.num_edges()),
                  int(m.num_faces()));
  return 1;
}

int mesh_snapshot(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  note_whole_mesh_read(L, box.mesh.get(), "mesh:snapshot()");
  std::shared_ptr<const HalfedgeMesh> state = copy_mesh(L, *box.mesh);
  auto* snapshot = static_cast<Snapshot*>(lua_newuserdatauv(L, sizeof(Snapshot), 0));
  new (snapshot) Snapshot{std::move(state), box.mesh};
  luaL_setmetatable(L, kSnapshotType);
  return 1;
}

int mesh_restore(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  auto* snapshot = static_cast<Snapshot*>(luaL_checkudata(L, 2, kSnapshotType));
  const std::weak_ptr<HalfedgeMesh>& origin = snapshot->origin;
  if (origin.owner_before(box.mesh) || box.mesh.owner_before(origin)) {
    return luaL_error(L, "this snapshot was taken of another mesh");
  }
  begin_change(L, box.mesh, true);
  const uint64_t seen = box.mesh->version();
  *box.mesh = *snapshot->state;
  box.mesh->bump_version_above(seen);
  RecordedEdit edit;
  edit.what = EditKind::Operation;
  edit.field = "restore";
  edit.state = snapshot->state;
  end_change(L, box.mesh, std::move(edit));
  return 0;
}

template <bool Undo>
int mesh_undo(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  EditJournal* journal = find_journal(binding_state(L), box.mesh, false);
  lua_pushnil(L);
  if (!journal) return 1;
  begin_change(L, box.mesh, false);
  const std::optional<std::string> label = Undo ? journal->undo(*box.mesh) : journal->redo(*box.mesh);
  if (!label) return 1;
  note_whole_mesh_read(L, box.mesh.get(), Undo ? "mesh:undo()" : "mesh:redo()");
  if (recorded(L, box.mesh.get())) {
    RecordedEdit edit;
    edit.what = EditKind::Operation;
    edit.field = Undo ? "undo" : "redo";
    edit.state = std::make_shared<const HalfedgeMesh>(*box.mesh);
    record_only(L, box.mesh, std::move(edit));
  }
  lua_pushstring(L, label->c_str());
  return 1;
}

// ---- diff ---------------------------------------------------------------------------------------------

// Appends one {element=, field=, before=, after=} to the list on top of the stack.
struct DiffWriter {
  lua_State* L;
  lua_Integer count = 0;

  void add(ElementRef element, const char* field, const std::string& before, const std::string& after) {
    lua_createtable(L, 0, 4);
    set_string_field(L, "element", format_id(element));
    lua_pushstring(L, field);
    lua_setfield(L, -2, "field");
    set_string_field(L, "before", before);
    set_string_field(L, "after", after);
    lua_rawseti(L, -2, ++count);
  }
};

template <class T>
bool same(const T& a, const T& b) {
  return a == b;
}
bool same(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof(glm::dvec3)) == 0; }

template <ElementKind K>
std::string show(Id<K> id) {
  return format_id(id);
}
std::string show(FaceId f) { return format_id(f); }
std::string show(const glm::dvec3& p) { return format_position(p); }
std::string show(bool alive) { return alive ? "alive" : "dead"; }

// One field of one slot; a or b is null when the slot does not exist in that mesh.
template <class Get>
void compare(DiffWriter& out, ElementRef element, const char* field, const HalfedgeMesh* a, const HalfedgeMesh* b,
             Get get) {
  if (a && b) {
    const auto before = get(*a);
    const auto after = get(*b);
    if (!same(before, after)) out.add(element, field, show(before), show(after));
  } else if (b) {
    out.add(element, field, "-", show(get(*b)));
  } else if (a) {
    out.add(element, field, show(get(*a)), "-");
  }
}

template <class Fn>
void for_each_slot(const HalfedgeMesh& before, const HalfedgeMesh& after, ElementKind kind, Fn&& fn) {
  const uint32_t a = before.capacity(kind), b = after.capacity(kind);
  for (uint32_t i = 0; i < std::max(a, b); ++i) fn(i, i < a ? &before : nullptr, i < b ? &after : nullptr);
}

void write_diff(DiffWriter& out, const HalfedgeMesh& before, const HalfedgeMesh& after) {
  using M = const HalfedgeMesh*;
  for_each_slot(before, after, ElementKind::Vertex, [&](uint32_t i, M a, M b) {
    const VertexId v(i);
    compare(out, v, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(v); });
    compare(out, v, "position", a, b, [&](const HalfedgeMesh& m) { return m.position(v); });
    compare(out, v, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(v); });
  });
  for_each_slot(before, after, ElementKind::Halfedge, [&](uint32_t i, M a, M b) {
    const HalfedgeId h(i);
    compare(out, h, "next", a, b, [&](const HalfedgeMesh& m) { return m.next(h); });
    compare(out, h, "twin", a, b, [&](const HalfedgeMesh& m) { return m.twin(h); });
    compare(out, h, "vertex", a, b, [&](const HalfedgeMesh& m) { return m.vertex(h); });
    compare(out, h, "edge", a, b, [&](const HalfedgeMesh& m) { return m.edge(h); });
    compare(out, h, "face", a, b, [&](const HalfedgeMesh& m) { return m.face(h); });
    compare(out, h, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(h); });
  });
  for_each_slot(before, after, ElementKind::Edge, [&](uint32_t i, M a, M b) {
    const EdgeId e(i);
    compare(out, e, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(e); });
    compare(out, e, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(e); });
  });
  for (const bool boundary : {false, true}) {
    const ElementKind kind = boundary ? ElementKind::Boundary : ElementKind::Face;
    for_each_slot(before, after, kind, [&](uint32_t i, M a, M b) {
      const FaceId f = boundary ? FaceId::boundary(i) : FaceId::face(i);
      compare(out, f, "halfedge", a, b, [&](const HalfedgeMesh& m) { return m.halfedge(f); });
      compare(out, f, "alive", a, b, [&](const HalfedgeMesh& m) { return m.alive(f); });
    });
  }
}

int mesh_diff(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  const HalfedgeMesh* before = nullptr;
  if (const Snapshot* snapshot = test_snapshot(L, 2)) before = snapshot->state.get();
  else if (const auto* other = static_cast<MeshBox*>(luaL_testudata(L, 2, kMeshType))) before = other->mesh.get();
  else return luaL_typeerror(L, 2, "snapshot or mesh");
  note_whole_mesh_read(L, box.mesh.get(), "mesh:diff()");
  note_whole_mesh_read(L, before, "mesh:diff()");
  lua_newtable(L);
  DiffWriter out{L};
  write_diff(out, *before, *box.mesh);
  return 1;
}

}  // namespace

void add_history_methods(lua_State* L) {
  if (luaL_newmetatable(L, kSnapshotType)) {
    lua_pushcfunction(L, snapshot_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, guarded<snapshot_tostring>);
    lua_setfield(L, -2, "__tostring");
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
  }
  lua_pop(L, 1);
  const luaL_Reg methods[] = {{"snapshot", guarded<mesh_snapshot>}, {"restore", guarded<mesh_restore>},
                              {"undo", guarded<mesh_undo<true>>},   {"redo", guarded<mesh_undo<false>>},
                              {"diff", guarded<mesh_diff>},         {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
}

}  // namespace meshedit
