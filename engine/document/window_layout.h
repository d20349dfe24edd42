// The window's fixed layout: a menu bar on top, a status bar at the bottom, a left column (the lesson, or the
// inspector when no lesson runs), a right column (pointer tables, inspector, exercises, or the curve and patch
// controls) and the view in the free centre, with the Lua console as a strip along the bottom of the centre when it
// is open. Pure arithmetic on rectangles, no ImGui: the app draws its panels into what compute_layout returns.
//
// Invariants of compute_layout, for any display size (zero while the window is minimised included):
// - every rectangle lies inside the display, and no two of menu, status, left, right, console and view overlap;
// - edges between parts fall on whole pixels (as ImGui places its windows) for a display of whole pixels;
// - the columns keep their preferred widths (LayoutPrefs, in font-size units so they grow with the text) while the
//   view keeps at least kMinViewShare of the width; past that both columns shrink in proportion, never below
//   kMinColumnEms unless that would take more than 30% of the display each;
// - a collapsed column has zero width and gives its room to the view; the console takes at most half the centre's
//   height;
// - each open column has a splitter strip along its inner edge, inside the column (dragging it changes the
//   preference); the console has one along its top edge, inside the console.
#pragma once

namespace meshedit {

// A rectangle in ImGui window coordinates (top-left origin, y down).
struct ScreenRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;

  float right() const { return x + width; }
  float bottom() const { return y + height; }
  bool empty() const { return width <= 0.0f || height <= 0.0f; }
  bool contains(float px, float py) const { return px >= x && px < right() && py >= y && py < bottom(); }
  bool contains(const ScreenRect& r) const {
    return r.x >= x && r.y >= y && r.right() <= right() && r.bottom() <= bottom();
  }
  // Overlap of positive area (touching edges do not overlap).
  bool overlaps(const ScreenRect& r) const {
    return !empty() && !r.empty() && x < r.right() && r.x < right() && y < r.bottom() && r.y < bottom();
  }
};

// What the user chose, remembered between runs (document/settings.h). Widths and heights are in font-size units.
struct LayoutPrefs {
  static constexpr float kDefaultLeftEms = 22.0f;
  static constexpr float kDefaultRightEms = 25.0f;
  static constexpr float kDefaultConsoleEms = 13.0f;
  float left_ems = kDefaultLeftEms;
  float right_ems = kDefaultRightEms;
  float console_ems = kDefaultConsoleEms;
  bool left_open = true;
  bool right_open = true;
};

struct WindowLayout {
  static constexpr float kMinViewShare = 0.4f;  // of the display's width, kept for the view
  static constexpr float kMinColumnEms = 12.0f;
  static constexpr float kMinConsoleEms = 5.0f;
  static constexpr float kSplitterPixels = 6.0f;

  ScreenRect display, menu, status, left, right, view, console;
  ScreenRect left_splitter, right_splitter, console_splitter;  // empty when their panel is closed
};

// `menu_height` and `status_height` are what the bars take (0 for none); `font_px` converts the preferences'
// font-size units to pixels; `console_open` gives the console its strip.
WindowLayout compute_layout(float display_width, float display_height, float menu_height, float status_height,
                            const LayoutPrefs& prefs, float font_px, bool console_open);

// The preference a splitter drag leaves: the panel's size as shown (`shown_px`, what compute_layout gave) grown by
// `delta_px`, in font-size units, clamped to [min_ems, kMaxPanelEms]. Starting from the size shown, not from the
// preference, makes the panel follow the mouse even where compute_layout had to shrink it.
constexpr float kMaxPanelEms = 60.0f;
float dragged_ems(float shown_px, float delta_px, float font_px, float min_ems);

}  // namespace meshedit
