// LuaConsole: a Lua read-eval-print loop with no window: it takes a line, runs it, and keeps the transcript and the
// history a console shows. The window's console (document/script_console.h) binds it to the document.
//
// A line is run the way lua.c runs it: first as `return <line>` (so `mesh:num_faces()` prints the count), and if that
// does not compile, as a statement. One ScriptRuntime (the `meshedit` module opened) lives as long as the console,
// so globals persist between lines. `print` writes into the transcript; a line's results are one Output entry
// (joined by tabs), its error one Error entry ("console:1: ...").
//
// Invariants:
// - Limits are smaller than `meshedit run`'s (console_limits()): a window must stay responsive, so a runaway line
//   stops after ~2e8 instructions or 5 s; the runtime's limits cannot be escaped with pcall (lua_runtime.h).
// - The transcript keeps at most kMaxEntries entries of at most kMaxEntryBytes each (older ones go first), so
//   printing in a loop cannot exhaust memory; history keeps the last kMaxHistory distinct lines.
// - Blank lines (spaces, tabs, newlines only) are neither run nor recorded.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"
#include "core/ids.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"

namespace meshedit {

enum class ConsoleEntryKind { Input, Output, Error };

struct ConsoleEntry {
  ConsoleEntryKind kind;
  std::string text;
};

// What a console line runs under: ~2e8 instructions, 256 MB of Lua memory, 5 s.
LuaLimits console_limits();
// Whether `line` has nothing to run (only spaces, tabs and newlines).
bool is_blank_line(const std::string& line);

class LuaConsole {
 public:
  static constexpr size_t kMaxEntries = 2000;
  static constexpr size_t kMaxEntryBytes = 4000;
  static constexpr size_t kMaxHistory = 200;

  // Throws std::bad_alloc when the runtime cannot be made.
  LuaConsole();

  // record(line), then evaluate(line). Returns false when the line failed (a blank line does not fail).
  bool submit(const std::string& line);
  // Puts a non-blank line into the transcript (as Input) and the history; false for a blank line.
  bool record(const std::string& line);
  // Runs the line (expression first, then statement) and writes its results or its error into the transcript.
  // Returns false when it raised an error or hit a limit.
  bool evaluate(const std::string& line);

  // The global `mesh`: a mesh userdata sharing `mesh` (handles made from it keep pointing at it).
  void set_mesh(std::shared_ptr<HalfedgeMesh> mesh);
  // The global `selected`: the handle of `element` on the global `mesh` (mesh:edge(i) and so on), nil when `element`
  // is not valid or the mesh has no such element.
  void set_selected(ElementRef element);

  // Adds output that comes from elsewhere (a lesson's print) to the transcript, under the same caps.
  void append_output(std::string text) { add(ConsoleEntryKind::Output, std::move(text)); }
  const std::deque<ConsoleEntry>& entries() const { return entries_; }
  void clear() { entries_.clear(); }
  // Walks the history from the newest line (Up) back to the oldest; Down goes forward and ends at "".
  std::string history_up();
  std::string history_down();

 private:
  void add(ConsoleEntryKind kind, std::string text);
  std::vector<std::string> run(const std::string& line);

  ScriptRuntime lua_;
  std::deque<ConsoleEntry> entries_;
  std::vector<std::string> history_;
  size_t history_cursor_ = 0;  // == history_.size() when not browsing
};

}  // namespace meshedit
