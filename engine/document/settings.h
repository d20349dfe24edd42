// The window's settings that last between runs: its size, the columns' widths and whether they are open, the
// console's height, the text size, the theme, whether edits animate and how long the student's code may run. Kept as
// `key = value` lines in settings.ini under $XDG_CONFIG_HOME/meshedit (or ~/.config/meshedit).
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
#include "script/lua_runtime.h"  // LuaLimits

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
  // View > Language: "en", "zh" (core/translation.h); "" until chosen, when the window follows the system's locale.
  std::string language;
  bool animate_edits = true;  // View > Animate edits: flip, split and collapse play for a quarter second
  // How long the student's code may run in the window (Run mine, a lesson's your_turn) before it is stopped at its
  // line: the window's interactive deadline (window_student_limits), not the grader's budget.
  static constexpr double kDefaultStudentCodeSeconds = 5.0;
  static constexpr double kMinStudentCodeSeconds = 0.5, kMaxStudentCodeSeconds = 600.0;
  double student_code_seconds = kDefaultStudentCodeSeconds;
  LayoutPrefs layout;
};

// The limits the window runs the student's code under: the wall-clock deadline of `seconds` (the setting
// student_code_seconds) and no instruction budget, so a runaway is always stopped by the deadline, with the same words
// on every machine ("flip.lua:4: time limit exceeded (5 s)"); the memory cap is LuaLimits'.
LuaLimits window_student_limits(double seconds);

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
