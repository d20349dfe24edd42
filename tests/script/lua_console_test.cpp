// LuaConsole, the read-eval-print loop without a window: a line is an expression first and a statement second, its
// results are one tab-joined line, print and errors land in the transcript with their text and line, a runaway line
// is stopped by the console's limits and the console answers the next one, the `meshedit` module and the console's
// globals are there, and the transcript and the history stay bounded.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "script/lua_console.h"

namespace meshedit {
namespace {

const ConsoleEntry& last_entry(const LuaConsole& console) { return console.entries().back(); }

TEST(LuaConsole, AnExpressionPrintsItsValue) {
  LuaConsole console;
  EXPECT_TRUE(console.submit("1 + 2"));
  ASSERT_EQ(console.entries().size(), 2u);
  EXPECT_EQ(console.entries()[0].kind, ConsoleEntryKind::Input);
  EXPECT_EQ(console.entries()[0].text, "1 + 2");
  EXPECT_EQ(console.entries()[1].kind, ConsoleEntryKind::Output);
  EXPECT_EQ(console.entries()[1].text, "3");
  console.submit("nil");
  EXPECT_EQ(last_entry(console).text, "nil");
}

TEST(LuaConsole, AStatementRunsAndPrintsNothingAndItsGlobalsPersist) {
  LuaConsole console;
  EXPECT_TRUE(console.submit("x = 20 + 1"));
  ASSERT_EQ(console.entries().size(), 1u);  // only the line itself
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Input);
  console.submit("x * 2");
  EXPECT_EQ(last_entry(console).text, "42");
  console.submit("local y = x + 1; z = y");
  console.submit("z, y");
  EXPECT_EQ(last_entry(console).text, "22\tnil");  // a local lives only in its line
}

TEST(LuaConsole, MultipleResultsAreOneLineJoinedByTabs) {
  LuaConsole console;
  console.submit("1, 'two', nil, true, 2.5");
  EXPECT_EQ(last_entry(console).text, "1\ttwo\tnil\ttrue\t2.5");
  console.submit("function pair() return 'a', 'b' end");
  console.submit("pair()");  // a call is an expression: its results are printed, as lua.c does
  EXPECT_EQ(last_entry(console).text, "a\tb");
  console.submit("string.rep('ab', 3), #'four'");
  EXPECT_EQ(last_entry(console).text, "ababab\t4");
}

TEST(LuaConsole, PrintWritesIntoTheTranscriptInOrder) {
  LuaConsole console;
  console.submit("print('a', 1, nil) print('b') return 'done'");
  ASSERT_EQ(console.entries().size(), 4u);
  EXPECT_EQ(console.entries()[1].text, "a\t1\tnil");
  EXPECT_EQ(console.entries()[2].text, "b");
  EXPECT_EQ(console.entries()[3].text, "done");
  for (size_t i = 1; i < 4; ++i) EXPECT_EQ(console.entries()[i].kind, ConsoleEntryKind::Output);
  console.submit("print('only')");  // print returns nothing: one line, no empty result line
  EXPECT_EQ(console.entries().size(), 6u);
  EXPECT_EQ(last_entry(console).text, "only");
}

TEST(LuaConsole, ASyntaxErrorIsReportedWithItsLine) {
  LuaConsole console;
  EXPECT_FALSE(console.submit("x = = 1"));
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Error);
  EXPECT_EQ(last_entry(console).text, "console:1: unexpected symbol near '='");
  EXPECT_FALSE(console.submit("local a = 1\nif a then"));
  EXPECT_EQ(last_entry(console).text, "console:2: 'end' expected near <eof>");
}

TEST(LuaConsole, ARuntimeErrorIsReportedWithItsLineAndTheConsoleGoesOn) {
  LuaConsole console;
  EXPECT_FALSE(console.submit("nosuch.field = 1"));
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Error);
  EXPECT_EQ(last_entry(console).text, "console:1: attempt to index a nil value (global 'nosuch')");
  EXPECT_FALSE(console.submit("local a = 1\nerror('stop at ' .. a)"));
  EXPECT_EQ(last_entry(console).text, "console:2: stop at 1");
  EXPECT_FALSE(console.submit("error({})"));
  EXPECT_EQ(last_entry(console).text, "(error object is a table value)");
  EXPECT_TRUE(console.submit("'still here'"));
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Output);
  EXPECT_EQ(last_entry(console).text, "still here");
}

TEST(LuaConsole, ARunawayLineIsStoppedByTheLimitEvenThroughPcall) {
  LuaConsole console;
  EXPECT_EQ(console_limits().instructions, 200'000'000u);
  EXPECT_EQ(console_limits().wall_seconds, 5.0);
  EXPECT_FALSE(console.submit("while true do pcall(function() while true do end end) end"));
  EXPECT_EQ(last_entry(console).kind, ConsoleEntryKind::Error);
  EXPECT_NE(last_entry(console).text.find("instruction budget exceeded (200000000 instructions)"), std::string::npos)
      << last_entry(console).text;
  EXPECT_TRUE(console.submit("1 + 1"));  // a new line has a budget of its own
  EXPECT_EQ(last_entry(console).text, "2");
}

TEST(LuaConsole, TheMeshEditModuleIsThere) {
  LuaConsole console;
  console.submit("meshedit.cube():num_faces()");
  EXPECT_EQ(last_entry(console).text, "12");  // the cube is triangulated
  console.submit("local g = meshedit.grid(2, 3) return g:num_faces(), type(meshedit.load)");
  EXPECT_EQ(last_entry(console).text, "12\tfunction");
  console.submit("io, package, debug");  // the sandbox of every runtime
  EXPECT_EQ(last_entry(console).text, "nil\tnil\tnil");
}

TEST(LuaConsole, TheMeshGlobalSharesTheHostsMesh) {
  LuaConsole console;
  const auto mesh = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube()));
  console.set_mesh(mesh);
  console.submit("mesh:num_vertices(), mesh:num_faces()");
  EXPECT_EQ(last_entry(console).text, "8\t12");
  EXPECT_TRUE(console.submit("mesh:vertex(0).position = {1, 2, 3}"));
  EXPECT_EQ(mesh->position(VertexId(0)), glm::dvec3(1.0, 2.0, 3.0));
}

TEST(LuaConsole, SelectedIsTheHandleOfTheElementGiven) {
  LuaConsole console;
  console.set_mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube())));
  console.set_selected(EdgeId(7));
  console.submit("tostring(selected)");
  EXPECT_EQ(last_entry(console).text, "e7");
  console.set_selected(VertexId(3));
  console.submit("tostring(selected), selected.position == mesh:vertex(3).position");
  EXPECT_EQ(last_entry(console).text, "v3\ttrue");
  console.set_selected({});
  console.submit("tostring(selected)");
  EXPECT_EQ(last_entry(console).text, "nil");
  console.set_selected(EdgeId(100000));  // no such edge: nil rather than an error
  console.submit("tostring(selected)");
  EXPECT_EQ(last_entry(console).text, "nil");
}

TEST(LuaConsole, SelectedIsNilWhenALineReplacedTheMesh) {
  LuaConsole console;
  console.set_mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube())));
  for (const char* replacement : {"mesh = nil", "mesh = 5", "mesh = {edge = function() return 1 end}"}) {
    SCOPED_TRACE(replacement);
    console.submit(replacement);
    console.set_selected(EdgeId(1));
    console.submit("tostring(selected)");
    EXPECT_EQ(last_entry(console).text, "nil");
  }
}

TEST(LuaConsole, BlankLinesAreNeitherRunNorRecorded) {
  LuaConsole console;
  EXPECT_TRUE(console.submit(""));
  EXPECT_TRUE(console.submit(" \t\n "));
  EXPECT_TRUE(console.entries().empty());
  EXPECT_EQ(console.history_up(), "");
  EXPECT_TRUE(is_blank_line("\n\t "));
  EXPECT_FALSE(is_blank_line(" x "));
}

TEST(LuaConsole, HistoryWalksBackAndForthWithoutDuplicates) {
  LuaConsole console;
  console.submit("1");
  console.submit("2");
  console.submit("nosuch()");  // a failed line is history too
  console.submit("1");         // moves "1" to the newest place
  EXPECT_EQ(console.history_up(), "1");
  EXPECT_EQ(console.history_up(), "nosuch()");
  EXPECT_EQ(console.history_up(), "2");
  EXPECT_EQ(console.history_up(), "2");  // stays at the oldest
  EXPECT_EQ(console.history_down(), "nosuch()");
  EXPECT_EQ(console.history_down(), "1");
  EXPECT_EQ(console.history_down(), "");
  EXPECT_EQ(console.history_down(), "");
}

TEST(LuaConsole, HistoryKeepsTheLastLinesOnly) {
  LuaConsole console;
  for (size_t i = 0; i < LuaConsole::kMaxHistory + 5; ++i) console.record("x = " + std::to_string(i));
  std::string oldest;
  for (size_t i = 0; i < LuaConsole::kMaxHistory + 5; ++i) oldest = console.history_up();
  EXPECT_EQ(oldest, "x = 5");
}

TEST(LuaConsole, TheTranscriptAndItsEntriesAreBounded) {
  LuaConsole console;
  console.submit("for i = 1, 3000 do print(i) end");
  EXPECT_EQ(console.entries().size(), LuaConsole::kMaxEntries);
  EXPECT_EQ(console.entries().front().text, "1001");
  EXPECT_EQ(last_entry(console).text, "3000");
  console.submit("string.rep('a', 10000)");
  EXPECT_EQ(last_entry(console).text, std::string(LuaConsole::kMaxEntryBytes, 'a') + "... (6000 more bytes)");
  console.append_output(std::string(LuaConsole::kMaxEntryBytes + 1, 'b'));
  EXPECT_EQ(last_entry(console).text, std::string(LuaConsole::kMaxEntryBytes, 'b') + "... (1 more bytes)");
  console.clear();
  EXPECT_TRUE(console.entries().empty());
}

}  // namespace
}  // namespace meshedit
