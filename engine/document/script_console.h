// ScriptConsole: the window's Lua console bound to the document: a LuaConsole (script/lua_console.h: the
// read-eval-print loop, its transcript and history) whose global `mesh` follows the document, and whose changes to
// that mesh reach the document as operations. ui/script_console.h draws it.
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
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

#include "core/halfedge_mesh.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "script/lua_console.h"

namespace meshedit {

class ScriptConsole {
 public:
  static constexpr size_t kMaxEntries = LuaConsole::kMaxEntries;
  static constexpr size_t kMaxEntryBytes = LuaConsole::kMaxEntryBytes;
  static constexpr size_t kMaxHistory = LuaConsole::kMaxHistory;

  ScriptConsole();

  // Runs `code` against the document (see the invariants). Empty or blank code does nothing.
  void submit(MeshDocument& doc, const Selection& selection, const std::string& code);

  // Adds output that comes from elsewhere (a lesson's print) to the transcript, under the same caps.
  void append_output(std::string text) { repl_.append_output(std::move(text)); }
  const std::deque<ConsoleEntry>& entries() const { return repl_.entries(); }
  void clear() { repl_.clear(); }
  // Walks the history from the newest line (Up) back to the oldest; Down goes forward and ends at "".
  std::string history_up() { return repl_.history_up(); }
  std::string history_down() { return repl_.history_down(); }

 private:
  void sync_from(const MeshDocument& doc);

  LuaConsole repl_;
  std::shared_ptr<HalfedgeMesh> mesh_;
  // The document state the console's mesh holds (UINT64_MAX: none), and the console mesh's version then (a Lua
  // change since would show as another version).
  uint64_t synced_generation_ = UINT64_MAX;
  uint64_t synced_version_ = UINT64_MAX;
  uint64_t mesh_version_when_synced_ = UINT64_MAX;
};

}  // namespace meshedit
