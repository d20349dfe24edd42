// The window's settings that last between runs: its size, the columns' widths and whether they are open, the
// console's height, the text size, the theme and whether edits animate. Kept as `key = value` lines in settings.ini
// under $XDG_CONFIG_HOME/meshedit (or ~/.config/meshedit).
//
// Invariants:
// - Reading never fails: a missing file gives the defaults; a line that is not `key = value`, an unknown key or a
//   value out of range keeps that setting's default and is named in the warnings ("settings.ini:3: ...").
// - Every value read is finite and inside its range (the same clamps as the window applies), so a hand-edited file
//   cannot open a window of zero width or text of size 500.
// - Writing goes through a temporary file renamed over the old one: a failed write leaves the old file whole, and
//   returns the reason instead of throwing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/palette.h"  // Theme
#include "document/window_layout.h"

namespace meshedit {

struct Settings {
  static constexpr int kDefaultWindowWidth = 1280, kDefaultWindowHeight = 800;
  static constexpr int kMinWindowWidth = 480, kMinWindowHeight = 320, kMaxWindowSide = 16384;
  static constexpr float kDefaultFontPx = 16.0f;  // at content scale 1
  static constexpr float kMinFontPx = 11.0f, kMaxFontPx = 32.0f;

  int window_width = kDefaultWindowWidth;
  int window_height = kDefaultWindowHeight;
  float font_px = kDefaultFontPx;
  Theme theme = Theme::Dark;
  bool animate_edits = true;  // View > Animate edits: flip, split and collapse play for a quarter second
  LayoutPrefs layout;
};

// Where settings.ini lives; empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path settings_path();

// Parses the text of a settings file named `name` (for the warnings).
Settings parse_settings(const std::string& text, const std::string& name, std::vector<std::string>& warnings);
Settings read_settings(const std::filesystem::path& path, std::vector<std::string>& warnings);
std::string format_settings(const Settings& settings);
// Writes the settings, making the folder when needed. Returns "" on success, else why not.
std::string write_settings(const std::filesystem::path& path, const Settings& settings);

// The text size after Ctrl+= (steps > 0), Ctrl+- (steps < 0), clamped to the range.
float stepped_font_px(float font_px, int steps);

}  // namespace meshedit
