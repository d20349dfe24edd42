// The "Your code" panel (ui/student_editor.h) in headless ImGui: a long line is never cut off (the view scrolls
// sideways to its end), the view follows the text cursor as keys move it, an error's line is scrolled into sight and
// marked, and Ctrl+S in the editor asks for a save.
#include "ui/student_editor.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <fstream>
#include <string>

#include "support/imgui_harness.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// GLFW's key numbers, as the window's backend maps them (a letter is its ASCII capital).
constexpr int kKeyEnd = 269, kKeyDown = 264, kKeyLeftControl = 341, kKeyS = 83;

const std::string kLongLine = "local far = \"" + std::string(300, 'x') + "\" -- the end";

// A student file of 60 lines whose third is 330 characters long.
fs::path long_file() {
  const fs::path file = testing::scratch_dir() / "flip.lua";
  std::ofstream out(file);
  out << "-- line 1\n-- line 2\n" << kLongLine << "\n";
  for (int line = 4; line <= 60; ++line) out << "-- line " << line << "\n";
  return file;
}

// The panel in a 400x300 window at the top-left corner of the screen.
struct Panel {
  StudentEdit edit;
  StudentEditorState state;
  std::string error;
  std::optional<size_t> error_line;
  bool save = false;

  void draw() {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(400, 300));
    ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoDecoration);
    save = draw_student_editor_contents(edit, state, error, error_line);
    ImGui::End();
  }
};

// The child window the code scrolls in.
ImGuiWindow* code_view() {
  for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
    if (std::string(window->Name).find("##code view") != std::string::npos) return window;
  }
  return nullptr;
}

void press(ui_testing::ImGuiHarness& imgui, Panel& panel, int key, bool ctrl = false) {
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = ctrl;
  io.KeysDown[key] = true;
  imgui.frame([&] { panel.draw(); });
  io.KeysDown[key] = false;
  io.KeyCtrl = false;
  for (int i = 0; i < 2; ++i) imgui.frame([&] { panel.draw(); });  // a scroll asked for lands a frame later
}

class StudentEditorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_End] = kKeyEnd;
    io.KeyMap[ImGuiKey_DownArrow] = kKeyDown;
    panel.edit.follow(long_file());
    for (int i = 0; i < 2; ++i) imgui.frame([&] { panel.draw(); });
  }
  void draw() {
    imgui.frame([&] { panel.draw(); });
  }
  ui_testing::ImGuiHarness imgui;
  Panel panel;
};

TEST_F(StudentEditorTest, ALongLineFitsInTheTextAndTheViewFollowsTheCursorToItsEnd) {
  const float char_width = ImGui::GetFont()->GetCharAdvance(' ');
  EXPECT_GT(panel.state.text_width, panel.state.view_width);
  EXPECT_GE(panel.state.text_width, float(kLongLine.size()) * char_width);
  ImGuiWindow* view = code_view();
  ASSERT_NE(view, nullptr);
  EXPECT_GT(view->ScrollMax.x, 0.0f);
  EXPECT_EQ(view->Scroll.x, 0.0f);

  // A click on line 3, then End: the view scrolls right until the line's end is in sight.
  const float line_height = ImGui::GetFontSize();
  const ImVec2 on_line_3(view->Pos.x + 20.0f, view->Pos.y + ImGui::GetStyle().FramePadding.y + line_height * 2.5f);
  imgui.click(on_line_3, [&] { panel.draw(); });
  press(imgui, panel, kKeyEnd);
  view = code_view();
  const float line_end = float(kLongLine.size()) * char_width;
  EXPECT_GT(view->Scroll.x, line_end - panel.state.view_width) << "the end of line 3 is right of the view";
  EXPECT_LT(view->Scroll.x, line_end) << "the end of line 3 is left of the view";
  EXPECT_EQ(view->Scroll.y, 0.0f);

  // Down, line after line, past the view's bottom: the view scrolls down with the cursor.
  for (int line = 4; line <= 40; ++line) press(imgui, panel, kKeyDown);
  view = code_view();
  const float cursor_y = ImGui::GetStyle().FramePadding.y + line_height * 39.0f;
  EXPECT_GT(view->Scroll.y, cursor_y + line_height - view->InnerRect.GetHeight() - 1.0f) << "line 40 is below the view";
  EXPECT_LE(view->Scroll.y, cursor_y) << "line 40 is above the view";
  EXPECT_FALSE(panel.edit.dirty()) << "moving the cursor changed the text";
}

TEST_F(StudentEditorTest, AnErrorLineIsScrolledIntoSightOnce) {
  panel.error = "flip.lua:50: attempt to index a nil value";
  panel.error_line = 50;
  for (int i = 0; i < 2; ++i) draw();
  const float line_height = ImGui::GetFontSize();
  const float line_50 = ImGui::GetStyle().FramePadding.y + line_height * 49.0f;
  ImGuiWindow* view = code_view();
  ASSERT_NE(view, nullptr);
  EXPECT_LE(view->Scroll.y, line_50);
  EXPECT_GE(view->Scroll.y + view->InnerRect.GetHeight(), line_50 + line_height);
  // The student scrolls back up: the same error does not pull the view down again.
  ImGui::SetScrollY(view, 0.0f);
  for (int i = 0; i < 2; ++i) draw();
  EXPECT_EQ(code_view()->Scroll.y, 0.0f);
}

TEST_F(StudentEditorTest, CtrlSInTheEditorAsksForASave) {
  ImGuiWindow* view = code_view();
  ASSERT_NE(view, nullptr);
  imgui.click(ImVec2(view->Pos.x + 20.0f, view->Pos.y + 10.0f), [&] { panel.draw(); });
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = true;
  io.KeysDown[kKeyLeftControl] = true;
  io.KeysDown[kKeyS] = true;
  draw();
  EXPECT_TRUE(panel.save);
  draw();
  EXPECT_FALSE(panel.save) << "a key held down saves once";
  io.KeysDown[kKeyS] = false;
  io.KeysDown[kKeyLeftControl] = false;
  io.KeyCtrl = false;
  // S alone types an S and asks for nothing.
  imgui.type("S", [&] { panel.draw(); });
  EXPECT_FALSE(panel.save);
  EXPECT_TRUE(panel.edit.dirty());
}

}  // namespace
}  // namespace meshedit
