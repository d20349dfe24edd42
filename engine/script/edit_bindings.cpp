// Mesh methods that create and delete elements, and mesh:record(fn), the Lua face of EditRecorder.
//
//   mesh:new_vertex([position]) :new_halfedge() :new_edge() :new_face() :new_boundary() -> the new element,
//       appended (id = the old count of slots), every pointer null, a vertex at position or (0, 0, 0)
//   mesh:delete(element)   marks a live element of this mesh dead (pointers to it stay, as in the core)
//   mesh:record(fn) -> log  runs fn() and returns every change it made to this mesh, as push_edit_log shows them
// Invariants: creation respects MeshLimits::elements_per_kind (a runaway `while true do m:new_vertex() end`
// stops with an error naming the limit, not by exhausting memory); every change goes through make_change; a
// Lua error in fn ends the recording (the recorder lives on the C++ stack, which Lua errors unwind).
#include <span>

#include <lua.hpp>

#include "core/edit_log.h"
#include "script/edit_recorder.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

template <ElementKind K>
int mesh_new(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  RecordedEdit edit;
  edit.what = EditKind::Create;
  edit.field = "alive";
  if (K == ElementKind::Vertex && !lua_isnoneornil(L, 2)) edit.value.position = check_vec3(L, 2, "position");
  const std::string what = std::string("new_") + kind_name(K);
  check_room(L, *box.mesh, K, 1, what.c_str());
  edit.element = ElementRef(K, box.mesh->capacity(K));
  const ElementRef made = edit.element;
  make_change(L, box.mesh, std::move(edit));
  push_handle_at(L, 1, made);
  return 1;
}

int mesh_delete(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  Handle& h = check_any_handle(L, 2);
  check_storable(L, box.mesh, h);
  RecordedEdit edit;
  edit.what = EditKind::Delete;
  edit.element = h.ref();
  edit.field = "alive";
  make_change(L, box.mesh, std::move(edit));
  return 0;
}

int mesh_record(lua_State* L) {
  MeshBox& box = check_mesh(L, 1);
  luaL_checktype(L, 2, LUA_TFUNCTION);
  EditRecorder recorder(L, box.mesh, {.keep_before = false, .max_edits = EditRecorder::kDefaultMaxEdits});
  lua_pushvalue(L, 2);
  lua_call(L, 0, 0);
  recorder.stop();
  push_edit_log(L, recorder.edits());
  return 1;
}

}  // namespace

void push_edit_log(lua_State* L, std::span<const RecordedEdit> edits) {
  lua_createtable(L, static_cast<int>(edits.size()), 0);
  for (size_t i = 0; i < edits.size(); ++i) {
    const RecordedEdit& edit = edits[i];
    lua_createtable(L, 0, 7);
    lua_pushstring(L, edit_kind_name(edit.what));
    lua_setfield(L, -2, "what");
    set_string_field(L, "element", format_id(edit.element));
    set_string_field(L, "field", edit.field);
    set_string_field(L, "before", format_edit_before(edit));
    set_string_field(L, "after", format_edit_after(edit));
    set_string_field(L, "where", edit.where);
    if (edit.what == EditKind::Create && edit.element.kind == ElementKind::Vertex) {
      push_vec3(L, edit.value.position);
      lua_setfield(L, -2, "position");
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void add_edit_methods(lua_State* L) {
  const luaL_Reg methods[] = {{"new_vertex", guarded<mesh_new<ElementKind::Vertex>>},
                              {"new_halfedge", guarded<mesh_new<ElementKind::Halfedge>>},
                              {"new_edge", guarded<mesh_new<ElementKind::Edge>>},
                              {"new_face", guarded<mesh_new<ElementKind::Face>>},
                              {"new_boundary", guarded<mesh_new<ElementKind::Boundary>>},
                              {"delete", guarded<mesh_delete>},
                              {"record", guarded<mesh_record>},
                              {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
}

}  // namespace meshedit
