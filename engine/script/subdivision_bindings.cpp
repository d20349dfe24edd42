// Catmull-Clark and linear subdivision as mesh methods, beside mesh:loop_subdivide (operation_bindings.cpp), and every
// scheme's phases one call each (core/subdivision_phases.h):
//
//   mesh:catmull_clark() -> true | nil, reason      mesh:linear_subdivide() -> true | nil, reason
//   local phases = mesh:subdivision_phases("catmull-clark")   -- "loop" (course weights), "catmull-clark", "linear"
//   phases.scheme, phases.phase_count, phases.next_phase, phases.next_label
//   phases:step() -> the phase that ran, its label | nil, reason
//   phases:points() -> what phase 1 computed, by the ids of the mesh it read: {vertices = {[id] = vec3}, edges = ...,
//                      faces = ...} (Loop: vertices, edges; Catmull-Clark: all three; linear: edges, and faces for
//                      the faces of more than three sides) | nil before phase 1 and after the last phase
//   phases:restart()
// Invariants:
// - A refused call changes nothing and answers nil and the core's reason; an accepted whole subdivision is an undo
//   point recorded as one Operation edit named after the method. Each runs in C++ out of the instruction hook's
//   reach, so it is refused when its result would pass kMaxSubdividedFaces or MeshLimits::elements_per_kind; so is
//   a phase 1.
// - The phases step the mesh they were made on and no other. A phase after the first runs only on the mesh the
//   previous phase left: when anything else changed it in between, step() refuses and says so, and restart() starts
//   again at phase 1.
// - Each phase that changes the mesh is an undo point recorded as one Operation edit "subdivision phase" holding
//   the mesh it made (so a recording replays it without the phases' state); phase 1 changes and records nothing.
// - What phase 1 computed is charged to the script's storage budget until the last phase or a restart drops it, or
//   the phases are collected.
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/catmull_clark.h"
#include "core/edit_log.h"
#include "core/linear_subdivision.h"
#include "core/subdivision_phases.h"
#include "script/internal/binding_state.h"
#include "script/internal/binding_support.h"
#include "script/vec3_bindings.h"

namespace meshedit {
namespace {

// Faces after one level: a triangle gives 4 (Loop, linear) or 3 (Catmull-Clark), an n-gon n.
size_t faces_after(const HalfedgeMesh& mesh, SubdivisionScheme scheme) {
  size_t faces = 0;
  for (FaceId f : mesh.faces()) {
    const uint32_t sides = mesh.degree(f);
    faces += sides == 3 ? (scheme == SubdivisionScheme::CatmullClark ? 3 : 4) : sides;
  }
  return faces;
}

// "" when one level of `scheme` may run on `m` from a script, else why not.
std::string subdivision_refusal(lua_State* L, const HalfedgeMesh& m, SubdivisionScheme scheme) {
  const size_t faces = faces_after(m, scheme);
  if (faces > kMaxSubdividedFaces) {
    return std::string(scheme_title(scheme)) + " subdivision would make " + std::to_string(faces) +
           " faces; scripts may make at most " + std::to_string(kMaxSubdividedFaces);
  }
  // Halfedges, the most numerous ids of the result: two per edge, and 2E + F' edges at most (each original edge
  // in two, plus at most one new edge inside an original face per child face).
  return room_refusal(L, m, 2 * (2 * m.num_edges() + faces));
}

// ---- whole subdivisions ------------------------------------------------------------------------------------------

int run_subdivision(lua_State* L, const char* name, SubdivisionScheme scheme, Check (*subdivide)(HalfedgeMesh&, int)) {
  MeshBox& box = check_mesh(L, 1);
  HalfedgeMesh& m = *box.mesh;
  if (const std::string refusal = subdivision_refusal(L, m, scheme); !refusal.empty()) return push_refusal(L, refusal);
  begin_change(L, box.mesh, true);
  const Check check = subdivide(m, 1);
  if (!check.ok) return push_refusal(L, check.reason);
  end_change(L, box.mesh, operation_edit(name, ElementRef(), ElementRef()));
  lua_pushboolean(L, 1);
  return 1;
}

int mesh_catmull_clark(lua_State* L) {
  return run_subdivision(L, "catmull_clark", SubdivisionScheme::CatmullClark, catmull_clark_subdivide);
}

int mesh_linear_subdivide(lua_State* L) {
  return run_subdivision(L, "linear_subdivide", SubdivisionScheme::Linear, linear_subdivide);
}

// ---- phases ------------------------------------------------------------------------------------------------------

constexpr const char* kPhasesType = "subdivision phases";

struct PhasesBox {
  SubdivisionPhases phases;
  std::shared_ptr<HalfedgeMesh> mesh;  // the mesh the phases step
  uint64_t version = 0;                // its version after the last phase ran
  std::shared_ptr<StorageAccount> account;
  size_t charged = 0;  // bytes of phase 1's points charged to `account`

  void release() {
    if (account) account->used -= charged;
    charged = 0;
  }
};

PhasesBox& check_phases(lua_State* L, int arg) {
  return *static_cast<PhasesBox*>(luaL_checkudata(L, arg, kPhasesType));
}

int phases_gc(lua_State* L) {
  auto* box = static_cast<PhasesBox*>(lua_touserdata(L, 1));
  box->release();
  box->~PhasesBox();
  return 0;
}

// What phase 1's points hold, roughly: a point (24 bytes) and an id (4 bytes) per new vertex, a point per old one.
size_t points_bytes(const HalfedgeMesh& mesh) {
  return 28 * (mesh.vertex_capacity() + mesh.edge_capacity() + mesh.face_capacity()) + 64;
}

int phases_step(lua_State* L) {
  PhasesBox& box = check_phases(L, 1);
  SubdivisionPhases& phases = box.phases;
  const SubdivisionScheme scheme = phases.scheme();
  const int phase = phases.next_phase();
  if (phase == 1) {
    const std::string refusal = subdivision_refusal(L, *box.mesh, scheme);
    if (!refusal.empty()) return push_refusal(L, refusal);
    const size_t bytes = points_bytes(*box.mesh);
    reserve_storage(L, bytes);
    const Check check = phases.run_next(*box.mesh);
    if (!check) return push_refusal(L, check.reason);
    box.account = binding_state(L).storage;
    box.account->used += bytes;
    box.charged = bytes;
  } else {
    if (box.mesh->version() != box.version) {
      return push_refusal(L, "the mesh changed after " + std::string(scheme_title(scheme)) + " phase " +
                                 std::to_string(phase - 1) + "; phases:restart() starts again at phase 1");
    }
    begin_change(L, box.mesh, true);
    if (const Check check = phases.run_next(*box.mesh); !check) return push_refusal(L, check.reason);
    RecordedEdit edit = operation_edit("subdivision phase", ElementRef(), ElementRef());
    edit.state = std::make_shared<const HalfedgeMesh>(*box.mesh);  // what redo and a replay put back
    end_change(L, box.mesh, std::move(edit));
    if (!phases.computed()) box.release();
  }
  box.version = box.mesh->version();
  lua_pushinteger(L, phase);
  lua_pushstring(L, phase_label(scheme, phase).c_str());
  return 2;
}

int phases_restart(lua_State* L) {
  PhasesBox& box = check_phases(L, 1);
  box.phases.restart();
  box.release();
  return 0;
}

// t[name] = {[id] = point} for each slot of `points` that `has_point` accepts.
template <class HasPoint>
void set_points(lua_State* L, const char* name, const std::vector<glm::dvec3>& points, HasPoint&& has_point) {
  lua_createtable(L, 0, 0);
  for (size_t slot = 0; slot < points.size(); ++slot) {
    if (!has_point(slot)) continue;
    push_vec3(L, points[slot]);
    lua_rawseti(L, -2, lua_Integer(slot));
  }
  lua_setfield(L, -2, name);
}

// The new vertex's position of each slot that has one, by the slot of the edge or face it belongs to.
std::vector<glm::dvec3> positions_of(const std::vector<uint32_t>& vertex_of, const std::vector<glm::dvec3>& position) {
  std::vector<glm::dvec3> points(vertex_of.size());
  for (size_t slot = 0; slot < vertex_of.size(); ++slot) {
    if (vertex_of[slot] != RefineLayout::kNone) points[slot] = position[vertex_of[slot]];
  }
  return points;
}

int phases_points(lua_State* L) {
  const PhasesBox& box = check_phases(L, 1);
  const SubdivisionPhases& phases = box.phases;
  if (!phases.computed()) {
    lua_pushnil(L);
    return 1;
  }
  // Every scheme keeps the original vertices' ids and gives new vertices ids past them: an original vertex is a live
  // one below the old capacity (the size of the points by vertex).
  const HalfedgeMesh& mesh = *box.mesh;
  const auto original_vertex = [&](size_t v) { return mesh.alive(VertexId(uint32_t(v))); };
  lua_createtable(L, 0, 3);
  if (const LoopState* loop = phases.loop_state()) {
    std::vector<uint8_t> split(loop->edge_position.size(), 0);
    for (EdgeId e : loop->original_edges) split[e.index] = 1;
    set_points(L, "vertices", loop->vertex_position, original_vertex);
    set_points(L, "edges", loop->edge_position, [&](size_t e) { return split[e] != 0; });
  } else if (const CatmullClarkState* cc = phases.catmull_clark_state()) {
    const RefineLayout& layout = cc->layout;
    set_points(L, "vertices", cc->vertex_point, original_vertex);
    set_points(L, "edges", cc->edge_point, [&](size_t e) { return layout.edge_vertex[e] != RefineLayout::kNone; });
    set_points(L, "faces", cc->face_point, [&](size_t f) { return layout.face_vertex[f] != RefineLayout::kNone; });
  } else if (const LinearState* linear = phases.linear_state()) {
    const RefineLayout& layout = linear->layout;
    set_points(L, "edges", positions_of(layout.edge_vertex, linear->position),
               [&](size_t e) { return layout.edge_vertex[e] != RefineLayout::kNone; });
    set_points(L, "faces", positions_of(layout.face_vertex, linear->position),
               [&](size_t f) { return layout.face_vertex[f] != RefineLayout::kNone; });
  }
  return 1;
}

int phases_index(lua_State* L) {
  const PhasesBox& box = check_phases(L, 1);
  const std::string key = luaL_checkstring(L, 2);
  const SubdivisionPhases& phases = box.phases;
  if (key == "scheme") lua_pushstring(L, scheme_name(phases.scheme()));
  else if (key == "phase_count") lua_pushinteger(L, phase_count(phases.scheme()));
  else if (key == "next_phase") lua_pushinteger(L, phases.next_phase());
  else if (key == "next_label") lua_pushstring(L, phases.next_label().c_str());
  else if (key == "step") lua_pushcfunction(L, guarded<phases_step>);
  else if (key == "points") lua_pushcfunction(L, guarded<phases_points>);
  else if (key == "restart") lua_pushcfunction(L, guarded<phases_restart>);
  else lua_pushnil(L);
  return 1;
}

int phases_tostring(lua_State* L) {
  const PhasesBox& box = check_phases(L, 1);
  lua_pushfstring(L, "%s phases (next: %s)", scheme_name(box.phases.scheme()), box.phases.next_label().c_str());
  return 1;
}

int mesh_subdivision_phases(lua_State* L) {
  MeshBox& mesh = check_mesh(L, 1);
  const char* name = luaL_checkstring(L, 2);
  const std::optional<SubdivisionScheme> scheme = scheme_named(name);
  if (!scheme) return luaL_argerror(L, 2, (std::string("expected ") + scheme_names()).c_str());
  auto* box = static_cast<PhasesBox*>(lua_newuserdatauv(L, sizeof(PhasesBox), 0));
  new (box) PhasesBox{SubdivisionPhases(*scheme), mesh.mesh, mesh.mesh->version(), nullptr, 0};
  luaL_setmetatable(L, kPhasesType);
  return 1;
}

}  // namespace

void add_subdivision_methods(lua_State* L) {
  if (luaL_newmetatable(L, kPhasesType)) {
    lua_pushcfunction(L, phases_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, guarded<phases_index>);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, guarded<phases_tostring>);
    lua_setfield(L, -2, "__tostring");
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
  }
  lua_pop(L, 1);
  const luaL_Reg methods[] = {{"catmull_clark", guarded<mesh_catmull_clark>},
                              {"linear_subdivide", guarded<mesh_linear_subdivide>},
                              {"subdivision_phases", guarded<mesh_subdivision_phases>},
                              {nullptr, nullptr}};
  luaL_setfuncs(L, methods, 0);
}

}  // namespace meshedit
