// The window's fixed layout (see window_layout.h).
#include "document/window_layout.h"

#include <algorithm>
#include <cmath>

namespace meshedit {
namespace {

float non_negative(float value) { return std::isfinite(value) ? std::max(0.0f, value) : 0.0f; }

}  // namespace

WindowLayout compute_layout(float display_width, float display_height, float menu_height, float status_height,
                            const LayoutPrefs& prefs, float font_px, bool console_open) {
  WindowLayout out;
  const float width = non_negative(display_width), height = non_negative(display_height);
  const float em = std::max(1.0f, non_negative(font_px));
  out.display = {0.0f, 0.0f, width, height};

  const float menu = std::min(std::ceil(non_negative(menu_height)), height);
  const float status = std::min(std::ceil(non_negative(status_height)), height - menu);
  out.menu = {0.0f, 0.0f, width, menu};
  out.status = {0.0f, height - status, width, status};
  const float top = menu, body = height - menu - status;

  // Columns: their preferred widths while the view keeps its share, else both shrink in proportion.
  float left = prefs.left_open ? std::max(WindowLayout::kMinColumnEms, non_negative(prefs.left_ems)) * em : 0.0f;
  float right = prefs.right_open ? std::max(WindowLayout::kMinColumnEms, non_negative(prefs.right_ems)) * em : 0.0f;
  const float room = width * (1.0f - WindowLayout::kMinViewShare);
  if (left + right > room && left + right > 0.0f) {
    const float floor = WindowLayout::kMinColumnEms * em;
    const float shrink = room / (left + right);
    const float least = std::min(floor, width * 0.3f);  // a tiny display keeps the view's share over the floor
    left = left > 0.0f ? std::max(left * shrink, least) : 0.0f;
    right = right > 0.0f ? std::max(right * shrink, least) : 0.0f;
    if (left + right > width) {  // a display narrower than two minimum columns: split what there is
      const float scale = width / (left + right);
      left *= scale;
      right *= scale;
    }
  }
  left = std::floor(left);  // whole pixels: ImGui places windows on whole pixels
  right = std::floor(right);
  out.left = {0.0f, top, left, body};
  out.right = {width - right, top, right, body};

  const float centre_x = left, centre_width = std::max(0.0f, width - left - right);
  float console = 0.0f;
  if (console_open && centre_width > 0.0f) {
    console = std::max(WindowLayout::kMinConsoleEms, non_negative(prefs.console_ems)) * em;
    console = std::floor(std::min(console, body * 0.5f));
  }
  out.console = {centre_x, top + body - console, console > 0.0f ? centre_width : 0.0f, console};
  out.view = {centre_x, top, centre_width, body - console};

  const float s = WindowLayout::kSplitterPixels;
  if (!out.left.empty()) out.left_splitter = {out.left.right() - std::min(s, left), top, std::min(s, left), body};
  if (!out.right.empty()) out.right_splitter = {out.right.x, top, std::min(s, right), body};
  if (!out.console.empty())
    out.console_splitter = {out.console.x, out.console.y, out.console.width, std::min(s, console)};
  return out;
}

float dragged_ems(float shown_px, float delta_px, float font_px, float min_ems) {
  const float em = std::max(1.0f, non_negative(font_px));
  const float ems = (non_negative(shown_px) + (std::isfinite(delta_px) ? delta_px : 0.0f)) / em;
  return std::clamp(ems, min_ems, kMaxPanelEms);
}

}  // namespace meshedit
