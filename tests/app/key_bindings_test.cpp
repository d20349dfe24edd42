// The window's key table (app/key_bindings.h): one help row per command, no key pressed two ways in one view, a
// view's own row before the Everywhere row of the same key, the course's keys where the course puts them, and every
// key in the user docs' key table.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "app/key_bindings.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(KeyBindings, EachCommandHasOneHelpRowAndNoKeyIsBoundTwice) {
  std::map<KeyCommand, int> help_rows;
  std::set<std::tuple<int, bool, bool, KeyView>> seen;
  const KeyBinding* before = nullptr;
  for (const KeyBinding& b : key_bindings()) {
    SCOPED_TRACE(b.keys);
    if (b.help) ++help_rows[b.command];
    else ASSERT_TRUE(before && before->command == b.command) << "a second key must follow its command's row";
    EXPECT_TRUE(seen.insert({b.key, b.ctrl, b.shift, b.view}).second) << "bound twice";
    before = &b;
  }
  for (const auto& [command, rows] : help_rows) EXPECT_EQ(rows, 1) << int(command);
  for (const KeyBinding& b : key_bindings()) EXPECT_EQ(help_rows.count(b.command), 1u) << b.keys;
}

TEST(KeyBindings, TheCourseKeysDoWhatTheCourseSays) {
  const auto command = [](int key, bool ctrl, bool shift, KeyView view) {
    const KeyBinding* b = find_key_binding(key, ctrl, shift, view);
    return b ? std::optional<KeyCommand>(b->command) : std::nullopt;
  };
  EXPECT_EQ(command(GLFW_KEY_F, false, false, KeyView::Mesh), KeyCommand::FlipOrFace);
  EXPECT_EQ(command(GLFW_KEY_S, false, false, KeyView::Mesh), KeyCommand::Split);
  EXPECT_EQ(command(GLFW_KEY_L, false, false, KeyView::Mesh), KeyCommand::Loop);
  EXPECT_EQ(command(GLFW_KEY_L, false, true, KeyView::Mesh), KeyCommand::LoopPhase);
  EXPECT_EQ(command(GLFW_KEY_N, false, false, KeyView::Mesh), KeyCommand::Next);
  EXPECT_EQ(command(GLFW_KEY_T, false, false, KeyView::Mesh), KeyCommand::Twin);
  EXPECT_EQ(command(GLFW_KEY_W, false, false, KeyView::Mesh), KeyCommand::Wireframe);
  EXPECT_EQ(command(GLFW_KEY_Q, false, false, KeyView::Mesh), KeyCommand::Shading);
  EXPECT_EQ(command(GLFW_KEY_Q, true, false, KeyView::Mesh), KeyCommand::Quit);
  EXPECT_EQ(command(GLFW_KEY_I, false, false, KeyView::Mesh), KeyCommand::Inspector);
  EXPECT_EQ(command(GLFW_KEY_SPACE, false, false, KeyView::Curve), KeyCommand::ResetView);
  // E and C mean one thing on a mesh and another on a curve.
  EXPECT_EQ(command(GLFW_KEY_E, false, false, KeyView::Mesh), KeyCommand::Edge);
  EXPECT_EQ(command(GLFW_KEY_E, false, false, KeyView::Curve), KeyCommand::CurveStep);
  EXPECT_EQ(command(GLFW_KEY_C, false, false, KeyView::Mesh), KeyCommand::Collapse);
  EXPECT_EQ(command(GLFW_KEY_C, false, false, KeyView::Curve), KeyCommand::CurveToggle);
  EXPECT_EQ(command(GLFW_KEY_Z, true, true, KeyView::Mesh), KeyCommand::Redo);
  EXPECT_EQ(command(GLFW_KEY_F, false, false, KeyView::Curve), std::nullopt);  // no flip on a curve
  EXPECT_EQ(command(GLFW_KEY_S, false, true, KeyView::Mesh), std::nullopt);    // modifiers must match
  EXPECT_STREQ(shortcut_of(KeyCommand::Redo), "Ctrl+Y");
  EXPECT_STREQ(shortcut_of(KeyCommand::LoopPhase), "Shift+L");
}

TEST(KeyBindings, EveryBoundKeyIsReadEachFrame) {
  const std::span<const int> read = bound_keys();
  for (const KeyBinding& b : key_bindings()) {
    EXPECT_NE(std::find(read.begin(), read.end(), b.key), read.end()) << b.keys;
  }
}

// The user docs' key table (docs/KEYS.md) names every key of every command with a help row, so the docs cannot
// promise a key the window lacks or leave one out.
TEST(KeyBindings, TheDocsListEveryKey) {
  std::ifstream in(testing::source_dir() / "docs" / "KEYS.md");
  ASSERT_TRUE(in) << "docs/KEYS.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  for (const KeyBinding& b : key_bindings()) {
    if (!b.help) continue;
    const std::string code = std::string("`") + b.keys + "`", spaced = std::string("`` ") + b.keys + " ``";
    EXPECT_TRUE(docs.find(code) != std::string::npos || docs.find(spaced) != std::string::npos)
        << b.keys << " is not in docs/KEYS.md";
  }
}

}  // namespace
}  // namespace meshedit
