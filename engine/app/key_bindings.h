// Every key of the window in one table: the dispatch (EditorApp::apply_key), the keys read each frame, the Keys
// dialog (F1), the menus' shortcut texts and the user docs' key table (tests/app/key_bindings_test.cpp holds the docs
// to this table) all come from kKeyBindings.
//
// Invariants:
// - A key press runs the first row whose key, Ctrl and Shift match exactly and whose view is the one shown (or
//   Everywhere); rows of one view come before the Everywhere row of the same key, so a view's own meaning wins.
// - Each KeyCommand has exactly one row with a `help` text (the Keys dialog's row and the menu's shortcut text); a row
//   with no help text is a second key for the command of the row before it (Ctrl+Shift+Z, the keypad's + - 0).
// - `edits` marks the commands that change the mesh or its history: a running exercise replay is finished first.
#pragma once

#include <cstddef>
#include <span>

namespace meshedit {

enum class KeyCommand {
  ToggleExercises,
  Quit,
  BiggerText,
  SmallerText,
  DefaultText,
  FoldLeft,
  FoldRight,
  Open,
  Help,
  Screenshot,
  ResetView,
  Console,
  Wireframe,
  Shading,
  CurveStep,
  CurveToggle,
  CurveMine,
  PatchMine,
  Undo,
  Redo,
  Inspector,
  ClearSelection,
  FlipOrFace,
  Split,
  Collapse,
  Loop,
  LoopPhase,
  Next,
  Twin,
  Vertex,
  Edge,
  Halfedge,
};

enum class KeyView { Everywhere, Mesh, Curve, Patches };

struct KeyBinding {
  KeyCommand command;
  int key;  // a GLFW key code
  bool ctrl;
  bool shift;
  KeyView view;
  bool edits;
  const char* keys;  // as the Keys dialog, the menus and the docs show it: "Shift+L", "Ctrl+Z"
  const char* help;  // the Keys dialog's text; nullptr on a second key of the same command
};

std::span<const KeyBinding> key_bindings();
// The row a key press runs in `view` (see the invariants), or nullptr.
const KeyBinding* find_key_binding(int key, bool ctrl, bool shift, KeyView view);
// The keys of `command` as shown ("Shift+L"), for a menu item's shortcut.
const char* shortcut_of(KeyCommand command);
// The GLFW keys some row names, each once: what the window reads each frame.
std::span<const int> bound_keys();

}  // namespace meshedit
