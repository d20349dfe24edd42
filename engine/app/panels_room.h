// PanelsRoom: the columns around the view and the window's look. Owns the settings that last between runs (the text
// size, the theme, the columns' widths and folds: document/settings.h), the layout made from them each frame
// (document/window_layout.h), the panels' own state (the inspector, the pointer tables, the Lua console and its strip),
// which tab of the right column comes to the front, and the probe where tests find what was drawn.
//
// Invariants:
// - The layout is fixed: menu bar, status bar, the left and right columns, the console strip, and the view in the free
//   centre. The columns are borderless ImGui windows that cannot move, resize or collapse by themselves: their
//   rectangles come from compute_layout every frame, so no panel covers the lesson or the view (only the modal dialogs
//   and menus are drawn over them). The splitters between them change the settings' widths.
// - What each column holds (panels_room.cpp):
//     left   the lesson while one runs; else the inspector over the list of lessons (the list alone outside the mesh
//            view);
//     right  mesh view: tabs Pointers, Inspector (while a lesson has the left column), Exercises, Your code, Repairs,
//            Check; curve view: the curve's controls and its levels; patch view: the patch controls and the evaluation
//            table (each beside a Check tab once Check my work opened it).
// - A change of the text size or the theme is taken once by the window (take_look_change), which applies it before
//   its next frame; the view's colours change at once.
#pragma once

#include <utility>

#include "core/translation.h"
#include "document/script_console.h"
#include "document/settings.h"
#include "document/window_layout.h"
#include "ui/element_link.h"
#include "ui/fonts.h"
#include "ui/inspector.h"
#include "ui/pointer_tables.h"
#include "ui/script_console.h"

namespace meshedit {

class CheckRoom;
class DocumentRoom;
class ExerciseRoom;
class LessonRoom;
class ViewRoom;

enum class RightTab { None, Tables, Inspector, Exercises, Code, Repairs, Check };

class PanelsRoom {
 public:
  PanelsRoom(DocumentRoom& document, ViewRoom& view, ExerciseRoom& exercises, CheckRoom& check, LessonRoom& lessons)
      : document_(document), view_(view), exercises_(exercises), check_(check), lessons_(lessons) {}

  const Settings& settings() const { return settings_; }
  Settings& settings() { return settings_; }
  void apply_settings(const Settings& settings);  // at start: the theme at once, the rest with the look
  void set_theme(Theme theme);
  // View > Language: the window's texts, the lesson's and the fonts' glyphs switch at the next frame; remembered.
  void set_language(Language language);
  void change_font_size(int steps);  // 0: back to the default
  // True once after the text size or the theme changed: the window applies the look before its next frame.
  bool take_look_change() { return std::exchange(look_changed_, false); }
  // What the window's apply_look made of the fonts: a missing font is a warning in the status line.
  void fonts_applied(const FontsLoaded& fonts);

  // The layout for this frame, under a menu bar and above a status bar of the given heights.
  void lay_out(float menu_height, float status_height);
  const WindowLayout& layout() const { return layout_; }
  float font_pixels() const { return font_pixels_; }
  // Where the lesson's text, the buttons, the menus and the tabs were drawn last frame (tests find them there).
  UiProbe& probe() { return probe_; }
  const UiProbe& probe() const { return probe_; }

  // Brings `tab` to the front of the right column next frame, unfolding the column.
  void bring_forward(RightTab tab);
  InspectorState& inspector() { return inspector_; }
  TablesState& tables() { return tables_; }
  ScriptConsole& console() { return console_; }
  const ScriptConsole& console() const { return console_; }
  ConsolePanelState& console_panel() { return console_panel_; }

  // The left and right columns, the console strip and the splitters, as the layout places them.
  void draw_columns();

 private:
  void draw_left_column();
  void draw_right_column();
  void draw_right_tabs();
  void draw_bezier_panel();  // the curve or the patch view's controls
  bool check_tab();          // the Check tab, when it is open; returns whether it was drawn
  void draw_console_strip();
  void draw_splitters();

  DocumentRoom& document_;
  ViewRoom& view_;
  ExerciseRoom& exercises_;
  CheckRoom& check_;
  LessonRoom& lessons_;
  Settings settings_;
  bool look_changed_ = true;   // the window applies the look before the first frame
  size_t glyphs_checked_ = 0;  // how many of the lesson's translations the fonts were checked against
  float font_pixels_ = Settings::kDefaultFontPx;
  WindowLayout layout_;
  UiProbe probe_;
  RightTab select_tab_ = RightTab::None;  // a tab to bring to the front at the next frame
  InspectorState inspector_;
  TablesState tables_;
  ScriptConsole console_;
  ConsolePanelState console_panel_;
};

}  // namespace meshedit
