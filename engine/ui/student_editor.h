// The "Your code" panel: the student file of the active exercise (flip.lua...) in an editor with its line numbers in a
// gutter, the line a load or run error names marked in the error colour with the message under the editor, and Save
// (the button, or Ctrl+S while the editor has the keyboard). The page's student has no other editor; on the desktop
// it sits beside any editor of the student's own.
//
// Invariants:
// - The panel edits StudentEdit's text and reports a save request; it writes nothing itself: the caller saves, which
//   the Exercises tab's StudentFile then loads as it loads any save.
// - The code scrolls both ways in a view of its own: the text box is as wide as the widest line and as tall as the
//   text, so a long line is never cut off, and the view follows the text cursor as it moves. The gutter follows the
//   view's vertical scroll.
// - A new error's line is scrolled into sight once.
// - Per frame it costs one pass over the text (line count and widest line), one over the text before the cursor
//   when it moved, plus the visible lines' numbers.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "document/student_edit.h"

namespace meshedit {

struct StudentEditorState {
  bool open = false;
  std::string scrolled_for;  // the error the view last scrolled to (once per new error, so the student can scroll on)
  int cursor_seen = -1;      // the text cursor and text length the view last followed
  int length_seen = -1;
  float text_width = 0.0f;  // the text box's width in the last frame: the widest line fits in it
  float view_width = 0.0f;  // the width of the view it scrolls in
};

// Draws the panel into the current window or tab. `error` is the last load or run error ("" when none), and
// `error_line` the line of the file it names. Returns true when the student asked to save this frame.
bool draw_student_editor_contents(StudentEdit& edit, StudentEditorState& state, const std::string& error,
                                  std::optional<size_t> error_line);

}  // namespace meshedit
