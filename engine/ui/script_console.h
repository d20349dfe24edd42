// The Lua console's panel: the transcript of a ScriptConsole (document/script_console.h) and an input line with
// Up/Down history. Running a line is the console's; the panel only draws it and hands it what is typed.
//
// Invariants: the panel's own state (ConsolePanelState) is visibility and the input line, never the console's;
// Enter submits the line, clears it and keeps the keyboard in the console.
#pragma once

#include <array>

#include "document/mesh_document.h"
#include "document/script_console.h"
#include "document/selection.h"

namespace meshedit {

// Panel state that is not the console itself: visibility and the input line.
struct ConsolePanelState {
  bool open = false;
  std::array<char, 2048> input{};  // the line being typed (NUL-terminated)
  bool focus_input = false;        // give the input line the keyboard on the next frame
  bool scroll_to_bottom = false;
};

// Draws the console (a transcript and an input line with Up/Down history) into the current window. A line entered
// is submitted to `console` against `doc` and `selection`.
void draw_console_panel_contents(ScriptConsole& console, ConsolePanelState& state, MeshDocument& doc,
                                 const Selection& selection);

}  // namespace meshedit
