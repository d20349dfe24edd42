// The window's key table (see key_bindings.h).
#include "app/key_bindings.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace meshedit {
namespace {

using C = KeyCommand;
using V = KeyView;

// Grouped as the Keys dialog shows them: the mesh view, the curve and patch views, then every view.
constexpr KeyBinding kKeyBindings[] = {
    // command, key, Ctrl, Shift, view, edits, keys, help
    {C::FlipOrFace, GLFW_KEY_F, false, false, V::Mesh, true, "F",
     "flip the selected edge (on a halfedge: go to its face)"},
    {C::Split, GLFW_KEY_S, false, false, V::Mesh, true, "S", "split the selected edge"},
    {C::Collapse, GLFW_KEY_C, false, false, V::Mesh, true, "C", "collapse the selected edge"},
    {C::Loop, GLFW_KEY_L, false, false, V::Mesh, true, "L", "Loop subdivision"},
    {C::LoopPhase, GLFW_KEY_L, false, true, V::Mesh, true, "Shift+L", "Loop subdivision, one phase per press"},
    {C::Next, GLFW_KEY_N, false, false, V::Mesh, false, "N", "from a halfedge to its next"},
    {C::Twin, GLFW_KEY_T, false, false, V::Mesh, false, "T", "from a halfedge to its twin"},
    {C::Vertex, GLFW_KEY_V, false, false, V::Mesh, false, "V", "from a halfedge to its vertex"},
    {C::Edge, GLFW_KEY_E, false, false, V::Mesh, false, "E", "from a halfedge to its edge"},
    {C::Halfedge, GLFW_KEY_H, false, false, V::Mesh, false, "H", "from anything to its halfedge"},
    {C::Undo, GLFW_KEY_Z, true, false, V::Mesh, true, "Ctrl+Z", "undo (ids come back exactly)"},
    {C::Redo, GLFW_KEY_Y, true, false, V::Mesh, true, "Ctrl+Y", "redo (also Ctrl+Shift+Z)"},
    {C::Redo, GLFW_KEY_Z, true, true, V::Mesh, true, "Ctrl+Shift+Z", nullptr},
    {C::Inspector, GLFW_KEY_I, false, false, V::Mesh, false, "I", "the inspector"},
    {C::ClearSelection, GLFW_KEY_ESCAPE, false, false, V::Mesh, false, "Esc", "clear the selection"},
    {C::CurveStep, GLFW_KEY_E, false, false, V::Curve, false, "E", "curve view: one more de Casteljau level"},
    {C::CurveToggle, GLFW_KEY_C, false, false, V::Curve, false, "C", "curve view: show or hide the curve"},
    {C::CurveMine, GLFW_KEY_M, false, false, V::Curve, false, "M",
     "curve view: the levels from your evaluate_step (scripts/student/curve.lua), checked against the reference"},
    {C::PatchMine, GLFW_KEY_M, false, false, V::Patches, false, "M",
     "patch view: the probe point from your evaluate (scripts/student/patch.lua), checked against the reference"},
    {C::Wireframe, GLFW_KEY_W, false, false, V::Everywhere, false, "W", "wireframe on or off"},
    {C::Shading, GLFW_KEY_Q, false, false, V::Everywhere, false, "Q", "flat or smooth shading"},
    {C::ResetView, GLFW_KEY_SPACE, false, false, V::Everywhere, false, "Space", "reset the view"},
    {C::ToggleExercises, GLFW_KEY_X, false, false, V::Everywhere, false, "X",
     "the exercises: run your flip, split, upsample or normals (scripts/student) or the reference; replay writes"},
    {C::Console, GLFW_KEY_GRAVE_ACCENT, false, false, V::Everywhere, false, "`",
     "the Lua console: `mesh` is the mesh shown, `selected` the selection; Up/Down for history"},
    {C::Screenshot, GLFW_KEY_P, false, false, V::Everywhere, false, "P", "screenshot (a PNG in the current folder)"},
    {C::Open, GLFW_KEY_O, true, false, V::Everywhere, false, "Ctrl+O", "open a file (or drop one on the window)"},
    {C::Quit, GLFW_KEY_Q, true, false, V::Everywhere, false, "Ctrl+Q",
     "quit (the window's size and columns are remembered; unsaved code in Your code is asked about first)"},
    {C::Help, GLFW_KEY_F1, false, false, V::Everywhere, false, "F1", "this list of keys"},
    {C::FoldLeft, GLFW_KEY_LEFT_BRACKET, false, false, V::Everywhere, false, "[",
     "fold or unfold the left column (the lesson)"},
    {C::FoldRight, GLFW_KEY_RIGHT_BRACKET, false, false, V::Everywhere, false, "]",
     "fold or unfold the right column (the tables)"},
    {C::BiggerText, GLFW_KEY_EQUAL, true, false, V::Everywhere, false, "Ctrl+=", "bigger text"},
    {C::BiggerText, GLFW_KEY_KP_ADD, true, false, V::Everywhere, false, "Ctrl+keypad +", nullptr},
    {C::SmallerText, GLFW_KEY_MINUS, true, false, V::Everywhere, false, "Ctrl+-", "smaller text"},
    {C::SmallerText, GLFW_KEY_KP_SUBTRACT, true, false, V::Everywhere, false, "Ctrl+keypad -", nullptr},
    {C::DefaultText, GLFW_KEY_0, true, false, V::Everywhere, false, "Ctrl+0", "the default text size"},
    {C::DefaultText, GLFW_KEY_KP_0, true, false, V::Everywhere, false, "Ctrl+keypad 0", nullptr},
};

}  // namespace

std::span<const KeyBinding> key_bindings() { return kKeyBindings; }

const KeyBinding* find_key_binding(int key, bool ctrl, bool shift, KeyView view) {
  for (const KeyBinding& b : kKeyBindings) {
    if (b.key == key && b.ctrl == ctrl && b.shift == shift && (b.view == view || b.view == KeyView::Everywhere)) {
      return &b;
    }
  }
  return nullptr;
}

const char* shortcut_of(KeyCommand command) {
  for (const KeyBinding& b : kKeyBindings) {
    if (b.command == command && b.help) return b.keys;
  }
  return nullptr;
}

std::span<const int> bound_keys() {
  static const std::vector<int> keys = [] {
    std::vector<int> all;
    for (const KeyBinding& b : kKeyBindings) {
      if (std::find(all.begin(), all.end(), b.key) == all.end()) all.push_back(b.key);
    }
    return all;
  }();
  return keys;
}

}  // namespace meshedit
