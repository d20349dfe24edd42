// The mesh API beyond reading: from_polygons, element creation and deletion, mesh:element("h37"),
// tables(), vec3 positions, the handle walks, and every error message they raise.
#include <gtest/gtest.h>

#include <string>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/value_format.h"
#include "mesh_script_fixture.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

// Two triangles over the unit square: v0 (0,0,0) v1 (1,0,0) v2 (1,1,0) v3 (0,1,0); f0 = (v0, v1, v2), f1 = (v0, v2,
// v3).
PolygonMesh square() {
  PolygonMesh p;
  for (glm::dvec3 q : {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0)})
    p.add_vertex(q);
  p.add_face({0, 1, 2});
  p.add_face({0, 2, 3});
  return p;
}

TEST(MeshApi, FromPolygonsBuildsTheSameMeshAsTheCore) {
  MeshScript s(square());
  s.run(
      "sq = meshedit.from_polygons({{0, 0, 0}, {x = 1, y = 0, z = 0}, meshedit.vec3(1, 1), {0, 1, 0}}, "
      "{{1, 2, 3}, {1, 3, 4}})");
  lua_getglobal(s.lua.state(), "sq");
  const std::shared_ptr<HalfedgeMesh> built = to_mesh(s.lua.state(), -1);
  lua_pop(s.lua.state(), 1);
  ASSERT_TRUE(built);
  EXPECT_TRUE(built->same_as(*s.mesh));
  EXPECT_EQ(s.run("return tostring(sq:face(1).halfedge.vertex), tostring(sq:vertex(2).position), sq:num_boundaries()"),
            (Strings{"v0", "(1, 1, 0)", "1"}));
}

TEST(MeshApi, FromPolygonsErrorsNameTheEntry) {
  MeshScript s(square());
  const std::string pts = "{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}";
  EXPECT_EQ(s.error("meshedit.from_polygons({{0, 0, 0}, 'x'}, {})"),
            "t.lua:1: from_polygons: positions[2] must be a vec3 or a table {x, y, z} of numbers, got string");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 3}, {1, 2}})"),
            "t.lua:1: from_polygons: polygons[2] has 2 corners; a polygon needs at least 3");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 5}})"),
            "t.lua:1: from_polygons: polygons[1][3] is 5, but positions go from 1 to 4");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 0}})"),
            "t.lua:1: from_polygons: polygons[1][3] is 0, but positions go from 1 to 4");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 2.5}})"),
            "t.lua:1: from_polygons: polygons[1][3] must be an index into positions, got number");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 3}, 7})"),
            "t.lua:1: from_polygons: polygons[2] must be a list of indices into positions, got number");
  EXPECT_EQ(s.error("meshedit.from_polygons(" + pts + ", {{1, 2, 3}, {1, 2, 4}})"),
            "t.lua:1: from_polygons: faces 0 and 1 both go from vertex 0 to vertex 1: their orientations are "
            "inconsistent (flip one of them) (face k is polygons[k+1], vertex k is positions[k+1])");
  EXPECT_EQ(s.error("meshedit.from_polygons(5, {})"),
            "t.lua:1: bad argument #1 to 'from_polygons' (table expected, got number)");
}

TEST(MeshApi, NewElementsAreAppendedWithNullPointers) {
  MeshScript s(make_grid(1, 1));  // 4 vertices, 10 halfedges, 5 edges, 2 faces, 1 boundary loop
  EXPECT_EQ(
      s.run("local v = m:new_vertex({0.5, 0.25, 1})\nlocal w = m:new_vertex()\n"
            "local h, e, f, b = m:new_halfedge(), m:new_edge(), m:new_face(), m:new_boundary()\n"
            "return tostring(v), tostring(v.position), tostring(w.position), tostring(v.halfedge), tostring(h), "
            "tostring(h.next), tostring(h.face), tostring(e), tostring(f), tostring(f.halfedge), tostring(b), "
            "b:is_boundary()"),
      (Strings{"v4", "(0.5, 0.25, 1)", "(0, 0, 0)", "nil", "h10", "nil", "nil", "e5", "f2", "nil", "b1", "true"}));
  EXPECT_EQ(s.mesh->position(VertexId(4)), glm::dvec3(0.5, 0.25, 1));
  EXPECT_EQ(s.mesh->num_vertices(), 6u);
  EXPECT_TRUE(s.mesh->alive(FaceId::boundary(1)));
  // Wiring the new elements reaches the mesh.
  s.run(
      "local h = m:halfedge(10)\nh:set_neighbors(h, nil, m:vertex(4), m:edge(5), m:boundary(1))\n"
      "m:boundary(1).halfedge = h");
  EXPECT_EQ(s.mesh->next(HalfedgeId(10)), HalfedgeId(10));
  EXPECT_FALSE(s.mesh->twin(HalfedgeId(10)).valid());
  EXPECT_EQ(s.mesh->face(HalfedgeId(10)), FaceId::boundary(1));
  EXPECT_EQ(s.mesh->halfedge(FaceId::boundary(1)), HalfedgeId(10));
}

TEST(MeshApi, DeleteMarksDeadAndKeepsPointers) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeId twin = s.mesh->twin(HalfedgeId(0));
  EXPECT_EQ(s.run("local t = m:halfedge(0).twin\nm:delete(t)\n"
                  "return m:alive(t), tostring(m:halfedge(0).twin), m:num_halfedges()"),
            (Strings{"false", format_id(twin), "9"}));
  EXPECT_FALSE(s.mesh->alive(twin));
  EXPECT_EQ(s.error("m:delete(m:halfedge(" + std::to_string(twin.index) + "))"),
            "t.lua:1: attempt to use dead halfedge " + format_id(twin));
  EXPECT_EQ(s.error("m:delete(3)"), "t.lua:1: bad argument #1 to 'delete' (element expected, got number)");
  EXPECT_EQ(s.error("m:delete(meshedit.grid(1, 1):vertex(0))"), "t.lua:1: v0 belongs to another mesh");
  s.run("m:delete(m:face(1))\nm:delete(m:boundary(0))\nm:delete(m:vertex(3))\nm:delete(m:edge(4))");
  EXPECT_FALSE(s.mesh->alive(FaceId::face(1)));
  EXPECT_FALSE(s.mesh->alive(FaceId::boundary(0)));
  EXPECT_FALSE(s.mesh->alive(VertexId(3)));
  EXPECT_FALSE(s.mesh->alive(EdgeId(4)));
}

TEST(MeshApi, ElementByPrintedId) {
  MeshScript s(make_grid(1, 1));
  EXPECT_EQ(s.run("return tostring(m:element('h7')), tostring(m:element('v3')), tostring(m:element('e4')), "
                  "tostring(m:element('f1')), tostring(m:element('b0')), m:element('h7') == m:halfedge(7)"),
            (Strings{"h7", "v3", "e4", "f1", "b0", "true"}));
  EXPECT_EQ(s.error("return m:element('x3')"),
            "t.lua:1: bad argument #1 to 'element' (expected an id such as \"h37\" or \"b0\", got \"x3\")");
  EXPECT_EQ(s.error("return m:element('h10')"),
            "t.lua:1: no halfedge with id 10 in this mesh (halfedge ids go from 0 to 9)");
  EXPECT_EQ(s.error("return m:element('b1')"),
            "t.lua:1: no boundary with id 1 in this mesh (boundary ids go from 0 to 0)");
}

// Lua that prints every list of mesh:tables() as "id field=value ...;" in a fixed field order.
constexpr const char* kPrintTables = R"(
local t = m:tables()
local out = {}
local function add(list, fields)
  for _, row in ipairs(list) do
    local parts = {row.id}
    for _, f in ipairs(fields) do parts[#parts + 1] = f .. "=" .. tostring(row[f]) end
    out[#out + 1] = table.concat(parts, " ")
  end
end
add(t.vertices, {"halfedge", "position"})
add(t.halfedges, {"next", "twin", "vertex", "edge", "face"})
add(t.edges, {"halfedge"})
add(t.faces, {"halfedge"})
add(t.boundaries, {"halfedge"})
return table.concat(out, ";")
)";

std::string expected_tables(const HalfedgeMesh& m) {
  std::string out;
  const auto row = [&](const std::string& text) { out += (out.empty() ? "" : ";") + text; };
  for (VertexId v : m.vertices()) {
    row(format_id(v) + " halfedge=" + format_id(m.halfedge(v)) + " position=" + format_position(m.position(v)));
  }
  for (HalfedgeId h : m.halfedges()) {
    row(format_id(h) + " next=" + format_id(m.next(h)) + " twin=" + format_id(m.twin(h)) +
        " vertex=" + format_id(m.vertex(h)) + " edge=" + format_id(m.edge(h)) + " face=" + format_id(m.face(h)));
  }
  for (EdgeId e : m.edges()) row(format_id(e) + " halfedge=" + format_id(m.halfedge(e)));
  for (FaceId f : m.faces()) row(format_id(f) + " halfedge=" + format_id(m.halfedge(f)));
  for (FaceId b : m.boundaries()) row(format_id(b) + " halfedge=" + format_id(m.halfedge(b)));
  return out;
}

TEST(MeshApi, TablesListLiveElementsWithStoredPointers) {
  MeshScript s(make_grid(1, 1));
  EXPECT_EQ(s.run(kPrintTables), Strings{expected_tables(*s.mesh)});
  // Dead elements leave the lists; pointers to them still print; null pointers print "-".
  s.run("local h = m:halfedge(0)\nm:delete(h.twin)\nh.face = nil\nm:delete(m:vertex(3))");
  const std::string tables = s.run(kPrintTables)[0];
  EXPECT_EQ(tables, expected_tables(*s.mesh));
  EXPECT_NE(tables.find("h0 next=h1 twin=" + format_id(s.mesh->twin(HalfedgeId(0)))), std::string::npos);
  EXPECT_NE(tables.find("face=-"), std::string::npos);
  EXPECT_EQ(tables.find(";v3 halfedge="), std::string::npos);
  EXPECT_NE(tables.find(";v2 halfedge="), std::string::npos);
  EXPECT_EQ(s.run("local t = m:tables() return #t.vertices, #t.halfedges, #t.edges, #t.faces, #t.boundaries, "
                  "getmetatable(t.vertices[1].position)"),
            (Strings{"3", "9", "5", "2", "1", "vec3"}));
}

TEST(MeshApi, PositionsAreVec3AndWritesTakeVec3OrTables) {
  MeshScript s(make_grid(1, 1));
  EXPECT_EQ(s.run("local v = m:vertex(2)\nlocal p = v.position\np.x = 9\n"
                  "return tostring(v.position), tostring(p), getmetatable(p), tostring(v.position + v.position)"),
            (Strings{"(0, 1, 0)", "(9, 1, 0)", "vec3", "(0, 2, 0)"}));
  s.run(
      "m:vertex(0).position = m:vertex(2).position * 2\nm:vertex(1).position = {1, 2, 3}\n"
      "m:vertex(3).position = {x = -1, y = 0.5, z = 0}");
  EXPECT_EQ(s.mesh->position(VertexId(0)), glm::dvec3(0, 2, 0));
  EXPECT_EQ(s.mesh->position(VertexId(1)), glm::dvec3(1, 2, 3));
  EXPECT_EQ(s.mesh->position(VertexId(3)), glm::dvec3(-1, 0.5, 0));
  EXPECT_EQ(s.error("m:vertex(0).position = 5"),
            "t.lua:1: v0.position must be a vec3 or a table {x, y, z} of numbers, got number");
  EXPECT_EQ(s.error("m:new_vertex('here')"),
            "t.lua:1: position must be a vec3 or a table {x, y, z} of numbers, got string");
}

TEST(MeshApi, WalksAroundFacesAndVertices) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh& m = *s.mesh;
  std::string face_cycle, face_vertices, fan, neighbours;
  m.for_each_face_halfedge(FaceId::face(0), [&](HalfedgeId h) {
    face_cycle += format_id(h) + " ";
    face_vertices += format_id(m.vertex(h)) + " ";
  });
  m.for_each_outgoing(VertexId(0), [&](HalfedgeId h) {
    fan += format_id(h) + " ";
    neighbours += format_id(m.vertex(m.twin(h))) + " ";
  });
  const char* collect =
      "local function all(it) local s = '' for x in it do s = s .. tostring(x) .. ' ' end return s end\n";
  EXPECT_EQ(s.run(std::string(collect) +
                  "local f, v = m:face(0), m:vertex(0)\n"
                  "return all(f:halfedges()), all(f:vertices()), all(v:halfedges()), all(v:neighbors())"),
            (Strings{face_cycle, face_vertices, fan, neighbours}));
  EXPECT_EQ(s.run("local h = m:halfedge(1) return tostring(h:prev()), h:prev().next == h, m:boundary(0):degree()"),
            (Strings{format_id(m.prev(HalfedgeId(1))), "true", "4"}));
  EXPECT_EQ(s.run("return m:halfedge(0).kind, m:boundary(0).kind, m:vertex(3).id"),
            (Strings{"halfedge", "boundary", "3"}));
  EXPECT_EQ(s.error("return m:edge(0):degree()"), "t.lua:1: e0 has no field 'degree'");
  EXPECT_EQ(s.error("return m:edge(0):halfedges()"), "t.lua:1: e0 has no field 'halfedges'");
  EXPECT_EQ(s.error("return m:vertex(0):vertices()"), "t.lua:1: v0 has no field 'vertices'");
}

TEST(MeshApi, WriteErrors) {
  MeshScript s(make_grid(1, 1));
  s.mesh->delete_element(HalfedgeId(7));
  EXPECT_EQ(s.error("m:halfedge(0).next = m:halfedge(7)"), "t.lua:1: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local h = m:halfedge(0)\nh:set_neighbors(m:halfedge(7), h.twin, h.vertex, h.edge, h.face)"),
            "t.lua:2: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local o = meshedit.grid(1, 1)\nlocal h = m:halfedge(0)\n"
                    "h:set_neighbors(h.next, h.twin, o:vertex(0), h.edge, h.face)"),
            "t.lua:3: v0 belongs to another mesh");
  EXPECT_EQ(s.error("local h = m:halfedge(0)\nh:set_neighbors(h.next, h.twin, h.vertex, h.twin, h.face)"),
            "t.lua:2: bad argument #4 to 'set_neighbors' (edge expected, got halfedge)");
  EXPECT_EQ(s.error("local h = m:halfedge(0)\nh:set_neighbors(h.next, h.twin, h.vertex, h.edge)"),
            "t.lua:2: bad argument #5 to 'set_neighbors' (value expected)");
  EXPECT_EQ(s.error("m:halfedge(0).face = m:edge(1)"), "t.lua:1: h0.face must be a face or nil, got edge");
  EXPECT_EQ(s.error("m:vertex(0).halfedge = 'h3'"), "t.lua:1: v0.halfedge must be a halfedge or nil, got string");
  EXPECT_EQ(s.error("m:halfedge(0).id = 4"), "t.lua:1: cannot set field 'id' of h0");
  EXPECT_EQ(s.error("m:vertex(0).next = nil"), "t.lua:1: cannot set field 'next' of v0");
  EXPECT_EQ(s.error("m.new_vertex(5)"), "t.lua:1: bad argument #1 to 'new_vertex' (mesh expected, got number)");
  // A face slot takes a boundary loop, and a failed write changes nothing.
  s.run("m:halfedge(0).face = m:boundary(0)");
  EXPECT_EQ(s.mesh->face(HalfedgeId(0)), FaceId::boundary(0));
  EXPECT_EQ(s.mesh->next(HalfedgeId(0)), HalfedgeId(1));
}

TEST(MeshApi, ElementCapStopsRunawayCreation) {
  MeshScript s(make_grid(1, 1));
  set_mesh_limits(s.lua.state(), {.elements_per_kind = 100, .storage_bytes = size_t(1) << 30});
  EXPECT_EQ(s.error("while true do m:new_vertex() end"),
            "t.lua:1: new_vertex: the mesh already has 100 vertex ids; scripts may make at most 100");
  EXPECT_EQ(s.mesh->vertex_capacity(), 100u);
  EXPECT_EQ(s.error("for i = 1, 1000 do m:new_boundary() end"),
            "t.lua:1: new_boundary: the mesh already has 100 boundary ids; scripts may make at most 100");
  // Operations, which run in C++, are refused near the cap instead.
  EXPECT_EQ(s.run("return m:split(m:edge(0))"),
            (Strings{"nil", "the mesh already has 100 vertex ids; scripts may make at most 100"}));
  EXPECT_EQ(MeshLimits{}.elements_per_kind, uint32_t(1) << 24);
}

TEST(MeshApi, StorageBudgetStopsRunawayCopies) {
  MeshScript s(make_grid(1, 1));
  const size_t bytes = HalfedgeMesh(*s.mesh).memory_bytes();
  set_mesh_limits(s.lua.state(), {.elements_per_kind = 1u << 24, .storage_bytes = 20 * bytes});
  // Snapshots nobody keeps are collected when the budget runs short.
  EXPECT_EQ(s.run("for i = 1, 1000 do local s = m:snapshot() local c = m:copy() end return 'ok'"), Strings{"ok"});
  const std::string message = s.error("local t = {}\nfor i = 1, 1000 do t[i] = m:snapshot() end");
  EXPECT_EQ(message.rfind("t.lua:2: meshes and snapshots made by this script would hold ", 0), 0u) << message;
  EXPECT_NE(message.find("; the limit is "), std::string::npos) << message;
  // Once the kept snapshots are gone, the budget is free again (19 copies: the check counts the source's bytes,
  // a little more than a copy's).
  EXPECT_EQ(s.run("local t = {} for i = 1, 19 do t[i] = m:copy() end return #t"), Strings{"19"});
}

}  // namespace
}  // namespace meshedit
