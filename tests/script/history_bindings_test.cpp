// Snapshots, restore, diff, and undo/redo of whole operations from Lua, and the EditJournal behind undo.
#include <gtest/gtest.h>

#include <string>

#include "core/history.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "mesh_script_fixture.h"
#include "script/internal/edit_journal.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

constexpr const char* kDiffText =
    "local function text(d) local s = '' for _, c in ipairs(d) do "
    "s = s .. c.element .. '.' .. c.field .. ':' .. c.before .. '->' .. c.after .. ' ' end return s end\n";

std::string core_text(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::string s;
  for (const FieldChange& c : diff(before, after)) {
    s += format_id(c.element) + "." + c.field + ":" + c.before + "->" + c.after + " ";
  }
  return s;
}

EdgeId interior_edge(const HalfedgeMesh& m) {
  for (EdgeId e : m.edges()) {
    if (!m.is_boundary(e)) return e;
  }
  return EdgeId();
}

TEST(HistoryBindings, DiffMatchesTheCoreDiff) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh start = *s.mesh;
  s.run("snap = m:snapshot()");
  EXPECT_EQ(s.run(std::string(kDiffText) + "return text(m:diff(snap))"), Strings{""});
  const EdgeId e = interior_edge(start);
  s.run("m:flip(m:edge(" + std::to_string(e.index) + "))");
  EXPECT_EQ(s.run(std::string(kDiffText) + "return text(m:diff(snap))"), Strings{core_text(start, *s.mesh)});
  s.run(
      "m:split(m:edge(0))\nlocal h = m:halfedge(1)\nh.next = h\nm:delete(m:vertex(3))\n"
      "m:vertex(0).position = {0.1, -0.0, 1e100}");
  const std::string expected = core_text(start, *s.mesh);
  EXPECT_NE(expected.find("v4.alive:-->alive"), std::string::npos) << expected;
  EXPECT_NE(expected.find("h1.next:"), std::string::npos) << expected;
  EXPECT_EQ(s.run(std::string(kDiffText) + "return text(m:diff(snap))"), Strings{expected});
  // Against another mesh (the argument is before) and the other way round: slots only on one side show "-".
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  EXPECT_EQ(s.run(std::string(kDiffText) + "cube = meshedit.cube() return text(m:diff(cube))"),
            Strings{core_text(cube, *s.mesh)});
  EXPECT_EQ(s.run(std::string(kDiffText) + "return text(cube:diff(m))"), Strings{core_text(*s.mesh, cube)});
  EXPECT_EQ(s.run("local d = m:diff(snap) return #d, d[1].element, d[1].field"),
            (Strings{std::to_string(diff(start, *s.mesh).size()), format_id(diff(start, *s.mesh)[0].element),
                     diff(start, *s.mesh)[0].field}));
  EXPECT_EQ(s.error("m:diff(5)"), "t.lua:1: bad argument #1 to 'diff' (snapshot or mesh expected, got number)");
}

TEST(HistoryBindings, RestoreBringsBackEveryIdAndHandlesFollow) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh start = *s.mesh;
  const uint64_t version = s.mesh->version();
  EXPECT_EQ(s.run("snap = m:snapshot()\nlocal v = m:split(m:edge(0))\nlocal h = m:halfedge(0)\nh.twin = nil\n"
                  "m:restore(snap)\n"
                  "return tostring(snap), m:alive(v), tostring(h.twin), m:num_vertices(), pcall(function() return "
                  "v.halfedge end)"),
            (Strings{"snapshot (4 vertices, 5 edges, 2 faces)", "false", format_id(start.twin(HalfedgeId(0))), "4",
                     "false", "t.lua:6: attempt to use dead vertex v4"}));
  EXPECT_TRUE(s.mesh->same_as(start));
  EXPECT_GT(s.mesh->version(), version);
  EXPECT_EQ(s.error("local other = meshedit.grid(1, 1)\nm:restore(other:snapshot())"),
            "t.lua:2: this snapshot was taken of another mesh");
  EXPECT_EQ(s.error("m:restore(m)"), "t.lua:1: bad argument #1 to 'restore' (snapshot expected, got mesh)");
  // A snapshot of a mesh that is gone cannot be restored into a new one at the same address.
  EXPECT_EQ(s.error("local g = meshedit.grid(1, 1) local old = g:snapshot() g = nil collectgarbage()\n"
                    "m:restore(old)"),
            "t.lua:2: this snapshot was taken of another mesh");
}

TEST(HistoryBindings, UndoAndRedoWholeOperations) {
  MeshScript s(make_grid(2, 2));
  const HalfedgeMesh start = *s.mesh;
  const EdgeId e = interior_edge(start);
  HalfedgeMesh flipped = start;
  ASSERT_TRUE(flip(flipped, e).ok());
  HalfedgeMesh written = flipped;
  written.set_position(VertexId(0), glm::dvec3(5, 5, 5));
  HalfedgeMesh split_too = written;
  const VertexId made = split(split_too, EdgeId(0)).value;
  const std::string es = std::to_string(e.index);

  EXPECT_EQ(s.run("return m:undo(), m:redo()"), (Strings{"nil", "nil"}));
  s.run("m:flip(m:edge(" + es + "))\nm:vertex(0).position = {5, 5, 5}\nm:split(m:edge(0))");
  EXPECT_TRUE(s.mesh->same_as(split_too));
  EXPECT_EQ(s.run("return m:undo()"), Strings{"split e0 -> " + format_id(made)});
  EXPECT_TRUE(s.mesh->same_as(written));  // the write after the flip stays: it is not an operation
  EXPECT_EQ(s.run("return m:undo()"), Strings{"flip e" + es});
  EXPECT_TRUE(s.mesh->same_as(start));
  EXPECT_EQ(s.run("return m:undo()"), Strings{"nil"});
  EXPECT_EQ(s.run("return m:redo()"), Strings{"flip e" + es});
  EXPECT_TRUE(s.mesh->same_as(written));  // redo returns to the state the undo left, write included
  EXPECT_EQ(s.run("return m:redo()"), Strings{"split e0 -> " + format_id(made)});
  EXPECT_TRUE(s.mesh->same_as(split_too));
  EXPECT_EQ(s.run("return m:redo()"), Strings{"nil"});
  // A change after an undo drops the redo.
  EXPECT_EQ(s.run("m:undo()\nm:halfedge(0).twin = nil\nreturn m:redo()"), Strings{"nil"});
  EXPECT_EQ(s.run("return m:undo()"), Strings{"flip e" + es});
  EXPECT_TRUE(s.mesh->same_as(start));
}

TEST(HistoryBindings, RestoreAndLoopSubdivideAreUndoable) {
  MeshScript s(make_grid(1, 1));
  const HalfedgeMesh start = *s.mesh;
  EXPECT_EQ(s.run("snap = m:snapshot()\nm:loop_subdivide()\nlocal n = m:num_faces()\nm:restore(snap)\n"
                  "return n, m:num_faces(), m:undo(), m:num_faces(), m:undo(), m:num_faces()"),
            (Strings{"8", "2", "restore", "8", "loop_subdivide", "2"}));
  EXPECT_TRUE(s.mesh->same_as(start));
}

TEST(HistoryBindings, HostChangesDropTheUndoHistory) {
  MeshScript s(make_grid(2, 2));
  const EdgeId e = interior_edge(*s.mesh);
  s.run("m:flip(m:edge(" + std::to_string(e.index) + "))");
  s.mesh->set_position(VertexId(0), glm::dvec3(7, 7, 7));  // the host edits the mesh between two calls
  const HalfedgeMesh now = *s.mesh;
  EXPECT_EQ(s.run("return m:undo()"), Strings{"nil"});
  EXPECT_TRUE(s.mesh->same_as(now));
  // A fresh history starts at the next operation.
  s.run("m:flip(m:edge(" + std::to_string(e.index) + "))");
  EXPECT_EQ(s.run("return m:undo()"), Strings{"flip e" + std::to_string(e.index)});
  EXPECT_TRUE(s.mesh->same_as(now));
}

TEST(EditJournal, StartsAtTheFirstOperationAndDropsPastItsCap) {
  HalfedgeMesh m = build_halfedge_mesh(make_grid(2, 2));
  const HalfedgeMesh start = m;
  EditJournal journal(3);
  RecordedEdit write;
  write.element = VertexId(0);
  write.field = "position";
  write.value.position = glm::dvec3(1, 2, 3);
  journal.before_change(m, false);
  apply_edit(m, write);
  journal.after_change(m, write);
  EXPECT_FALSE(journal.active());  // plain writes before any operation cost nothing
  EXPECT_FALSE(journal.undo(m));

  const EdgeId e = interior_edge(start);
  RecordedEdit op;
  op.what = EditKind::Operation;
  op.element = e;
  op.field = "flip";
  const HalfedgeMesh before_flip = m;
  journal.before_change(m, true);
  ASSERT_TRUE(flip(m, e).ok());
  journal.after_change(m, op);
  EXPECT_TRUE(journal.active());
  EXPECT_EQ(journal.size(), 1u);
  EXPECT_EQ(journal.base_bytes(), before_flip.memory_bytes());
  for (int i = 0; i < 2; ++i) {
    journal.before_change(m, false);
    apply_edit(m, write);
    journal.after_change(m, write);
  }
  EXPECT_EQ(journal.size(), 3u);
  journal.before_change(m, false);
  apply_edit(m, write);
  journal.after_change(m, write);  // the fourth edit passes the cap of 3
  EXPECT_FALSE(journal.active());
  EXPECT_FALSE(journal.undo(m));
}

}  // namespace
}  // namespace meshedit
