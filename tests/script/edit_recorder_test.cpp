// Pointer-write recording: a student-style split written only with new_* and pointer writes matches the core's
// split pointer for pointer; recording it gives one edit per write with the right file:line; replaying any
// prefix of the log steps through exactly those writes and ends same_as the mesh the script made. Also
// mesh:record, what is and is not recorded, nesting, the cap, and a recorder outliving its Lua state.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/edit_log.h"
#include "core/history.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/value_format.h"
#include "mesh_script_fixture.h"
#include "script/edit_recorder.h"
#include "script/script_runtime.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

// The assignment's split, in the names and the allocation order of core/mesh_ops.h, one write per line.
constexpr const char* kStudentSplit = R"(function split_edge(mesh, e)
  local h0 = e.halfedge
  if h0.face:is_boundary() then h0 = h0.twin end
  local h1 = h0.twin
  local interior = not h1.face:is_boundary()
  local h2 = h0.next
  local h3 = h2.next
  local h4 = h1.next
  local h5 = interior and h4.next or nil
  local a, b, c = h0.vertex, h1.vertex, h3.vertex
  local d = interior and h5.vertex or nil
  local f0, f1 = h0.face, h1.face
  local m = mesh:new_vertex((a.position + b.position) * 0.5)
  local ea = mesh:new_edge()
  local ec = mesh:new_edge()
  local ed = interior and mesh:new_edge() or nil
  local g0 = mesh:new_face()
  local g1 = interior and mesh:new_face() or nil
  local n0 = mesh:new_halfedge()
  local n1 = mesh:new_halfedge()
  local n2 = mesh:new_halfedge()
  local n3 = mesh:new_halfedge()
  local n4 = interior and mesh:new_halfedge() or nil
  local n5 = interior and mesh:new_halfedge() or nil
  n0:set_neighbors(n2, n1, a, ea, g0)
  n2:set_neighbors(h3, n3, m, ec, g0)
  n3:set_neighbors(h0, n2, c, ec, f0)
  h0.vertex = m
  h2.next = n3
  h3.next = n0
  h3.face = g0
  f0.halfedge = h0
  g0.halfedge = n0
  if interior then
    n1:set_neighbors(h4, n0, m, ea, g1)
    n4:set_neighbors(h5, n5, m, ed, f1)
    n5:set_neighbors(n1, n4, d, ed, g1)
    h1.next = n4
    h4.next = n5
    h4.face = g1
    f1.halfedge = h1
    g1.halfedge = n1
    ed.halfedge = n4
  else
    n1:set_neighbors(h4, n0, m, ea, f1)
    h1.next = n1
  end
  ea.halfedge = n0
  ec.halfedge = n2
  m.halfedge = n1
  if a.halfedge == h0 then a.halfedge = n0 end
  return m
end
)";

// The 1-based line of the one line of kStudentSplit containing `marker`.
int line_of(const std::string& marker) {
  const std::string text = kStudentSplit;
  const size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  EXPECT_EQ(text.find(marker, at + 1), std::string::npos) << marker << " is not unique";
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

// The `where` of every edit the student's split makes on edge e, in order.
std::vector<std::string> expected_wheres(const HalfedgeMesh& before, EdgeId e) {
  HalfedgeId h0 = before.halfedge(e);
  if (before.face(h0).is_boundary()) h0 = before.twin(h0);
  const bool interior = !before.face(before.twin(h0)).is_boundary();
  const bool moves_a = before.halfedge(before.vertex(h0)) == h0;
  std::vector<std::pair<std::string, int>> steps = {{"new_vertex", 1}, {"local ea", 1}, {"local ec", 1}};
  if (interior) steps.insert(steps.end(), {{"local ed", 1}});
  steps.push_back({"local g0", 1});
  if (interior) steps.push_back({"local g1", 1});
  for (const char* n : {"local n0", "local n1", "local n2", "local n3"}) steps.push_back({n, 1});
  if (interior) steps.insert(steps.end(), {{"local n4", 1}, {"local n5", 1}});
  steps.insert(steps.end(), {{"n0:set_neighbors", 5},
                             {"n2:set_neighbors", 5},
                             {"n3:set_neighbors", 5},
                             {"h0.vertex = m", 1},
                             {"h2.next = n3", 1},
                             {"h3.next = n0", 1},
                             {"h3.face = g0", 1},
                             {"f0.halfedge = h0", 1},
                             {"g0.halfedge = n0", 1}});
  if (interior) {
    steps.insert(steps.end(), {{"n1:set_neighbors(h4, n0, m, ea, g1)", 5},
                               {"n4:set_neighbors", 5},
                               {"n5:set_neighbors", 5},
                               {"h1.next = n4", 1},
                               {"h4.next = n5", 1},
                               {"h4.face = g1", 1},
                               {"f1.halfedge = h1", 1},
                               {"g1.halfedge = n1", 1},
                               {"ed.halfedge = n4", 1}});
  } else {
    steps.insert(steps.end(), {{"n1:set_neighbors(h4, n0, m, ea, f1)", 5}, {"h1.next = n1", 1}});
  }
  steps.insert(steps.end(), {{"ea.halfedge = n0", 1}, {"ec.halfedge = n2", 1}, {"m.halfedge = n1", 1}});
  if (moves_a) steps.push_back({"then a.halfedge = n0", 1});
  std::vector<std::string> wheres;
  for (const auto& [marker, count] : steps) {
    for (int i = 0; i < count; ++i) wheres.push_back("split.lua:" + std::to_string(line_of(marker)));
  }
  return wheres;
}

void expect_same_pointers(const HalfedgeMesh& got, const HalfedgeMesh& expected) {
  ASSERT_EQ(got.halfedge_capacity(), expected.halfedge_capacity());
  for (HalfedgeId h : expected.halfedges()) {
    SCOPED_TRACE(format_id(h));
    EXPECT_EQ(format_id(got.next(h)), format_id(expected.next(h)));
    EXPECT_EQ(format_id(got.twin(h)), format_id(expected.twin(h)));
    EXPECT_EQ(format_id(got.vertex(h)), format_id(expected.vertex(h)));
    EXPECT_EQ(format_id(got.edge(h)), format_id(expected.edge(h)));
    EXPECT_EQ(format_id(got.face(h)), format_id(expected.face(h)));
  }
  for (VertexId v : expected.vertices()) EXPECT_EQ(got.halfedge(v), expected.halfedge(v)) << format_id(v);
  for (EdgeId e : expected.edges()) EXPECT_EQ(got.halfedge(e), expected.halfedge(e)) << format_id(e);
  for (FaceId f : expected.faces()) EXPECT_EQ(got.halfedge(f), expected.halfedge(f)) << format_id(f);
  for (FaceId b : expected.boundaries()) EXPECT_EQ(got.halfedge(b), expected.halfedge(b)) << format_id(b);
  EXPECT_TRUE(got.same_as(expected));
}

// Runs the student's split on edge e of a fresh grid(1, 1) under an EditRecorder, checks the result against the
// core's split, every record's place, and the replay of every prefix.
void check_recorded_split(EdgeId e) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh before = *s.mesh;
  HalfedgeMesh expected = before;
  const OpResult<VertexId> made = split(expected, e);
  ASSERT_TRUE(made.ok()) << made.check.reason;

  s.run(kStudentSplit, "student/split.lua");
  EditRecorder recorder(s.lua.state(), s.mesh);
  EXPECT_EQ(s.run("return tostring(split_edge(m, m:edge(" + std::to_string(e.index) + ")))"),
            Strings{format_id(made.value)});
  recorder.stop();
  expect_same_pointers(*s.mesh, expected);
  ASSERT_TRUE(recorder.before());
  EXPECT_TRUE(recorder.before()->same_as(before));

  const std::vector<RecordedEdit>& log = recorder.edits();
  const std::vector<std::string> wheres = expected_wheres(before, e);
  ASSERT_EQ(log.size(), wheres.size());
  for (size_t i = 0; i < log.size(); ++i)
    EXPECT_EQ(log[i].where, wheres[i]) << "edit " << i << ": " << describe(log[i]);
  EXPECT_EQ(describe(log[0]),
            "new " + format_id(made.value) + " at " + describe(log[0]).substr(describe(log[0]).find(" at ") + 4));
  EXPECT_EQ(log[0].value.position, expected.position(made.value));

  // Each step of the replay makes exactly the change its record describes.
  HalfedgeMesh previous = before;
  for (size_t k = 1; k <= log.size(); ++k) {
    SCOPED_TRACE("step " + std::to_string(k) + ": " + describe(log[k - 1]));
    const HalfedgeMesh step = replay(before, log, k);
    const std::vector<FieldChange> changes = diff(previous, step);
    const RecordedEdit& edit = log[k - 1];
    if (edit.what == EditKind::Set) {
      const bool same = format_edit_before(edit) == format_edit_after(edit);
      ASSERT_EQ(changes.size(), same ? 0u : 1u);
      if (!same) {
        EXPECT_EQ(changes[0].element, edit.element);
        EXPECT_EQ(changes[0].field, edit.field);
        EXPECT_EQ(changes[0].before, format_edit_before(edit));
        EXPECT_EQ(changes[0].after, format_edit_after(edit));
      }
    } else {
      ASSERT_EQ(edit.what, EditKind::Create);
      ASSERT_FALSE(changes.empty());
      for (const FieldChange& c : changes) EXPECT_EQ(c.element, edit.element);
    }
    previous = step;
  }
  EXPECT_TRUE(replay(before, log, 0).same_as(before));
  EXPECT_TRUE(previous.same_as(*s.mesh));
  EXPECT_TRUE(previous.same_as(expected));
}

TEST(EditRecorder, StudentSplitOfAnInteriorEdgeRecordsEveryWriteWithItsLine) {
  const HalfedgeMesh grid = build_halfedge_mesh(make_grid(1, 1));
  EdgeId interior;
  for (EdgeId e : grid.edges()) {
    if (!grid.is_boundary(e)) interior = e;
  }
  ASSERT_TRUE(interior.valid());
  check_recorded_split(interior);
}

TEST(EditRecorder, StudentSplitOfABoundaryEdgeRecordsEveryWriteWithItsLine) {
  const HalfedgeMesh grid = build_halfedge_mesh(make_grid(1, 1));
  for (EdgeId e : grid.edges()) {
    if (grid.is_boundary(e)) {
      SCOPED_TRACE(format_id(e));
      check_recorded_split(e);
    }
  }
}

TEST(EditRecorder, StudentSplitMatchesTheCoreOnEveryEdge) {
  for (const PolygonMesh& shape : {make_icosahedron(), make_grid(2, 2), make_cube()}) {
    const HalfedgeMesh start = build_halfedge_mesh(shape);
    for (EdgeId e : start.edges()) {
      HalfedgeMesh expected = start;
      if (!split(expected, e).ok()) continue;  // the cube's quads: the core refuses, the student's would not apply
      SCOPED_TRACE(format_id(e));
      MeshScript s(shape);
      s.run(kStudentSplit, "split.lua");
      s.run("split_edge(m, m:edge(" + std::to_string(e.index) + "))");
      expect_same_pointers(*s.mesh, expected);
    }
  }
}

TEST(EditRecorder, LuaRecordReturnsTheLog) {
  MeshScript s(make_grid(1, 1));
  s.run(kStudentSplit, "split.lua");
  const std::string where_new = "split.lua:" + std::to_string(line_of("new_vertex"));
  const std::string where_h0 = "split.lua:" + std::to_string(line_of("h0.vertex = m"));
  const Strings got = s.run(
      "local log = m:record(function() split_edge(m, m:edge(0)) end)\n"
      "local first, write\n"
      "for _, r in ipairs(log) do if r.field == 'vertex' and r.what == 'set' and r.where == '" +
      where_h0 +
      "' then write = r end end\n"
      "first = log[1]\n"
      "return #log, first.what, first.element, first.field, first.before, first.after, first.where, "
      "tostring(first.position), write.element, write.before, write.after");
  HalfedgeMesh core = build_halfedge_mesh(make_grid(1, 1));
  HalfedgeId h0 = core.halfedge(EdgeId(0));
  if (core.face(h0).is_boundary()) h0 = core.twin(h0);
  const VertexId a = core.vertex(h0);
  const glm::dvec3 mid = (core.position(a) + core.position(core.vertex(core.twin(h0)))) * 0.5;
  const VertexId made = split(core, EdgeId(0)).value;
  EXPECT_EQ(got[0], std::to_string(expected_wheres(build_halfedge_mesh(make_grid(1, 1)), EdgeId(0)).size()));
  EXPECT_EQ(got[1], "new");
  EXPECT_EQ(got[2], format_id(made));
  EXPECT_EQ(got[3], "alive");
  EXPECT_EQ(got[4], "-");
  EXPECT_EQ(got[5], "alive");
  EXPECT_EQ(got[6], where_new);
  EXPECT_EQ(got[7], format_position(mid));
  EXPECT_EQ(got[8], format_id(h0));
  EXPECT_EQ(got[9], format_id(a));
  EXPECT_EQ(got[10], format_id(made));
  EXPECT_TRUE(s.mesh->same_as(core));
  EXPECT_EQ(s.error("m:record(5)"), "t.lua:1: bad argument #1 to 'record' (function expected, got number)");
}

TEST(EditRecorder, RecordsOperationsAndStateChangesAndReplaysThem) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh before = *s.mesh;
  EditRecorder recorder(s.lua.state(), s.mesh);
  s.run(
      "local snap = m:snapshot()\n"         // 1
      "m:split(m:edge(0))\n"                // 2
      "m:vertex(0).position = {0, 0, 1}\n"  // 3
      "m:flip(m:edge(2))\n"                 // 4 (refused or not: only accepted ones are recorded)
      "m:restore(snap)\n"                   // 5
      "m:undo()\n"                          // 6
      "m:delete(m:halfedge(0))\n"           // 7
      "m:loop_subdivide()\n",               // 8 (refused: the mesh is broken now)
      "ops.lua");
  recorder.stop();
  std::vector<std::string> seen;
  for (const RecordedEdit& edit : recorder.edits()) seen.push_back(describe(edit) + " @" + edit.where);
  HalfedgeMesh flipped = before;
  ASSERT_TRUE(split(flipped, EdgeId(0)).ok());
  const bool flip_ok = can_flip(flipped, EdgeId(2)).ok;
  std::vector<std::string> expected = {"split e0 -> v4 @ops.lua:2",
                                       "v0.position = (0, 0, 1) (was (0, 0, 0)) @ops.lua:3"};
  if (flip_ok) expected.push_back("flip e2 @ops.lua:4");
  expected.insert(expected.end(), {"restore @ops.lua:5", "undo @ops.lua:6", "delete h0 @ops.lua:7"});
  EXPECT_EQ(seen, expected);
  EXPECT_TRUE(replay(before, recorder.edits(), recorder.edits().size()).same_as(*s.mesh));
  // The undo step brings back the state before the restore.
  const size_t undo_step = flip_ok ? 5 : 4;
  HalfedgeMesh before_restore = replay(before, recorder.edits(), undo_step - 2);
  EXPECT_TRUE(replay(before, recorder.edits(), undo_step).same_as(before_restore));
}

TEST(EditRecorder, WatchesOnlyItsMeshAndStopsWhenAsked) {
  MeshScript s(make_grid(1, 1));
  EditRecorder recorder(s.lua.state(), s.mesh, {.keep_before = false, .max_edits = 100});
  EXPECT_FALSE(recorder.before());
  s.run(
      "local scratch = m:copy()\nscratch:halfedge(0).twin = nil\nm:halfedge(1).twin = nil\n"
      "co = coroutine.wrap(function()\n  m:halfedge(2).twin = nil\n  coroutine.yield()\nend)\nco()",
      "dir/sub/w.lua");
  ASSERT_EQ(recorder.edits().size(), 2u);
  EXPECT_EQ(describe(recorder.edits()[0]),
            "h1.twin = - (was " + format_id(build_halfedge_mesh(make_grid(1, 1)).twin(HalfedgeId(1))) + ")");
  EXPECT_EQ(recorder.edits()[0].where, "w.lua:3");
  EXPECT_EQ(recorder.edits()[1].where, "w.lua:5");  // inside the coroutine
  recorder.stop();
  EXPECT_FALSE(recorder.recording());
  s.run("m:halfedge(3).twin = nil");
  EXPECT_EQ(recorder.edits().size(), 2u);
  const std::vector<RecordedEdit> taken = recorder.take_edits();
  EXPECT_EQ(taken.size(), 2u);
}

TEST(EditRecorder, NestedRecordersBothSeeEveryChange) {
  MeshScript s(make_grid(1, 1));
  EditRecorder outer(s.lua.state(), s.mesh);
  EXPECT_EQ(s.run("local log = m:record(function()\n  m:halfedge(0).twin = nil\n  m:new_edge()\nend)\n"
                  "m:halfedge(1).twin = nil\nreturn #log, log[2].what, log[2].element, log[2].where"),
            (Strings{"2", "new", "e5", "t.lua:3"}));
  ASSERT_EQ(outer.edits().size(), 3u);
  EXPECT_EQ(outer.edits()[1].where, "t.lua:3");
  EXPECT_EQ(outer.edits()[2].where, "t.lua:5");
}

TEST(EditRecorder, CapStopsARunawayLoopBeforeTheWrite) {
  MeshScript s(make_grid(1, 1));
  EditRecorder recorder(s.lua.state(), s.mesh, {.keep_before = true, .max_edits = 10});
  EXPECT_EQ(s.error("local h = m:halfedge(0)\nwhile true do\n  h.next = h\n  m:new_vertex()\nend"),
            "t.lua:3: more than 10 changes recorded; is there a loop that never ends?");
  EXPECT_EQ(recorder.edits().size(), 10u);
  EXPECT_TRUE(replay(*recorder.before(), recorder.edits(), 10).same_as(*s.mesh));
  EXPECT_EQ(s.mesh->vertex_capacity(), 4u + 5u);
  // A Lua error inside mesh:record ends that recording too.
  recorder.stop();
  EXPECT_EQ(s.error("m:record(function() error('boom') end)"), "t.lua:1: boom");
  s.run("m:halfedge(1).next = nil");  // no recorder left: nothing to be full
}

TEST(EditRecorder, OutlivesItsLuaState) {
  auto mesh = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_grid(1, 1)));
  std::unique_ptr<EditRecorder> recorder;
  {
    ScriptRuntime lua;
    push_mesh(lua.state(), mesh);
    lua_setglobal(lua.state(), "m");
    recorder = std::make_unique<EditRecorder>(lua.state(), mesh);
    lua.run_string("m:halfedge(0).twin = nil", "x.lua");
  }
  EXPECT_FALSE(recorder->recording());
  EXPECT_EQ(recorder->edits().size(), 1u);
  recorder->stop();
  recorder.reset();
  lua_State* bare = luaL_newstate();
  EXPECT_THROW(EditRecorder(bare, mesh), ScriptError);
  lua_close(bare);
}

}  // namespace
}  // namespace meshedit
