// ScriptConsole: the Lua console (REPL) of the window, as plain data, and its ImGui panel.
//
// A line is run the way lua.c runs it: first as `return <line>` (so `mesh:num_faces()` prints 6), and if that
// does not compile, as a statement. One LuaRuntime lives as long as the console, so globals persist between
// lines. `print` writes into the console.
//
// Invariants:
// - The global `mesh` is one shared mesh for the console's whole life; before each line it is made equal to
//   the document's mesh (in place, so handles kept in globals stay usable), and if the line changed it, the
//   change reaches the document through apply_operation under the label "console: <line>": undo, the diff
//   highlights and the tables work as for F or S. A line that fails after changing the mesh still hands the
//   change over (a student sees what their code did), labelled "console (error): ...".
// - Time proportional to the edit on a big mesh: a local change reaches the document as the same writes (a patch
//   made again through the setters, so the document keeps a patch too), and the console's mesh catches up with one
//   local change made elsewhere (F, S, undo) by applying the document's `last.patch`. Only other changes copy the
//   mesh: the first line, a whole-mesh change, two changes made elsewhere between lines. Catching up moves the
//   console mesh's version on, so the script's own undo history (mesh:undo()) is dropped, never replayed onto it.
// - `selected` is the handle of the window's selection (nil when nothing is selected), set before each line.
// - Limits are smaller than `meshedit run`'s: the window must stay responsive, so a runaway line stops after
//   ~2e8 instructions or 5 s; the runtime's limits cannot be escaped with pcall (lua_runtime.h).
// - The transcript keeps at most kMaxEntries entries of at most kMaxEntryBytes each (older ones go first), so
//   printing in a loop cannot exhaust memory; history keeps the last kMaxHistory distinct lines.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"

namespace meshedit {

enum class ConsoleEntryKind { Input, Output, Error };

struct ConsoleEntry {
  ConsoleEntryKind kind;
  std::string text;
};

class ScriptConsole {
 public:
  static constexpr size_t kMaxEntries = 2000;
  static constexpr size_t kMaxEntryBytes = 4000;
  static constexpr size_t kMaxHistory = 200;

  ScriptConsole();

  // Runs `code` against the document (see the invariants). Empty or blank code does nothing.
  void submit(MeshDocument& doc, const Selection& selection, const std::string& code);

  // Adds output that comes from elsewhere (a lesson's print) to the transcript, under the same caps.
  void append_output(std::string text) { add(ConsoleEntryKind::Output, std::move(text)); }
  const std::deque<ConsoleEntry>& entries() const { return entries_; }
  void clear() { entries_.clear(); }
  // Walks the history from the newest line (Up) back to the oldest; Down goes forward and ends at "".
  std::string history_up();
  std::string history_down();

 private:
  void add(ConsoleEntryKind kind, std::string text);
  void sync_from(const MeshDocument& doc);
  void bind_selection(const Selection& selection);
  std::vector<std::string> run(const std::string& code);

  ScriptRuntime lua_;
  std::shared_ptr<HalfedgeMesh> mesh_;
  // The document state the console's mesh holds (UINT64_MAX: none), and the console mesh's version then (a Lua
  // change since would show as another version).
  uint64_t synced_generation_ = UINT64_MAX;
  uint64_t synced_version_ = UINT64_MAX;
  uint64_t mesh_version_when_synced_ = UINT64_MAX;
  std::deque<ConsoleEntry> entries_;
  std::vector<std::string> history_;
  size_t history_cursor_ = 0;  // == history_.size() when not browsing
};

// Panel state that is not the console itself: visibility and the input line.
struct ConsolePanelState {
  bool open = false;
  std::array<char, 2048> input{};  // the line being typed (NUL-terminated)
  bool focus_input = false;        // give the input line the keyboard on the next frame
  bool scroll_to_bottom = false;
};

// Draws the console (a transcript and an input line with Up/Down history) into the current window. Running a line
// happens here.
void draw_console_panel_contents(ScriptConsole& console, ConsolePanelState& state, MeshDocument& doc,
                                 const Selection& selection);

}  // namespace meshedit
