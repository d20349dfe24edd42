// The window's command table (see command_table.h).
#include "document/command_table.h"

#include <algorithm>
#include <iterator>
#include <vector>

namespace meshedit {
namespace {

using I = CommandId;
using V = CommandView;
constexpr bool kEdits = true, kWaitable = true, kSeparator = true, kSubmenu = true;

// In the menu bar's order, then the commands that only have a key. Fields:
// id, name, menu, key, other key, view, help, edits, a lesson can wait for it, separator before, submenu.
constexpr Command kCommands[] = {
    // ---- File ----
    {I::OpenFromComputer, "open-from-computer", "File > Open mesh from this computer...", nullptr, nullptr,
     V::Everywhere, nullptr},
    {I::Open, "open", "File > Open...", "Ctrl+O", nullptr, V::Everywhere, "open a file (or drop one on the window)"},
    {I::OpenRecent, "open-recent", "File > Open recent", nullptr, nullptr, V::Everywhere, nullptr, false, false, false,
     kSubmenu},
    {I::OpenRepaired, "open-repaired", "File > Open a repaired copy", nullptr, nullptr, V::Everywhere, nullptr, false,
     kWaitable},
    {I::SaveAs, "save-as", "File > Save as...", nullptr, nullptr, V::Everywhere, nullptr},
    {I::Screenshot, "screenshot", "File > Screenshot", "P", nullptr, V::Everywhere,
     "screenshot (a PNG in the current folder)"},
    {I::DownloadCode, "download-code", "File > Download your code", nullptr, nullptr, V::Everywhere, nullptr, false,
     false, kSeparator},
    {I::UploadCode, "upload-code", "File > Upload your .lua from this computer...", nullptr, nullptr, V::Everywhere,
     nullptr},
    {I::CheckMyWork, "check-my-work", "File > Check my work", "Ctrl+K", nullptr, V::Everywhere,
     "check your work: the course's visible tests on your saved files, as Gradescope runs them (the Check tab)", false,
     false, kSeparator},
    {I::Writeup, "write-up", "File > Write-up", nullptr, nullptr, V::Everywhere, nullptr},
    {I::WriteupView, "write-up-view", "File > Use this view in the write-up", nullptr, nullptr, V::Everywhere, nullptr},
    {I::Quit, "quit", "File > Quit", "Ctrl+Q", nullptr, V::Everywhere,
     "quit (the window's size and columns are remembered; unsaved code in Your code is asked about first)", false,
     false, kSeparator},
    // ---- Edit ----
    {I::Undo, "undo", "Edit > Undo", "Ctrl+Z", nullptr, V::Mesh, "undo (ids come back exactly)", kEdits},
    {I::Redo, "redo", "Edit > Redo", "Ctrl+Y", "Ctrl+Shift+Z", V::Mesh, "redo (also Ctrl+Shift+Z)", kEdits},
    {I::Flip, "flip", "Edit > Flip edge", "F", nullptr, V::Mesh,
     "flip the selected edge (on a halfedge: go to its face)", kEdits, false, kSeparator},
    {I::Split, "split", "Edit > Split edge", "S", nullptr, V::Mesh, "split the selected edge", kEdits},
    {I::Collapse, "collapse", "Edit > Collapse edge", "C", nullptr, V::Mesh, "collapse the selected edge", kEdits},
    {I::Triangulate, "triangulate", "Edit > Triangulate", nullptr, nullptr, V::Mesh, nullptr, kEdits, kWaitable,
     kSeparator},
    // ---- Subdivide ----
    {I::Loop, "loop", "Subdivide > Loop subdivision", "L", nullptr, V::Mesh, "Loop subdivision", kEdits, kWaitable},
    {I::LoopPhase, "loop-phase", "Subdivide > Loop, the next phase", "Shift+L", nullptr, V::Mesh,
     "Loop subdivision, one phase per press", kEdits, kWaitable},
    {I::LoopWeights, "loop-weights", "Subdivide > Loop's original weights (beta)", nullptr, nullptr, V::Mesh, nullptr},
    {I::CatmullClark, "catmull-clark", "Subdivide > Catmull-Clark subdivision", nullptr, nullptr, V::Mesh, nullptr,
     kEdits, kWaitable, kSeparator},
    {I::CatmullClarkPhase, "catmull-clark-phase", "Subdivide > Catmull-Clark, the next phase", nullptr, nullptr,
     V::Mesh, nullptr, kEdits, kWaitable},
    {I::Linear, "linear", "Subdivide > Linear subdivision", nullptr, nullptr, V::Mesh, nullptr, kEdits, kWaitable},
    {I::LinearPhase, "linear-phase", "Subdivide > Linear, the next phase", nullptr, nullptr, V::Mesh, nullptr, kEdits,
     kWaitable},
    // ---- View ----
    {I::Wireframe, "wireframe", "View > Wireframe", "W", nullptr, V::Everywhere, "wireframe on or off"},
    {I::Shading, "smooth-shading", "View > Smooth shading", "Q", nullptr, V::Everywhere, "flat or smooth shading"},
    {I::Vertices, "vertices", "View > Vertices", nullptr, nullptr, V::Everywhere, nullptr},
    {I::HalfedgeArrows, "halfedge-arrows", "View > Halfedge arrows", nullptr, nullptr, V::Everywhere, nullptr},
    {I::Boundary, "boundary", "View > Boundary", nullptr, nullptr, V::Everywhere, nullptr},
    {I::IdLabels, "id-labels", "View > Id labels", nullptr, nullptr, V::Everywhere, nullptr},
    {I::AnimateEdits, "animate-edits", "View > Animate edits", nullptr, nullptr, V::Everywhere, nullptr},
    {I::FoldLeft, "left-column", "View > Left column (lesson)", "[", nullptr, V::Everywhere,
     "fold or unfold the left column (the lesson)", false, false, kSeparator},
    {I::FoldRight, "right-column", "View > Right column (tables)", "]", nullptr, V::Everywhere,
     "fold or unfold the right column (the tables)"},
    {I::Inspector, "inspector", "View > Inspector", "I", nullptr, V::Mesh, "the inspector"},
    {I::PointerTables, "pointer-tables", "View > Pointer tables", nullptr, nullptr, V::Everywhere, nullptr},
    {I::Exercises, "exercises", "View > Exercises: mine vs reference", "X", nullptr, V::Everywhere,
     "the exercises: run your flip, split, upsample or normals (scripts/student) or the reference; replay writes"},
    {I::YourCode, "your-code", "View > Your code (the exercise's file)", nullptr, nullptr, V::Everywhere, nullptr},
    {I::Console, "console", "View > Lua console", "`", nullptr, V::Everywhere,
     "the Lua console: `mesh` is the mesh shown, `selected` the selection; Up/Down for history"},
    {I::UpAxis, "up-axis", "View > Up axis", nullptr, nullptr, V::Everywhere, nullptr, false, false, false, kSubmenu},
    {I::BiggerText, "bigger-text", "View > Bigger text", "Ctrl+=", "Ctrl+keypad +", V::Everywhere, "bigger text", false,
     false, kSeparator},
    {I::SmallerText, "smaller-text", "View > Smaller text", "Ctrl+-", "Ctrl+keypad -", V::Everywhere, "smaller text"},
    {I::DefaultText, "default-text", "View > Default text size", "Ctrl+0", "Ctrl+keypad 0", V::Everywhere,
     "the default text size"},
    {I::Theme, "theme", "View > Theme", nullptr, nullptr, V::Everywhere, nullptr, false, false, false, kSubmenu},
    {I::Language, "language", "View > Language", nullptr, nullptr, V::Everywhere, nullptr, false, false, false,
     kSubmenu},
    {I::ResetView, "reset-view", "View > Reset view", "Space", nullptr, V::Everywhere, "reset the view", false, false,
     kSeparator},
    // ---- Help ----
    {I::Keys, "keys", "Help > Keys", "F1", nullptr, V::Everywhere, "this list of keys"},
    {I::BugReport, "bug-report", "Help > Save a bug report", nullptr, nullptr, V::Everywhere, nullptr},
    // ---- keys only ----
    {I::ClearSelection, "clear-selection", nullptr, "Esc", nullptr, V::Mesh, "clear the selection"},
    {I::Next, "next", nullptr, "N", nullptr, V::Mesh, "from a halfedge to its next"},
    {I::Twin, "twin", nullptr, "T", nullptr, V::Mesh, "from a halfedge to its twin"},
    {I::Vertex, "vertex", nullptr, "V", nullptr, V::Mesh, "from a halfedge to its vertex"},
    {I::Edge, "edge", nullptr, "E", nullptr, V::Mesh, "from a halfedge to its edge"},
    {I::Halfedge, "halfedge", nullptr, "H", nullptr, V::Mesh, "from anything to its halfedge"},
    {I::CurveStep, "curve-step", nullptr, "E", nullptr, V::Curve, "curve view: one more de Casteljau level"},
    {I::CurveToggle, "curve-toggle", nullptr, "C", nullptr, V::Curve, "curve view: show or hide the curve"},
    {I::CurveMine, "curve-mine", nullptr, "M", nullptr, V::Curve,
     "curve view: the levels from your evaluate_step (scripts/student/curve.lua), checked against the reference"},
    {I::PatchMine, "patch-mine", nullptr, "M", nullptr, V::Patches,
     "patch view: the probe point from your evaluate (scripts/student/patch.lua), checked against the reference"},
};

// Row i is CommandId i: command(id) is an index.
constexpr bool rows_in_id_order() {
  for (size_t i = 0; i < std::size(kCommands); ++i) {
    if (static_cast<size_t>(kCommands[i].id) != i) return false;
  }
  return true;
}
static_assert(rows_in_id_order(), "kCommands' rows must be in CommandId's order");
static_assert(std::size(kCommands) == static_cast<size_t>(CommandId::PatchMine) + 1, "a row per CommandId");

constexpr std::string_view kMenuSeparator = " > ";

}  // namespace

std::span<const Command> commands() { return kCommands; }

const Command& command(CommandId id) { return kCommands[static_cast<size_t>(id)]; }

const Command* find_command(std::string_view name) {
  const auto* found =
      std::find_if(std::begin(kCommands), std::end(kCommands), [&](const Command& c) { return name == c.name; });
  return found == std::end(kCommands) ? nullptr : found;
}

std::string_view menu_label(const Command& command) {
  if (!command.menu) return {};
  const std::string_view path = command.menu;
  return path.substr(path.find(kMenuSeparator) + kMenuSeparator.size());
}

std::string_view menu_title(const Command& command) {
  if (!command.menu) return {};
  const std::string_view path = command.menu;
  return path.substr(0, path.find(kMenuSeparator));
}

std::string command_place(const Command& command) {
  std::string place = command.menu ? command.menu : "";
  if (command.key) place += place.empty() ? command.key : std::string(" (") + command.key + ")";
  return place;
}

const Command* find_lesson_command(std::string_view name) {
  const Command* found = find_command(name);
  return found && found->lesson_can_wait ? found : nullptr;
}

std::string lesson_command_names() {
  std::vector<const char*> names;
  for (const Command& c : kCommands) {
    if (c.lesson_can_wait) names.push_back(c.name);
  }
  std::string text;
  for (size_t i = 0; i < names.size(); ++i) {
    text += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
    text += names[i];
  }
  return text;
}

}  // namespace meshedit
