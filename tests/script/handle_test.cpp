// Element handles as values since they became plain userdata anchored to their mesh (binding_support.h,
// handle_context.h): equality across boxes and reads, a handle outliving every other reference to its mesh,
// dead handles, how keys are understood (interned or built at run time, numbers, other types), and that
// collections in the middle of walks and writes never leave a handle pointing at nothing.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <lua.hpp>

#include "core/primitives.h"
#include "mesh_script_fixture.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

TEST(Handles, EqualWhenSameElementOfSameMeshWhicheverBoxOrReadMadeThem) {
  MeshScript s(make_grid(1, 1));
  // A second mesh userdata (box) for the same C++ mesh, as a host or the grader's bridge makes.
  push_mesh(s.lua.state(), s.mesh);
  lua_setglobal(s.lua.state(), "m2");
  EXPECT_EQ(s.run("local h = m:halfedge(3) return h == m2:halfedge(3), h == h.twin.twin, h == h.next.next.next, "
                  "h.mesh == m, h.mesh:halfedge(3) == h, m2:halfedge(3).mesh == m"),
            (Strings{"true", "true", "true", "true", "true", "true"}));
  EXPECT_EQ(s.run("local c = m:copy() return m:halfedge(3) == c:halfedge(3), m:halfedge(3) == m:halfedge(4), "
                  "m:vertex(0) == m:halfedge(0), m:face(0) == m:edge(0), m:vertex(0) == m, m:vertex(0) == 'v0'"),
            (Strings{"false", "false", "false", "false", "false", "false"}));
  // Handles from iteration and from walks are the same elements as those read by id.
  EXPECT_EQ(s.run("for h in m:halfedges() do if h ~= m:halfedge(h.id) then return 'iteration' end end "
                  "for h in m:face(0):halfedges() do if h.face ~= m:face(0) then return 'walk' end end "
                  "for v in m:vertex(0):neighbors() do if v ~= m:vertex(v.id) then return 'neighbors' end end "
                  "return 'same'"),
            Strings{"same"});
  EXPECT_EQ(s.run("return tostring(m:halfedge(3)), tostring(m2:halfedge(3).next), type(m:vertex(1)), m:edge(2).kind"),
            (Strings{"h3", "h4", "userdata", "edge"}));
}

TEST(Handles, KeepTheirMeshAliveAfterEveryOtherReferenceIsGone) {
  MeshScript s(make_grid(1, 1));
  EXPECT_EQ(s.run("local h = meshedit.grid(2, 1):halfedge(0)\n"
                  "for i = 1, 3 do collectgarbage('collect') end\n"
                  "local t = {} for i = 1, 2000 do t[i] = {i} end t = nil collectgarbage('collect')\n"
                  "return tostring(h.next), h.next.next.next == h, h.mesh:num_faces(), h.face:degree()"),
            (Strings{"h1", "true", "4", "3"}));

  // The C++ side lets go of its mesh; the handle in a global keeps it, and releases it once it is dropped.
  std::weak_ptr<HalfedgeMesh> watch;
  {
    MeshScript t(make_grid(1, 1));
    watch = t.mesh;
    const std::string halfedge = format_id(t.mesh->halfedge(VertexId(2)));
    t.run("keep = m:vertex(2) m = nil");
    t.mesh.reset();
    t.run("collectgarbage('collect') collectgarbage('collect')");
    EXPECT_FALSE(watch.expired());
    EXPECT_EQ(t.run("return tostring(keep.halfedge), keep.position.y, keep:degree()"), (Strings{halfedge, "1.0", "2"}));
    t.run("keep = nil collectgarbage('collect') collectgarbage('collect')");
    EXPECT_TRUE(watch.expired());
  }
}

TEST(Handles, DeadElementsRefuseEverythingButIdAndKind) {
  MeshScript s(make_grid(1, 1));
  s.mesh->delete_element(HalfedgeId(7));
  s.mesh->delete_element(VertexId(3));
  EXPECT_EQ(s.run("local h = m:halfedge(7) return h.id, h.kind, tostring(h), h == m:halfedge(7), m:alive(h)"),
            (Strings{"7", "halfedge", "h7", "true", "false"}));
  EXPECT_EQ(s.error("local h = m:halfedge(7)\nreturn h.twin"), "t.lua:2: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local h = m:halfedge(7)\nreturn h.nonsense"), "t.lua:2: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local h = m:halfedge(7)\nreturn h.mesh"), "t.lua:2: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local v = m:vertex(3)\nreturn v:degree()"), "t.lua:2: attempt to use dead vertex v3");
  EXPECT_EQ(s.error("local v = m:vertex(3)\nv.position = {1, 2, 3}"), "t.lua:2: attempt to use dead vertex v3");
  EXPECT_EQ(s.error("m:halfedge(0).next = m:halfedge(7)"), "t.lua:1: attempt to use dead halfedge h7");
  EXPECT_EQ(s.error("local h = m:halfedge(0)\nh:set_neighbors(h, m:halfedge(7), h.vertex, h.edge, h.face)"),
            "t.lua:2: attempt to use dead halfedge h7");
  // A pointer to a dead element still reads (a broken mesh stays inspectable).
  s.mesh->set_next(HalfedgeId(0), HalfedgeId(7));
  EXPECT_EQ(s.run("return tostring(m:halfedge(0).next)"), Strings{"h7"});
}

TEST(Handles, KeysAreUnderstoodHoweverTheStringWasMade) {
  MeshScript s(make_grid(1, 1));
  // Keys built at run time are the same interned strings as the literals.
  EXPECT_EQ(s.run("local h = m:halfedge(0) local k = 'ne' .. 'xt' "
                  "return tostring(h[k]), tostring(h[('TWIN'):lower()]), h[string.rep('i', 1) .. 'd'], "
                  "h.vertex:degree(), h[table.concat({'is', 'boundary'}, '_')](h)"),
            (Strings{"h1", format_id(s.mesh->twin(HalfedgeId(0))), "0", std::to_string(s.mesh->degree(VertexId(0))),
                     "false"}));
  EXPECT_EQ(s.run("local h = m:halfedge(0) local k = 'ne' .. 'xt' h[k] = h.next return tostring(h.next)"),
            Strings{"h1"});
  EXPECT_EQ(s.error("return m:halfedge(0)[1]"), "t.lua:1: h0 has no field '1'");
  EXPECT_EQ(s.error("return m:halfedge(0)[string.rep('x', 60)]"),
            "t.lua:1: h0 has no field '" + std::string(60, 'x') + "'");
  EXPECT_EQ(s.error("return m:edge(0):degree()"), "t.lua:1: e0 has no field 'degree'");
  EXPECT_EQ(s.error("return m:vertex(0).next"), "t.lua:1: v0 has no field 'next'");
  EXPECT_EQ(s.error("m:vertex(0).id = 3"), "t.lua:1: cannot set field 'id' of v0");
  EXPECT_NE(s.error("return m:halfedge(0)[{}]").find("string expected, got table"), std::string::npos);
  // A method taken from one handle and called on something else is refused like any bad argument.
  EXPECT_EQ(s.error("local degree = m:vertex(0).degree\nreturn degree(m)"),
            "t.lua:2: bad argument #1 to 'degree' (vertex or face expected, got mesh)");
  EXPECT_EQ(s.error("local degree = m:vertex(0).degree\nreturn degree(m:edge(0))"),
            "t.lua:2: bad argument #1 to 'degree' (vertex or face expected, got edge)");
}

TEST(Handles, CollectionsDuringWalksAndWritesLeaveEveryHandleValid) {
  MeshScript s(make_grid(1, 1));
  // Meshes made and dropped in a loop while handles of them are read, compared, written and collected.
  EXPECT_EQ(s.run("local kept = {}\n"
                  "for i = 1, 200 do\n"
                  "  local g = meshedit.grid(3, 2)\n"
                  "  for h in g:halfedges() do\n"
                  "    local n = h.next\n"
                  "    if n.next.next ~= h and not h.face:is_boundary() then error('walk ' .. tostring(h)) end\n"
                  "    h.next = n\n"
                  "  end\n"
                  "  kept[i % 7] = g:vertex(i % g:num_vertices())\n"
                  "  if i % 50 == 0 then collectgarbage('collect') end\n"
                  "end\n"
                  "collectgarbage('collect')\n"
                  "local n = 0 for _, v in pairs(kept) do n = n + v:degree() end\n"
                  "return n > 0, kept[1].mesh:num_faces()"),
            (Strings{"true", "12"}));
}

}  // namespace
}  // namespace meshedit
