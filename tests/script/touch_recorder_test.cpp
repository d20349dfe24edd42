// TouchRecorder: each element a script reaches (a handle made: an iterator's step, a field read, a lookup, new_*) is
// counted once; a change counts as written; a call that reads the whole mesh is named and counts every element; a
// scratch copy's elements and changes are not counted; recorders nest, stop, and outlive their Lua state.
#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include <lua.hpp>

#include "core/primitives.h"
#include "mesh_script_fixture.h"
#include "script/touch_recorder.h"

namespace meshedit {
namespace {

using testing::MeshScript;

size_t live_elements(const HalfedgeMesh& m) {
  return m.num_vertices() + m.num_halfedges() + m.num_edges() + m.num_faces() + m.num_boundaries();
}

TEST(TouchRecorder, CountsEachElementReachedOnce) {
  MeshScript s(make_grid(4, 4));
  TouchRecorder touches(s.lua.state(), s.mesh);
  // h0, h0.next, h0.twin, read five times over: three elements, none written.
  s.run("for i = 1, 5 do local h = m:halfedge(0); local n, t = h.next, h.twin end");
  TouchCount count = touches.count();
  EXPECT_EQ(count.elements, 3u);
  EXPECT_EQ(count.written, 0u);
  EXPECT_EQ(count.whole_mesh_call, "");
  // h0.face reaches f0; the handle kept in a local is not a new touch when read again.
  s.run("local h = m:halfedge(0); local f = h.face; local again = m:element('h0')");
  EXPECT_EQ(touches.count().elements, 4u);
}

TEST(TouchRecorder, CountsWritesAndNewElementsAsWritten) {
  MeshScript s(make_grid(4, 4));
  TouchRecorder touches(s.lua.state(), s.mesh);
  // h0.next is written with the value it has: a write all the same.
  s.run("local h = m:halfedge(0); h.next = h.next; h.next = h.next");
  EXPECT_EQ(touches.count().elements, 2u);  // h0 and its next
  EXPECT_EQ(touches.count().written, 1u);
  s.run("local v = m:new_vertex({0, 0, 1}); local h = m:halfedge(0); h.next = h.next");
  const TouchCount count = touches.count();
  EXPECT_EQ(count.written, 2u);  // h0 again, and the new vertex
  EXPECT_EQ(count.elements, 3u);
}

TEST(TouchRecorder, ALoopOverTheMeshTouchesEveryElementItVisits) {
  MeshScript s(make_grid(10, 10));
  TouchRecorder touches(s.lua.state(), s.mesh);
  s.run("for h in m:halfedges() do end");
  EXPECT_EQ(touches.count().elements, s.mesh->num_halfedges());
  s.run("for h in m:halfedges() do local f = h.face end");
  EXPECT_EQ(touches.count().elements, s.mesh->num_halfedges() + s.mesh->num_faces() + s.mesh->num_boundaries());
}

TEST(TouchRecorder, ACallThatReadsTheWholeMeshIsNamedAndCountsEveryElement) {
  for (const char* call : {"mesh:copy()", "mesh:validate()", "mesh:snapshot()", "mesh:tables()", "mesh:diff()"}) {
    SCOPED_TRACE(call);
    MeshScript s(make_grid(3, 3));
    TouchRecorder touches(s.lua.state(), s.mesh);
    s.run("local e = m:edge(0)");
    const std::string name = std::string(call).substr(5, std::string(call).find('(') - 5);
    s.run(name == "diff" ? "local d = m:diff(m:snapshot())" : "local x = m:" + name + "()");
    const TouchCount count = touches.count();
    // The first whole-mesh call is named (the diff's snapshot comes first).
    EXPECT_EQ(count.whole_mesh_call, name == "diff" ? "mesh:snapshot()" : call);
    EXPECT_EQ(count.elements, live_elements(*s.mesh));
  }
}

TEST(TouchRecorder, AWholeMeshOperationCountsEveryElement) {
  MeshScript s(make_grid(3, 3));
  s.run("snap = m:snapshot()");
  TouchRecorder touches(s.lua.state(), s.mesh);
  s.run("m:restore(snap)");
  EXPECT_EQ(touches.count().whole_mesh_call, "mesh:restore()");
  EXPECT_EQ(touches.count().elements, live_elements(*s.mesh));
}

TEST(TouchRecorder, AScratchCopyIsNotCountedAfterTheCopy) {
  MeshScript s(make_grid(3, 3));
  auto other = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_grid(6, 6)));
  push_mesh(s.lua.state(), other);
  lua_setglobal(s.lua.state(), "other");
  TouchRecorder touches(s.lua.state(), s.mesh);
  s.run("for h in other:halfedges() do h.next = h.next end; local v = other:new_vertex()");
  EXPECT_EQ(touches.count().elements, 0u);
  EXPECT_EQ(touches.count().written, 0u);
}

TEST(TouchRecorder, RecordersNestStopAndOutliveTheirState) {
  std::optional<TouchRecorder> outer;
  {
    MeshScript s(make_grid(3, 3));
    outer.emplace(s.lua.state(), s.mesh);
    s.run("local h = m:halfedge(0)");
    {
      TouchRecorder inner(s.lua.state(), s.mesh);
      s.run("local h = m:halfedge(1)");
      EXPECT_EQ(inner.count().elements, 1u);
      inner.stop();
      s.run("local h = m:halfedge(2)");
      EXPECT_EQ(inner.count().elements, 1u);
    }
    EXPECT_EQ(outer->count().elements, 3u);
  }
  // The state closed: the count stays, and stopping again is harmless.
  EXPECT_EQ(outer->count().elements, 3u);
  outer->stop();
  EXPECT_EQ(outer->count().elements, 3u);
}

}  // namespace
}  // namespace meshedit
