// The window's layout as JSON, for tests and bug reports (the `layout-json PATH` action): the display, the text size,
// the view's rectangle, every ImGui window drawn in the last frame with its rectangle, where the lesson's text and
// its Back and Next buttons were drawn, and the labels drawn over the view.
//
// Shape (rectangles are [x, y, width, height] in window coordinates, top-left origin):
//   {"display": [w, h], "font_px": 16, "theme": "dark", "mode": "mesh" | "curve" | "patches",
//    "view": [...],
//    "panels": [{"name": "left column", "rect": [...]}, ...],      windows (the curve canvas is the view itself and
//    "splitters": [{"name": "left splitter", "rect": [...]}, ...],  is not listed; splitters sit inside their panel)
//    "lesson": {"text": [...], "back": [...], "next": [...]},       (only the parts drawn)
//    "labels": {"drawn": [{"text": "h0", "element": "h3", "source": "lesson" | "id", "rect": [...]}, ...],
//               "dropped": 0}}
#pragma once

#include <string>

namespace meshedit {

class EditorApp;

// Needs the ImGui context the app drew its last frame with.
std::string layout_json(const EditorApp& app);

}  // namespace meshedit
