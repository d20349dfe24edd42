// The window's commands in one table: each command's name, its menu item, its keys, its Keys-dialog text, whether
// it edits the mesh and whether a lesson can wait for it. Everything that names a command reads this table: the
// menus (app/editor_menus.cpp draws them from it), the keys (app/commands.h finds a key press's command here), the
// Keys dialog (F1) and the user docs' key table (docs/KEYS.md, held to it by tests/app/commands_test.cpp), the
// scripted verb `command NAME`, and the lesson's wait_for{command = NAME} with its hint ("Run Edit > Triangulate").
// What a command does is one function per command: app/commands.cpp's run_command, which for the mesh edits calls
// document/mesh_edits.h, the function the headless lesson driver's answers run too.
//
// The table lives here, below the document and the app, because the lesson API (this module) checks the command
// names a lesson waits for; it is plain data (keys as text, no GLFW), read by every module above.
//
// Invariants:
// - Names are unique; menu paths ("Subdivide > Loop subdivision") are unique; rows of one menu are in the menu's
//   order, and the menus come in the menu bar's order (File, Edit, Subdivide, View, Help).
// - A key ("Shift+L", "Ctrl+Z", "Space", "Ctrl+keypad +") is bound once per view; a key of one view wins over the same
//   key of Everywhere. Every command with a key has a `help` text; a command without one has none.
// - A command a lesson can wait for has a menu path: the hint "Run <menu> (<key>)" tells the student where it is.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace meshedit {

enum class CommandId {
  // File
  OpenFromComputer,
  Open,
  OpenRecent,
  OpenRepaired,
  SaveAs,
  Screenshot,
  DownloadCode,
  UploadCode,
  CheckMyWork,
  Writeup,
  WriteupView,
  Quit,
  // Edit
  Undo,
  Redo,
  Flip,
  Split,
  Collapse,
  Triangulate,
  // Subdivide
  Loop,
  LoopPhase,
  LoopWeights,
  CatmullClark,
  CatmullClarkPhase,
  Linear,
  LinearPhase,
  // View
  Wireframe,
  Shading,
  Vertices,
  HalfedgeArrows,
  Boundary,
  IdLabels,
  AnimateEdits,
  FoldLeft,
  FoldRight,
  Inspector,
  PointerTables,
  Exercises,
  YourCode,
  Console,
  UpAxis,
  BiggerText,
  SmallerText,
  DefaultText,
  Theme,
  Language,
  ResetView,
  // Help
  Keys,
  BugReport,
  // Keys only
  ClearSelection,
  Next,
  Twin,
  Vertex,
  Edge,
  Halfedge,
  CurveStep,
  CurveToggle,
  CurveMine,
  PatchMine,
};

// Where a command's key works: in every view, or only while the mesh, curve or patch view is on screen.
enum class CommandView { Everywhere, Mesh, Curve, Patches };

struct Command {
  CommandId id;
  const char* name;       // "loop-phase": for `command NAME` and wait_for{command = NAME}
  const char* menu;       // "Subdivide > Loop, the next phase"; nullptr: no menu item
  const char* key;        // "Shift+L", as the menus, the Keys dialog and the docs show it; nullptr: no key
  const char* other_key;  // a second key for the same command ("Ctrl+Shift+Z"), or nullptr
  CommandView view;       // where the keys work (a menu item works wherever its menu is enabled)
  const char* help;       // the Keys dialog's text for the key
  bool edits;             // changes the mesh or its history: a running exercise replay is finished first
  bool lesson_can_wait;   // a lesson may wait_for{command = name}: told to it each time the command ran
  bool separator_before;  // its menu draws a separator above it
  bool submenu;           // its menu item opens a submenu (Open recent, Up axis, Theme, Language): nothing to run
};

std::span<const Command> commands();
const Command& command(CommandId id);
// The command named `name`, or nullptr.
const Command* find_command(std::string_view name);
// The last part of the menu path ("Loop subdivision"); "" for no menu item.
std::string_view menu_label(const Command& command);
// The menu path's first part ("Subdivide"); "" for no menu item.
std::string_view menu_title(const Command& command);
// Where the student finds it: "Subdivide > Loop subdivision (L)", "Edit > Triangulate".
std::string command_place(const Command& command);

// The commands a lesson can wait for (lesson_can_wait): the one named `name`, or nullptr.
const Command* find_lesson_command(std::string_view name);
// "loop, loop-phase, ... or open-repaired": for the message that refuses another name.
std::string lesson_command_names();

}  // namespace meshedit
