// A script that breaks a mesh (h.next = h, cycles that never come back, pointers to deleted elements) never
// crashes or hangs anything: tables, validate, diff, iteration, degree, the walks and the operations all answer,
// with errors that say what is broken. The last test writes thousands of random pointers (fixed seed) and calls
// everything after each batch.
#include <gtest/gtest.h>

#include <string>

#include "core/primitives.h"
#include "core/validate.h"
#include "mesh_script_fixture.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

TEST(BrokenMesh, SelfLoopedHalfedge) {
  MeshScript s(make_grid(1, 1));  // f0's cycle is h0 -> h1 -> h2
  ASSERT_EQ(s.mesh->halfedge(FaceId::face(0)), HalfedgeId(0));
  s.run("snap = m:snapshot()\nlocal h = m:halfedge(1)\nh.next = h");
  EXPECT_EQ(s.run("local t = m:tables() return t.halfedges[2].next, (m:validate()), #m:diff(snap), "
                  "m:face(0):degree(), tostring(m:halfedge(1):prev())"),
            (Strings{"h1", "false", "1", "0", "h1"}));
  EXPECT_EQ(s.run("local n = 0 for v in m:vertices() do n = n + v:degree() end return n"),
            Strings{std::to_string(s.mesh->degree(VertexId(0)) + s.mesh->degree(VertexId(1)) +
                                   s.mesh->degree(VertexId(2)) + s.mesh->degree(VertexId(3)))});
  EXPECT_EQ(s.error("for h in m:face(0):halfedges() do end"), "t.lua:1: the next-cycle of f0 does not close");
  EXPECT_EQ(s.error("return m:halfedge(0):prev()"), "t.lua:1: the next-cycle from h0 does not come back to it");
  const Strings flip = s.run("return m:flip(m:halfedge(0).edge)");
  EXPECT_EQ(flip[0], "nil");
  EXPECT_FALSE(flip[1].empty());
  EXPECT_EQ(s.run("return m:loop_subdivide()")[0], "nil");
  const std::string save = s.error("m:save('/tmp/never-written.obj')");
  EXPECT_EQ(save.rfind("t.lua:1: ", 0), 0u) << save;
  EXPECT_NE(save.find("f0"), std::string::npos) << save;
  EXPECT_EQ(s.run("m:restore(snap) return (m:validate())"), Strings{"true"});
}

TEST(BrokenMesh, CycleThatNeverComesBack) {
  MeshScript s(make_grid(2, 2));
  // h0 -> h1 -> h2 -> h1 ...: a "rho"; walks from h0 must stop.
  s.run("local h0, h1, h2 = m:halfedge(0), m:halfedge(1), m:halfedge(2)\nh2.next = h1");
  EXPECT_EQ(s.run("return m:face(0):degree(), (m:validate())"), (Strings{"0", "false"}));
  EXPECT_EQ(s.error("return m:halfedge(0):prev()"), "t.lua:1: the next-cycle from h0 does not come back to it");
  EXPECT_EQ(s.error("for v in m:face(0):vertices() do end"), "t.lua:1: the next-cycle of f0 does not close");
  EXPECT_EQ(s.run("local n = 0 for v in m:vertices() do n = n + v:degree() end return n > 0")[0], "true");
}

TEST(BrokenMesh, PointersToDeletedElements) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeId twin = s.mesh->twin(HalfedgeId(0));
  s.run("local h = m:halfedge(0)\nm:delete(h.twin)\nm:delete(h.vertex)\nm:delete(h.face)\nm:delete(h.edge)");
  EXPECT_EQ(s.run("local h = m:halfedge(0) return tostring(h.twin), m:alive(h.twin), tostring(h.vertex), "
                  "tostring(h.face), h:is_boundary()"),
            (Strings{format_id(twin), "false", "v0", "f0", "false"}));
  EXPECT_EQ(s.error("return m:halfedge(0).twin.next"), "t.lua:1: attempt to use dead halfedge " + format_id(twin));
  EXPECT_EQ(s.error("return m:halfedge(0).vertex:degree()"), "t.lua:1: attempt to use dead vertex v0");
  EXPECT_EQ(s.error("m:halfedge(1).next = m:halfedge(0).twin"),
            "t.lua:1: attempt to use dead halfedge " + format_id(twin));
  const Strings flip = s.run("return m:flip(m:edge(1))");
  EXPECT_EQ(flip[0], "nil");
  const ValidationReport report = validate(*s.mesh);
  EXPECT_EQ(s.run("local ok, r = m:validate() return r.total, #m:tables().halfedges"),
            (Strings{std::to_string(report.total), "9"}));
  // A handle of an element created after a snapshot reads as dead once the snapshot is restored.
  EXPECT_EQ(s.error("local s = m:snapshot()\nlocal v = m:new_vertex()\nm:restore(s)\nv.position = {1, 2, 3}"),
            "t.lua:4: attempt to use dead vertex v4");
}

// Random writes with the runtime's fixed seed; after every batch, everything is called (under pcall where a
// broken mesh may make it fail). Returns the failures whose message is not one of the expected ones.
constexpr const char* kFuzz = R"(
local kinds = {"vertices", "halfedges", "edges", "faces", "boundaries"}
local function pick(kind)
  local list = {}
  for x in m[kind](m) do list[#list + 1] = x end
  if #list == 0 then return nil end
  return list[math.random(#list)]
end
local writes = {
  {"halfedges", "next", "halfedges"}, {"halfedges", "twin", "halfedges"}, {"halfedges", "vertex", "vertices"},
  {"halfedges", "edge", "edges"}, {"halfedges", "face", "faces"}, {"halfedges", "face", "boundaries"},
  {"vertices", "halfedge", "halfedges"}, {"edges", "halfedge", "halfedges"}, {"faces", "halfedge", "halfedges"},
  {"boundaries", "halfedge", "halfedges"},
}
local reads = {halfedges = {"next", "twin", "vertex", "edge", "face"}, vertices = {"halfedge", "position"},
               edges = {"halfedge"}, faces = {"halfedge"}, boundaries = {"halfedge"}}
local expected = {"does not close", "do not close into a fan", "does not come back", "attempt to use dead"}
local unexpected, failures, calls = {}, 0, 0
local function check(ok, err)
  calls = calls + 1
  if ok then return end
  failures = failures + 1
  for _, e in ipairs(expected) do if tostring(err):find(e, 1, true) then return end end
  if #unexpected < 5 then unexpected[#unexpected + 1] = tostring(err) end
end
local base = m:snapshot()
local function inspect()
  local t = m:tables()
  local ok, report = m:validate()
  assert(ok or report.total > 0)
  local d = m:diff(base)
  for _, kind in ipairs(kinds) do
    for x in m[kind](m) do
      for _, f in ipairs(reads[kind]) do
        check(pcall(function()
          local y = x[f]
          if type(y) == "userdata" and y.kind == "halfedge" then return tostring(y), y.next end
        end))
      end
      check(pcall(function() return x:is_boundary() end))
      if kind == "halfedges" then check(pcall(function() return x:prev() end)) end
      if kind ~= "halfedges" and kind ~= "edges" then
        check(pcall(function() return x:degree() end))
        check(pcall(function() for _ in x:halfedges() do end end))
        if kind == "vertices" then check(pcall(function() for _ in x:neighbors() do end end))
        else check(pcall(function() for _ in x:vertices() do end end)) end
      end
    end
  end
end
for round = 1, 40 do
  for i = 1, 25 do
    local r = math.random(20)
    if r <= 15 then
      local w = writes[math.random(#writes)]
      local x = pick(w[1])
      local value = nil
      if math.random(6) > 1 then value = pick(w[3]) end
      if x then x[w[2]] = value end
    elseif r == 16 then
      local x = pick(kinds[math.random(5)])
      if x then m:delete(x) end
    elseif r == 17 then
      local kind = ({"vertex", "halfedge", "edge", "face", "boundary"})[math.random(5)]
      m["new_" .. kind](m)
    else
      local e = pick("edges")
      if e then
        local op = ({"flip", "split", "collapse"})[r - 17]
        m[op](m, e)
      end
    end
  end
  inspect()
  if m:loop_subdivide() then m:undo() end
  if round % 10 == 0 then m:undo() m:redo() end
end
return #unexpected, table.concat(unexpected, " | "), failures > 0, calls > 10000
)";

TEST(BrokenMesh, RandomWritesNeverCrashOrHang) {
  for (const PolygonMesh& shape : {make_grid(3, 3), make_icosahedron()}) {
    MeshScript s(shape);
    EXPECT_EQ(s.run(kFuzz, "fuzz.lua"), (Strings{"0", "", "true", "true"}));
  }
}

}  // namespace
}  // namespace meshedit
