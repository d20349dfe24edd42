// The command table (document/command_table.h) and its keys (app/commands.h): names and menu paths unique, each menu's
// items together and in the menu bar's order, every key text a GLFW key, no key pressed two ways in one view, the
// course's keys where the course puts them, every key in the user docs' key table, and the lesson's commands each
// with a menu item to run them from.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "app/commands.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(Commands, NamesAndMenuPathsAreUniqueAndEachMenuIsInOnePiece) {
  std::set<std::string> names, paths;
  std::vector<std::string> menus;  // the menu titles in the order their items come
  for (const Command& c : commands()) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(names.insert(c.name).second) << "named twice";
    if (!c.menu) continue;
    EXPECT_TRUE(paths.insert(c.menu).second) << "menu path twice";
    EXPECT_FALSE(menu_label(c).empty()) << c.menu;
    const std::string title(menu_title(c));
    if (menus.empty() || menus.back() != title) {
      EXPECT_EQ(std::find(menus.begin(), menus.end(), title), menus.end()) << title << "'s items are apart";
      menus.push_back(title);
    }
  }
  EXPECT_EQ(menus, (std::vector<std::string>{"File", "Edit", "Subdivide", "View", "Help"}));
}

TEST(Commands, EveryKeyTextIsAKeyAndNoKeyIsBoundTwiceInAView) {
  std::set<std::tuple<int, bool, bool, CommandView>> seen;
  for (const Command& c : commands()) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(c.key != nullptr, c.help != nullptr) << "a key has a help text, and only a key";
    if (!c.key) {
      EXPECT_EQ(c.other_key, nullptr);
    }
    for (const char* text : {c.key, c.other_key}) {
      if (!text) continue;
      const std::optional<KeyChord> chord = parse_key_text(text);
      ASSERT_TRUE(chord) << text;
      EXPECT_TRUE(seen.insert({chord->key, chord->mods.ctrl, chord->mods.shift, c.view}).second) << text;
    }
  }
}

TEST(Commands, TheCourseKeysDoWhatTheCourseSays) {
  const auto command_of = [](int key, bool ctrl, bool shift, CommandView view) {
    const Command* c = find_key_command(key, {ctrl, shift}, view);
    return c ? std::optional<CommandId>(c->id) : std::nullopt;
  };
  using I = CommandId;
  using V = CommandView;
  EXPECT_EQ(command_of(GLFW_KEY_F, false, false, V::Mesh), I::Flip);
  EXPECT_EQ(command_of(GLFW_KEY_S, false, false, V::Mesh), I::Split);
  EXPECT_EQ(command_of(GLFW_KEY_L, false, false, V::Mesh), I::Loop);
  EXPECT_EQ(command_of(GLFW_KEY_L, false, true, V::Mesh), I::LoopPhase);
  EXPECT_EQ(command_of(GLFW_KEY_N, false, false, V::Mesh), I::Next);
  EXPECT_EQ(command_of(GLFW_KEY_T, false, false, V::Mesh), I::Twin);
  EXPECT_EQ(command_of(GLFW_KEY_W, false, false, V::Mesh), I::Wireframe);
  EXPECT_EQ(command_of(GLFW_KEY_Q, false, false, V::Mesh), I::Shading);
  EXPECT_EQ(command_of(GLFW_KEY_Q, true, false, V::Mesh), I::Quit);
  EXPECT_EQ(command_of(GLFW_KEY_I, false, false, V::Mesh), I::Inspector);
  EXPECT_EQ(command_of(GLFW_KEY_SPACE, false, false, V::Curve), I::ResetView);
  // E and C mean one thing on a mesh and another on a curve.
  EXPECT_EQ(command_of(GLFW_KEY_E, false, false, V::Mesh), I::Edge);
  EXPECT_EQ(command_of(GLFW_KEY_E, false, false, V::Curve), I::CurveStep);
  EXPECT_EQ(command_of(GLFW_KEY_C, false, false, V::Mesh), I::Collapse);
  EXPECT_EQ(command_of(GLFW_KEY_C, false, false, V::Curve), I::CurveToggle);
  EXPECT_EQ(command_of(GLFW_KEY_M, false, false, V::Patches), I::PatchMine);
  EXPECT_EQ(command_of(GLFW_KEY_Z, true, false, V::Mesh), I::Undo);
  EXPECT_EQ(command_of(GLFW_KEY_Y, true, false, V::Mesh), I::Redo);
  EXPECT_EQ(command_of(GLFW_KEY_Z, true, true, V::Mesh), I::Redo);
  EXPECT_EQ(command_of(GLFW_KEY_KP_ADD, true, false, V::Mesh), I::BiggerText);
  EXPECT_EQ(command_of(GLFW_KEY_F, false, false, V::Curve), std::nullopt);  // no flip on a curve
  EXPECT_EQ(command_of(GLFW_KEY_S, false, true, V::Mesh), std::nullopt);    // modifiers must match
  EXPECT_STREQ(command(I::Redo).key, "Ctrl+Y");                             // the menus' shortcut texts
  EXPECT_STREQ(command(I::LoopPhase).key, "Shift+L");
}

TEST(Commands, EveryBoundKeyIsReadEachFrame) {
  const std::span<const int> read = bound_keys();
  for (const Command& c : commands()) {
    for (const char* text : {c.key, c.other_key}) {
      if (!text) continue;
      EXPECT_NE(std::find(read.begin(), read.end(), parse_key_text(text)->key), read.end()) << text;
    }
  }
}

TEST(Commands, TheLessonNamesOfKeys) {
  EXPECT_EQ(lesson_key_name(GLFW_KEY_F, {}), "F");
  EXPECT_EQ(lesson_key_name(GLFW_KEY_L, {false, true}), "shift+L");
  EXPECT_EQ(lesson_key_name(GLFW_KEY_Z, {true, false}), "ctrl+Z");
  EXPECT_EQ(lesson_key_name(GLFW_KEY_SPACE, {}), "Space");
  EXPECT_EQ(lesson_key_name(GLFW_KEY_LEFT_BRACKET, {}), "");
}

// A lesson's wait_for{command = NAME} hint says where the command is, so every command a lesson can wait for has a
// menu item; and the names a lesson may use are these.
TEST(Commands, EveryCommandALessonCanWaitForHasAMenuItem) {
  size_t waitable = 0;
  for (const Command& c : commands()) {
    if (!c.lesson_can_wait) continue;
    ++waitable;
    EXPECT_NE(c.menu, nullptr) << c.name;
    EXPECT_EQ(find_lesson_command(c.name), &c);
    EXPECT_NE(lesson_command_names().find(c.name), std::string::npos) << c.name;
  }
  EXPECT_EQ(waitable, 8u);
  EXPECT_EQ(command_place(command(CommandId::LoopPhase)), "Subdivide > Loop, the next phase (Shift+L)");
  EXPECT_EQ(command_place(command(CommandId::Triangulate)), "Edit > Triangulate");
  EXPECT_EQ(find_lesson_command("wireframe"), nullptr);  // a command, but not one a lesson waits for
}

// The user docs' key table (docs/KEYS.md) names every command's key, so the docs cannot promise a key the window
// lacks or leave one out.
TEST(Commands, TheDocsListEveryKey) {
  std::ifstream in(testing::source_dir() / "docs" / "KEYS.md");
  ASSERT_TRUE(in) << "docs/KEYS.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  for (const Command& c : commands()) {
    if (!c.key) continue;
    const std::string code = std::string("`") + c.key + "`", spaced = std::string("`` ") + c.key + " ``";
    EXPECT_TRUE(docs.find(code) != std::string::npos || docs.find(spaced) != std::string::npos)
        << c.key << " is not in docs/KEYS.md";
  }
}

}  // namespace
}  // namespace meshedit
