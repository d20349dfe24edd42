// The `meshedit` Lua module: handles, fields, pointer writes, the exact error messages, a student-style flip
// written in Lua against the core's flip, and a mesh a script broke that validate() still reports on.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

// A runtime with `m` bound to the given mesh.
struct Fixture {
  std::shared_ptr<HalfedgeMesh> mesh;
  ScriptRuntime lua;
  explicit Fixture(PolygonMesh polygons) : mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(polygons))) {
    push_mesh(lua.state(), mesh);
    lua_setglobal(lua.state(), "m");
  }
  Strings run(const std::string& code) { return lua.run_string(code, "t.lua"); }
  std::string error(const std::string& code) {
    try {
      lua.run_string(code, "t.lua");
    } catch (const ScriptError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST(MeshBindings, HandlesPrintCompareAndReadPointers) {
  Fixture f(make_grid(1, 1));
  const HalfedgeMesh& m = *f.mesh;
  const HalfedgeId h(3);
  EXPECT_EQ(f.run("local h = m:halfedge(3) return tostring(h), tostring(h.next), tostring(h.twin), "
                  "tostring(h.vertex), tostring(h.edge), tostring(h.face), h.id"),
            (Strings{"h3", format_id(m.next(h)), format_id(m.twin(h)), format_id(m.vertex(h)), format_id(m.edge(h)),
                     format_id(m.face(h)), "3"}));
  EXPECT_EQ(f.run("return m:halfedge(3) == m:halfedge(3), m:halfedge(3) == m:halfedge(4), "
                  "m:halfedge(3).twin.twin == m:halfedge(3), m:vertex(0) == m:halfedge(0)"),
            (Strings{"true", "false", "true", "false"}));
  EXPECT_EQ(f.run("local v = m:vertex(2) return tostring(v.halfedge), v.position.x, v.position.y, v.position.z, "
                  "v:degree(), v:is_boundary()"),
            (Strings{format_id(m.halfedge(VertexId(2))), "0.0", "1.0", "0.0", "2", "true"}));  // v2 = (0, 1, 0)
  EXPECT_EQ(f.run("return tostring(m:face(0).halfedge), m:face(0):degree(), m:face(0):is_boundary(), "
                  "tostring(m:boundary(0)), m:boundary(0):is_boundary(), m:boundary(0):degree()"),
            (Strings{format_id(m.halfedge(FaceId::face(0))), "3", "false", "b0", "true", "4"}));
}

TEST(MeshBindings, IteratorsVisitEveryLiveElementInIdOrder) {
  Fixture f(make_grid(1, 1));
  EXPECT_EQ(f.run("local s = {} for h in m:halfedges() do s[#s + 1] = tostring(h) end return table.concat(s, ' ')"),
            Strings{"h0 h1 h2 h3 h4 h5 h6 h7 h8 h9"});
  EXPECT_EQ(f.run("local n = {0, 0, 0, 0} for _ in m:vertices() do n[1] = n[1] + 1 end "
                  "for _ in m:edges() do n[2] = n[2] + 1 end for _ in m:faces() do n[3] = n[3] + 1 end "
                  "for _ in m:boundaries() do n[4] = n[4] + 1 end return table.unpack(n)"),
            (Strings{"4", "5", "2", "1"}));
  EXPECT_EQ(f.run("return m:num_vertices(), m:num_halfedges(), m:num_edges(), m:num_faces(), m:num_boundaries()"),
            (Strings{"4", "10", "5", "2", "1"}));
}

TEST(MeshBindings, ErrorMessages) {
  Fixture f(make_grid(1, 1));
  f.mesh->delete_element(HalfedgeId(7));
  EXPECT_EQ(f.error("local h = m:halfedge(7)\nreturn h.next"), "t.lua:2: attempt to use dead halfedge h7");
  EXPECT_EQ(f.error("m:halfedge(7).next = m:halfedge(1)"), "t.lua:1: attempt to use dead halfedge h7");
  EXPECT_EQ(f.run("return tostring(m:halfedge(7)), m:alive(m:halfedge(7)), m:alive(m:halfedge(6))"),
            (Strings{"h7", "false", "true"}));
  EXPECT_EQ(f.error("local h = m:halfedge(0)\nh:set_neighbors(m:vertex(0), h, h.vertex, h.edge, h.face)"),
            "t.lua:2: bad argument #1 to 'set_neighbors' (halfedge expected, got vertex)");
  EXPECT_EQ(f.error("local h = m:halfedge(0)\nh:set_neighbors(h, h, h.vertex, h.edge, 5)"),
            "t.lua:2: bad argument #5 to 'set_neighbors' (face expected, got number)");
  EXPECT_EQ(f.error("m:flip(m:vertex(0))"), "t.lua:1: bad argument #1 to 'flip' (edge expected, got vertex)");
  EXPECT_EQ(f.error("m:halfedge(0).next = m:vertex(1)"), "t.lua:1: h0.next must be a halfedge or nil, got vertex");
  EXPECT_EQ(f.error("return m:halfedge(0).nxt"), "t.lua:1: h0 has no field 'nxt'");
  EXPECT_EQ(f.error("m:edge(0).twin = nil"), "t.lua:1: cannot set field 'twin' of e0");
  EXPECT_EQ(f.error("return m:halfedge(10)"),
            "t.lua:1: no halfedge with id 10 in this mesh (halfedge ids go from 0 to 9)");
  EXPECT_EQ(f.error("return m:vertex(-1)"), "t.lua:1: no vertex with id -1 in this mesh (vertex ids go from 0 to 3)");
  EXPECT_EQ(f.error("return meshedit.grid(0, 1)"), "t.lua:1: bad argument #1 to 'grid' (must be between 1 and 1000)");
  EXPECT_EQ(f.run("return pcall(meshedit.grid, 1, 0)"),
            (Strings{"false", "bad argument #2 to 'meshedit.grid' (must be between 1 and 1000)"}));
  // A C++ exception (FileError) becomes a Lua error at the calling line.
  EXPECT_EQ(f.error("meshedit.load('no-such-file.obj')"),
            "t.lua:1: no-such-file.obj: cannot open: No such file or directory");
  EXPECT_EQ(f.error("local other = meshedit.grid(1, 1)\nm:halfedge(0).next = other:halfedge(1)"),
            "t.lua:2: h1 belongs to another mesh");
  EXPECT_EQ(f.error("m:save('/nonexistent-dir/x.obj')").rfind("t.lua:1: ", 0), 0u);
}

TEST(MeshBindings, PointerWritesReachTheMesh) {
  Fixture f(make_grid(1, 1));
  f.run(
      "local h = m:halfedge(0)\nh.twin = nil\nh.face = m:boundary(0)\nm:vertex(1).position = {1, 2, 3}\n"
      "m:vertex(2).position = {x = 4, y = 5, z = 6}\nm:edge(1).halfedge = m:halfedge(5)");
  EXPECT_FALSE(f.mesh->twin(HalfedgeId(0)).valid());
  EXPECT_EQ(f.mesh->face(HalfedgeId(0)), FaceId::boundary(0));
  EXPECT_EQ(f.mesh->position(VertexId(1)), glm::dvec3(1, 2, 3));
  EXPECT_EQ(f.mesh->position(VertexId(2)), glm::dvec3(4, 5, 6));
  EXPECT_EQ(f.mesh->halfedge(EdgeId(1)), HalfedgeId(5));
  EXPECT_EQ(f.run("return tostring(m:halfedge(0).twin)"), Strings{"nil"});
}

// The student's flip, written the way the assignment asks (every pointer set with set_neighbors), following
// the picture in core/mesh_ops.h.
constexpr const char* kStudentFlip = R"(
function flip_edge(mesh, e)
  local h0 = e.halfedge
  local h1 = h0.twin
  local h2, h4 = h0.next, h1.next
  local h3, h5 = h2.next, h4.next
  local a, b, c, d = h0.vertex, h1.vertex, h3.vertex, h5.vertex
  local f0, f1 = h0.face, h1.face
  h0:set_neighbors(h3, h1, d, e, f0)
  h3:set_neighbors(h4, h3.twin, c, h3.edge, f0)
  h4:set_neighbors(h0, h4.twin, a, h4.edge, f0)
  h1:set_neighbors(h5, h0, c, e, f1)
  h5:set_neighbors(h2, h5.twin, d, h5.edge, f1)
  h2:set_neighbors(h1, h2.twin, b, h2.edge, f1)
  if a.halfedge == h0 then a.halfedge = h4 end
  if b.halfedge == h1 then b.halfedge = h2 end
  f0.halfedge, f1.halfedge = h0, h1
  return e
end
for e in m:edges() do
  if not e:is_boundary() then return tostring(flip_edge(m, e)) end
end
)";

TEST(MeshBindings, StudentFlipInLuaMatchesTheCoreFlipPointerForPointer) {
  Fixture f(make_grid(1, 1));
  HalfedgeMesh expected = build_halfedge_mesh(make_grid(1, 1));
  EdgeId interior;
  for (EdgeId e : expected.edges()) {
    if (!expected.is_boundary(e)) interior = e;
  }
  ASSERT_TRUE(flip(expected, interior).ok());
  EXPECT_EQ(f.run(kStudentFlip), Strings{format_id(interior)});
  const HalfedgeMesh& got = *f.mesh;
  for (HalfedgeId h : expected.halfedges()) {
    SCOPED_TRACE(format_id(h));
    EXPECT_EQ(got.next(h), expected.next(h));
    EXPECT_EQ(got.twin(h), expected.twin(h));
    EXPECT_EQ(got.vertex(h), expected.vertex(h));
    EXPECT_EQ(got.edge(h), expected.edge(h));
    EXPECT_EQ(got.face(h), expected.face(h));
  }
  for (VertexId v : expected.vertices()) EXPECT_EQ(got.halfedge(v), expected.halfedge(v)) << format_id(v);
  for (EdgeId e : expected.edges()) EXPECT_EQ(got.halfedge(e), expected.halfedge(e)) << format_id(e);
  for (FaceId fc : expected.faces()) EXPECT_EQ(got.halfedge(fc), expected.halfedge(fc)) << format_id(fc);
  EXPECT_TRUE(got.same_as(expected));
}

TEST(MeshBindings, CoreOperationsFromLua) {
  Fixture f(make_grid(1, 1));
  HalfedgeMesh expected = build_halfedge_mesh(make_grid(1, 1));
  const auto split_vertex = split(expected, EdgeId(0));
  ASSERT_TRUE(split_vertex.ok());
  EXPECT_EQ(f.run("return tostring(m:split(m:edge(0)))"), Strings{format_id(split_vertex.value)});
  EXPECT_TRUE(f.mesh->same_as(expected));
  // A refused operation returns nil and the core's reason.
  const Check refused = can_flip(expected, EdgeId(1));
  ASSERT_FALSE(refused.ok);
  EXPECT_EQ(f.run("return m:flip(m:edge(1))"), (Strings{"nil", refused.reason}));
  EXPECT_EQ(f.run("local ok = m:loop_subdivide() return ok, (m:validate()), m:num_faces()"),
            (Strings{"true", "true", "12"}));  // 3 faces after the split, 4 each after subdividing
  // 1,050,000 faces would become 4,200,000, just past the cap of 4,194,304: refused, mesh unchanged.
  EXPECT_EQ(f.run("local g = meshedit.grid(1000, 525) return g:num_faces(), g:loop_subdivide()"),
            (Strings{"1050000", "nil", "loop subdivision would make 4200000 faces; scripts may make at most 4194304"}));
}

TEST(MeshBindings, BrokenMeshCanStillBeValidated) {
  Fixture f(make_grid(1, 1));
  const auto r = f.run(
      "local h = m:halfedge(0)\nh.next = h\n"
      "local ok, report = m:validate()\n"
      "return ok, report.total > 0, report.summary, tostring(report.violations[1].element), "
      "report.violations[1].invariant, report.violations[1].message");
  EXPECT_EQ(r, (Strings{"false", "true", "6 problems; first: h1.face is f0, but h1 is not in f0's next-cycle", "h1",
                        "face cycle", "h1.face is f0, but h1 is not in f0's next-cycle"}));
  // The broken mesh still iterates and prints without hanging.
  EXPECT_EQ(f.run("local n = 0 for h in m:halfedges() do n = n + 1 local _ = tostring(h.next) end return n"),
            Strings{"10"});
}

}  // namespace
}  // namespace meshedit
