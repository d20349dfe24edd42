// The command table (document/command_table.h) as the window uses it: its key texts as GLFW keys, the command a key
// press runs, the keys the window reads each frame, and the key names a lesson waits for. EditorApp::run_command
// (app/commands.cpp) is what every command runs, from a menu, a key or a scripted verb.
//
// Invariants: every key text of the table parses (tests/app/commands_test.cpp); a key press runs the command of
// that key in the view shown, else the command of that key in every view (a view's own meaning wins).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "document/command_table.h"

namespace meshedit {

// Modifier state of a key press.
struct KeyMods {
  bool ctrl = false;
  bool shift = false;
};

// A key with its modifiers: a GLFW key code.
struct KeyChord {
  int key = 0;
  KeyMods mods;
};

// Where a command was started from: the one difference is the key's own meaning (F on a halfedge walks to its face,
// P names its screenshot by the time); a menu item, a key and a scripted verb otherwise run the same.
enum class CommandStart { Menu, Key, Script };

// "Shift+L", "Ctrl+Z", "Space", "Esc", "F1", "`", "[", "Ctrl+=", "Ctrl+keypad +" as a GLFW key; nullopt for other text.
std::optional<KeyChord> parse_key_text(std::string_view text);
// The command a key press runs while `view` is shown, or nullptr.
const Command* find_key_command(int key, KeyMods mods, CommandView view);
// The command's first key (nullopt: it has none).
std::optional<KeyChord> command_key(const Command& command);
// The GLFW keys some command names, each once: what the window reads each frame.
std::span<const int> bound_keys();
// "F", "shift+L", "ctrl+Z", "Space", "Escape": the names a lesson's wait_for{key=} is told (lesson_events.h compares
// them ignoring case); "" for a key lessons have no name for.
std::string lesson_key_name(int key, KeyMods mods);

}  // namespace meshedit
