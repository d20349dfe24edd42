// StudentEdit: the text of one student file (scripts/student/flip.lua...) as the window's editor shows and changes it,
// without ImGui. The Exercises tab reads the file through StudentFile (student_file.h), which loads it again when its
// stamp changes: save() writes the file, and the next run loads the new code by that same path.
//
// Invariants:
// - text() is the file as last read, plus the student's unsaved changes (dirty()). follow() reads the file again when
//   the path or the file on disk changed and nothing is unsaved, so an edit made in another editor shows here; unsaved
//   text is never replaced behind the student's back.
// - A file that cannot be read shows empty with read_error() set; save() writes whole or not at all (a temporary file
//   renamed over the old one) and says why not. Nothing here throws but std::bad_alloc.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/check.h"
#include "script/file_stamp.h"

namespace meshedit {

class StudentEdit {
 public:
  // Shows `path`'s file: reads it when the path differs, or when the file changed on disk and nothing is unsaved.
  void follow(const std::filesystem::path& path);
  // Reads the file again, unsaved changes dropped (the file was replaced on purpose: an upload).
  void reread() {
    dirty_ = false;
    read();
  }
  const std::filesystem::path& path() const { return path_; }
  const std::string& text() const { return text_; }
  std::string& text_for_editing() { return text_; }  // the editor's buffer; call mark_edited() after a change
  void mark_edited() {
    dirty_ = true;
    changes_ += 1;
  }
  // How many times text() changed (an edit, a read, a draft taken): a keeper of copies compares it with the last it
  // saw.
  uint64_t changes() const { return changes_; }
  // Takes `draft`, the student's unsaved text of this file from before (a page reloaded), as unsaved changes; false,
  // and nothing changes, when it is the text already shown.
  bool take_draft(std::string draft);
  bool dirty() const { return dirty_; }
  const std::string& read_error() const { return read_error_; }
  // Line `line` of text() (1 the first), without its newline; nullopt when there is no such line.
  std::optional<std::string_view> line(size_t line) const;
  // Replaces line `line` (1 the first; one past the last appends a line) with `text`; false when there is no such line.
  bool set_line(size_t line, std::string_view text);
  // Writes text() to path(); on success the text is clean and its stamp is the file's.
  Check save();

 private:
  void read();
  // Where line `line` (1 the first) starts in text_; nullopt when there is no such line. A text ending in a newline
  // has an empty last line, as the editor shows it.
  std::optional<size_t> line_start(size_t line) const;
  std::filesystem::path path_;
  std::string text_;
  std::string read_error_;
  FileStamp stamp_;  // the file's stamp when last read or written
  bool dirty_ = false;
  uint64_t changes_ = 0;
};

// The line a Lua error names in `file_name` ("flip.lua:3: unexpected symbol" -> 3, also "[string \"flip.lua\"]:3:"
// and a path ending in the name); nullopt when the message names no line of that file.
// Lua gives an error's place only in its text (the parser's syntax errors, and luaL_where's "file:line:" before a run
// error), so the line is read from there; what kind of failure it was is ScriptError's typed fields' business.
std::optional<size_t> error_line_in(std::string_view error, std::string_view file_name);

}  // namespace meshedit
