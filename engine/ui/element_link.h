// The clickable element id every panel uses (`h12`, `v5`, `b0`), the panels' shared colours, and UiProbe, the
// record of where clickable things were drawn (so headless tests can click them by name).
//
// Invariants:
// - A link is followed only when its element is alive: a dead, missing or null reference is drawn in the error colour,
//   says why in a tooltip, and never changes the selection.
// - Hovering a live link sets selection.hovered, so the mesh view can light the element up.
// - Must be called between ImGui::NewFrame() and ImGui::Render(), inside a window.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "core/halfedge_mesh.h"
#include "document/selection.h"
#include "ui/theme.h"

namespace meshedit {

// Colours shared by the panels, from the palette of the current theme (ui/theme.h).
namespace ui_colors {
inline ImVec4 link() { return im_colour(ui_palette().link); }
inline ImVec4 broken() { return im_colour(ui_palette().error); }  // dead / missing / null references, errors
inline ImVec4 dead() { return im_colour(ui_palette().dead); }     // dead rows
inline ImVec4 valid() { return im_colour(ui_palette().ok); }
inline ImVec4 warning() { return im_colour(ui_palette().warning); }
inline ImVec4 changed_cell() { return im_colour(ui_palette().changed_cell); }  // a cell the last operation changed
}  // namespace ui_colors

// Where clickable items were drawn during a frame. Panels append to it when their state holds one; tests
// clear it before a frame and click the recorded rectangles in the next one.
struct UiProbe {
  struct Item {
    std::string name;    // what kind of item: "next", "row", "cell:twin", "select-culprit", ...
    ElementRef element;  // the element it selects (invalid for buttons without one)
    ImVec2 min, max;     // screen rectangle
    ImVec2 center() const { return ImVec2((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f); }
  };
  std::vector<Item> items;

  void clear() { items.clear(); }
  // The first item with this name (and element, when given); nullptr if none was drawn.
  const Item* find(std::string_view name, ElementRef element = {}) const;
  // Records the last ImGui item under `name`.
  void record_last_item(std::string name, ElementRef element = {});
};

// Gives the next window this size the first time it appears, unless the caller already chose one with
// ImGui::SetNextWindowSize (the app's layout wins over the panels' defaults).
void default_window_size(ImVec2 size);

// Draws `ref` as a link named `name` (the ImGui id and the probe name; unique within the current id scope).
// Returns true when it was clicked; then selection.selected == ref. Broken references are recorded in the probe
// too (as plain text that ignores clicks).
bool element_link(const HalfedgeMesh& mesh, ElementRef ref, Selection& selection, const char* name,
                  UiProbe* probe = nullptr);

}  // namespace meshedit
