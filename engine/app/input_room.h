// InputRoom: the mouse and the keys, read from ImGui's io each frame. The camera follows drags (orbit; middle or
// Shift+drag pans) and the wheel over the view; the hover follows the mouse over the mesh view; a left click that did
// not drag, and each key pressed that a command has, are handed to the window (EditorApp::click, handle_key), which
// runs them as scripted actions are run, so GUI tests exercise what users do.
//
// Invariants:
// - While a panel has the mouse or the keyboard (ImGui's WantCapture*), the view takes neither; over the curve view,
//   its canvas has the mouse. A drag that started in the view goes on over the columns; a click, a hover or the
//   wheel count only in the view.
// - No pick while the camera moves (it would redraw the whole id buffer every frame); when the id buffer is stale and
//   slow to redraw, the hover waits until the mouse rests (kHoverRestSeconds), and hover_pending() says so.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "app/commands.h"

namespace meshedit {

class DocumentRoom;
class ViewRoom;

class InputRoom {
 public:
  InputRoom(DocumentRoom& document, ViewRoom& view) : document_(document), view_(view) {}

  // The keys pressed this frame that a command has, with their modifiers.
  static std::vector<std::pair<int, KeyMods>> keys_pressed();
  // The mouse this frame: the camera and the hover follow it; returns the view pixel of a left click.
  std::optional<glm::ivec2> read_mouse();
  // What is under pixel (x, y) of the mesh view becomes the hovered element.
  void hover(int x, int y);
  bool hover_pending() const { return hover_pending_; }  // a hover waits for the mouse to rest

 private:
  static constexpr double kHoverRestSeconds = 0.15;
  DocumentRoom& document_;
  ViewRoom& view_;
  bool dragging_ = false;
  bool hover_pending_ = false;
  double mouse_moved_at_ = 0.0;
};

}  // namespace meshedit
