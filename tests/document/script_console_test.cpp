// The Lua console: expressions print, statements run, globals persist, a change to `mesh` reaches the
// document as one undoable operation (pointer for pointer what the core does), errors and runaway lines are
// reported without losing the console, and the transcript and history stay bounded.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/script_console.h"

namespace meshedit {
namespace {

MeshDocument cube_document() { return make_document(build_halfedge_mesh(make_cube())); }

const ConsoleEntry& last_entry(const ScriptConsole& console) { return console.entries().back(); }

TEST(ScriptConsole, ExpressionsPrintAndStatementsRun) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "mesh:num_faces()");
  ASSERT_EQ(console.entries().size(), 2u);
  EXPECT_EQ(console.entries()[0].kind, ConsoleEntryKind::Input);
  EXPECT_EQ(console.entries()[0].text, "mesh:num_faces()");
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Output);
  EXPECT_EQ(last_entry(console).text, std::to_string(doc.mesh.num_faces()));

  console.submit(doc, {}, "x = 20 + 1");
  EXPECT_EQ(last_entry(console).text, "x = 20 + 1");  // a statement prints nothing
  console.submit(doc, {}, "print('x is', x)");
  EXPECT_EQ(last_entry(console).text, "x is\t21");
  console.submit(doc, {}, "x, tostring(mesh:halfedge(3).next)");
  EXPECT_EQ(last_entry(console).text, "21\t" + format_id(doc.mesh.next(HalfedgeId(3))));
  console.submit(doc, {}, "   ");
  EXPECT_EQ(console.entries().size(), 7u);  // blank input is ignored
}

TEST(ScriptConsole, AFlipFromTheConsoleIsAnUndoableDocumentOperation) {
  MeshDocument doc = cube_document();
  const HalfedgeMesh original = doc.mesh;
  HalfedgeMesh expected = doc.mesh;
  ASSERT_TRUE(flip(expected, EdgeId(7)).ok());

  ScriptConsole console;
  console.submit(doc, {}, "tostring(mesh:flip(mesh:edge(7)))");
  EXPECT_EQ(last_entry(console).text, "e7");
  EXPECT_TRUE(doc.mesh.same_as(expected));
  EXPECT_EQ(doc.history.undo_label(), "console: tostring(mesh:flip(mesh:edge(7)))");
  EXPECT_FALSE(doc.last.changes.empty());

  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(original));
  // The console follows the document: after the undo, the script sees the unflipped mesh again.
  console.submit(doc, {}, "tostring(mesh:halfedge(0).next)");
  EXPECT_EQ(last_entry(console).text, format_id(original.next(HalfedgeId(0))));
}

TEST(ScriptConsole, HandlesKeptInGlobalsSeeLaterDocumentChanges) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "h = mesh:edge(7).halfedge");
  const HalfedgeId h = doc.mesh.halfedge(EdgeId(7));
  ASSERT_TRUE(apply_operation(doc, "flip e7", [](HalfedgeMesh& m) { return flip(m, EdgeId(7)); }).ok());
  console.submit(doc, {}, "tostring(h.vertex), tostring(h.next)");
  EXPECT_EQ(last_entry(console).text, format_id(doc.mesh.vertex(h)) + "\t" + format_id(doc.mesh.next(h)));
}

HalfedgeMesh flipped(HalfedgeMesh mesh, std::initializer_list<uint32_t> edges) {
  for (const uint32_t e : edges) EXPECT_TRUE(flip(mesh, EdgeId(e)).ok());
  return mesh;
}

// A local line reaches the document as writes its journal logs: the document keeps a patch (no copy of the mesh,
// the diff and the validation from the patch), and undo and redo step through it.
TEST(ScriptConsole, ALocalLineReachesTheDocumentAsAPatch) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 5)));
  const HalfedgeMesh original = doc.mesh;
  ScriptConsole console;
  console.submit(doc, {}, "mesh:flip(mesh:edge(4))");
  EXPECT_TRUE(doc.mesh.same_as(flipped(original, {4})));
  EXPECT_TRUE(doc.last.patch.has_value());
  console.submit(doc, {}, "mesh:split(mesh:edge(9))");
  HalfedgeMesh expected = flipped(original, {4});
  ASSERT_TRUE(split(expected, EdgeId(9)).ok());
  EXPECT_TRUE(doc.mesh.same_as(expected));
  EXPECT_TRUE(doc.last.patch.has_value());
  ASSERT_TRUE(undo(doc));
  EXPECT_TRUE(doc.mesh.same_as(flipped(original, {4})));
  ASSERT_TRUE(redo(doc));
  EXPECT_TRUE(doc.mesh.same_as(expected));
}

// The console's mesh catches up with changes made elsewhere, one (from the document's patch) or two (copied).
TEST(ScriptConsole, CatchesUpWithChangesMadeElsewhere) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 5)));
  const HalfedgeMesh original = doc.mesh;
  ScriptConsole console;
  console.submit(doc, {}, "mesh:flip(mesh:edge(4))");
  ASSERT_TRUE(apply_operation(doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, EdgeId(9)); }).ok());
  console.submit(doc, {}, "mesh:flip(mesh:edge(11))");
  EXPECT_TRUE(doc.mesh.same_as(flipped(original, {4, 9, 11})));

  ASSERT_TRUE(apply_operation(doc, "flip e14", [](HalfedgeMesh& m) { return flip(m, EdgeId(14)); }).ok());
  ASSERT_TRUE(apply_operation(doc, "flip e20", [](HalfedgeMesh& m) { return flip(m, EdgeId(20)); }).ok());
  console.submit(doc, {}, "mesh:flip(mesh:edge(25))");
  EXPECT_TRUE(doc.mesh.same_as(flipped(original, {4, 9, 11, 14, 20, 25})));
  // The script sees both changes made elsewhere, not only the last.
  console.submit(doc, {}, "tostring(mesh:edge(14).halfedge.next), tostring(mesh:edge(20).halfedge.next)");
  const auto next_on = [&](uint32_t e) { return format_id(doc.mesh.next(doc.mesh.halfedge(EdgeId(e)))); };
  EXPECT_EQ(last_entry(console).text, next_on(14) + "\t" + next_on(20));
}

// mesh:undo() in the console undoes the console's own operations only while nothing else changed the mesh: after a
// change made elsewhere it has nothing to undo, rather than replaying its history over that change.
TEST(ScriptConsole, TheScriptsUndoNeverReplaysOverAChangeMadeElsewhere) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(6, 5)));
  const HalfedgeMesh original = doc.mesh;
  ScriptConsole console;
  console.submit(doc, {}, "mesh:flip(mesh:edge(4))");
  console.submit(doc, {}, "tostring(mesh:undo())");
  EXPECT_EQ(last_entry(console).text, "flip e4");
  EXPECT_TRUE(doc.mesh.same_as(original));

  console.submit(doc, {}, "mesh:flip(mesh:edge(4))");
  ASSERT_TRUE(apply_operation(doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, EdgeId(9)); }).ok());
  console.submit(doc, {}, "tostring(mesh:undo())");
  EXPECT_EQ(last_entry(console).text, "nil");
  EXPECT_TRUE(doc.mesh.same_as(flipped(original, {4, 9})));
}

TEST(ScriptConsole, SelectedIsTheWindowsSelection) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  Selection selection;
  selection.selected = EdgeId(7);
  console.submit(doc, selection, "tostring(selected)");
  EXPECT_EQ(last_entry(console).text, "e7");
  console.submit(doc, {}, "tostring(selected)");
  EXPECT_EQ(last_entry(console).text, "nil");
}

TEST(ScriptConsole, ErrorsAreReportedAndAHalfDoneChangeStillReachesTheDocument) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "nosuch.field = 1");
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Error);
  EXPECT_EQ(last_entry(console).text, "console:1: attempt to index a nil value (global 'nosuch')");
  EXPECT_TRUE(doc.history.undo_label().empty());

  console.submit(doc, {}, "mesh:halfedge(0).next = mesh:halfedge(0) error('stop')");
  EXPECT_EQ(last_entry(console).text, "console:1: stop");
  EXPECT_EQ(doc.mesh.next(HalfedgeId(0)), HalfedgeId(0));
  EXPECT_EQ(doc.history.undo_label(), "console (error): mesh:halfedge(0).next = mesh:halfedge(0) error('stop')");
  EXPECT_FALSE(cached_validation(doc).ok());
}

TEST(ScriptConsole, ARunawayLineStopsAndTheConsoleKeepsWorking) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "while true do pcall(function() while true do end end) end");
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Error);
  EXPECT_NE(last_entry(console).text.find("instruction budget exceeded"), std::string::npos)
      << last_entry(console).text;
  console.submit(doc, {}, "1 + 1");
  EXPECT_EQ(last_entry(console).text, "2");
}

TEST(ScriptConsole, TranscriptAndEntriesAreBounded) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "for i = 1, 3000 do print(i) end");
  EXPECT_EQ(console.entries().size(), ScriptConsole::kMaxEntries);
  EXPECT_EQ(last_entry(console).text, "3000");
  console.submit(doc, {}, "print(string.rep('a', 10000))");
  EXPECT_EQ(last_entry(console).text, std::string(ScriptConsole::kMaxEntryBytes, 'a') + "... (6000 more bytes)");
}

TEST(ScriptConsole, HistoryWalksBackAndForthWithoutDuplicates) {
  MeshDocument doc = cube_document();
  ScriptConsole console;
  console.submit(doc, {}, "1");
  console.submit(doc, {}, "2");
  console.submit(doc, {}, "1");  // moves "1" to the newest place
  EXPECT_EQ(console.history_up(), "1");
  EXPECT_EQ(console.history_up(), "2");
  EXPECT_EQ(console.history_up(), "2");  // stays at the oldest
  EXPECT_EQ(console.history_down(), "1");
  EXPECT_EQ(console.history_down(), "");
}

}  // namespace
}  // namespace meshedit
