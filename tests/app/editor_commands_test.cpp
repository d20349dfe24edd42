// The command table drives the window (EditorApp on a surfaceless EGL context, its frames run through a headless
// ImGui): each menu shows every command the table puts in it, and a click on an item runs its command; a command a
// lesson waits for reaches the lesson whether it ran from its menu item, its key or a scripted verb; and the verb
// `triangulate` and Edit > Triangulate do the same (a running exercise replay finished first, one undoable step, the
// lesson told). Skipped where no EGL context can be made.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "app/action_verbs.h"
#include "app/editor_app.h"
#include "app/window_host.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1280, kHeight = 800;

class EditorCommands : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
    app_->show_mesh(build_halfedge_mesh(make_torus(4, 6)), "");  // triangles: every subdivision and Loop run
  }
  void TearDown() override { app_.reset(); }  // its GL objects go while the context is current

  void frame() { harness_.frame(draw()); }
  std::function<void()> draw() {
    return [this] { app_->frame(kWidth, kHeight, 16.0f); };
  }
  // Clicks what the last frame drew under `name` in the window's probe; false when it drew nothing so named.
  bool click(const std::string& name) {
    const UiProbe::Item* item = app_->panels().probe().find(name);
    if (!item) return false;
    harness_.click(item->center(), draw());
    return true;
  }
  // Opens the menu and clicks the command's item in it.
  void click_menu_item(const Command& c) {
    frame();
    ASSERT_TRUE(click("menu:" + std::string(menu_title(c)))) << c.menu;
    ASSERT_TRUE(click(std::string("menu-item:") + c.name)) << c.menu << " is not in its menu";
  }
  // Runs a scripted verb as `meshedit --actions` does; "" or what failed.
  std::string verb(const std::string& line) {
    const std::vector<ScriptedAction> actions = parse_actions(line + "\n", "test");
    const ScriptedAction& action = actions.at(0);
    return find_action_verb(action.verb)->run(*app_, action);
  }
  // Opens a lesson whose one step waits for the command `name`.
  void wait_for_command(const std::string& name) {
    const fs::path file = testing::scratch_dir() / "waits.lua";
    std::ofstream(file) << "lesson { title = \"Waits\" }\n"
                           "step(\"Run it\", function() wait_for { command = \""
                        << name << "\" } say(\"ran\") end)\n";
    ASSERT_TRUE(app_->lessons().open(file)) << app_->lesson().error();
    app_->show_mesh(build_halfedge_mesh(make_torus(4, 6)), "");
    ASSERT_EQ(app_->lesson().step_state(), LessonRunner::StepState::Waiting);
  }
  bool lesson_heard_it() const { return app_->lesson().step_state() == LessonRunner::StepState::Finished; }

  ui_testing::ImGuiHarness harness_{ImVec2(kWidth, kHeight)};
  std::unique_ptr<EditorApp> app_;
};

TEST_F(EditorCommands, EachMenuShowsEveryCommandTheTablePutsInIt) {
  for (const Command& c : commands()) {
    if (!c.menu) continue;
    // The page's own items (its file picker, the student file's download and upload) are not on the desktop.
    const bool page_only = c.id == CommandId::OpenFromComputer ? !host_has_file_picker()
                           : c.id == CommandId::DownloadCode || c.id == CommandId::UploadCode
                               ? host_files_on_users_disk()
                               : false;
    frame();
    ASSERT_TRUE(click("menu:" + std::string(menu_title(c)))) << c.menu;
    EXPECT_EQ(app_->panels().probe().find(std::string("menu-item:") + c.name) != nullptr, !page_only) << c.menu;
    harness_.click(ImVec2(kWidth / 2.0f, kHeight - 4.0f), draw());  // closes the menu
  }
}

TEST_F(EditorCommands, AMenuItemRunsItsCommand) {
  const bool wireframe = app_->view().options().wireframe;
  click_menu_item(command(CommandId::Wireframe));
  EXPECT_NE(app_->view().options().wireframe, wireframe);
  const size_t faces = app_->document().mesh.num_faces();
  click_menu_item(command(CommandId::Linear));
  EXPECT_EQ(app_->document().mesh.num_faces(), 4 * faces);
  click_menu_item(command(CommandId::Undo));
  EXPECT_EQ(app_->document().mesh.num_faces(), faces);
}

// Every command a lesson can wait for (but File > Open a repaired copy, which needs a refused file:
// window_repair_test.cpp) is told to a waiting lesson from its menu item, its key (when it has one), the verb
// `command NAME` and the verb made for it.
TEST_F(EditorCommands, ALessonHearsOfItsCommandFromTheMenuTheKeyAndTheVerbs) {
  for (const Command& c : commands()) {
    if (!c.lesson_can_wait || c.id == CommandId::OpenRepaired) continue;
    SCOPED_TRACE(c.name);
    wait_for_command(c.name);
    click_menu_item(c);
    EXPECT_TRUE(lesson_heard_it()) << "from the menu";

    if (const std::optional<KeyChord> key = command_key(c)) {
      wait_for_command(c.name);
      app_->handle_key(key->key, key->mods);
      EXPECT_TRUE(lesson_heard_it()) << "from the key " << c.key;
    }

    wait_for_command(c.name);
    EXPECT_EQ(verb(std::string("command ") + c.name), "");
    EXPECT_TRUE(lesson_heard_it()) << "from the verb command";

    const std::string name = c.name;
    const bool phase = name.ends_with("-phase");
    const std::string scheme = phase ? name.substr(0, name.size() - 6) : name;
    const std::string own =
        name == "triangulate" ? "triangulate" : std::string(phase ? "subdivide-phase " : "subdivide ") + scheme;
    wait_for_command(c.name);
    EXPECT_EQ(verb(own), "");
    EXPECT_TRUE(lesson_heard_it()) << "from the verb " << own;
  }
}

TEST_F(EditorCommands, TheTriangulateVerbAndMenuItemDoTheSame) {
  const auto triangulated = [&](bool from_menu) {
    wait_for_command("triangulate");
    // A replay of the student's flip running: the edit must land after it ends, not in the middle of its history.
    const std::string solutions = (testing::source_dir() / "tests" / "exercise" / "solutions").string();
    EXPECT_EQ(verb("exercise flip " + solutions), "");
    EXPECT_EQ(verb("select e3"), "");
    EXPECT_EQ(verb("run-mine"), "");
    app_->exercises().wait_for_run(app_->document(), app_->selection());  // its code ran on its own thread
    EXPECT_EQ(verb("replay-start"), "");
    EXPECT_TRUE(app_->exercises().replaying());
    if (from_menu) click_menu_item(command(CommandId::Triangulate));
    else EXPECT_EQ(verb("triangulate"), "");
    EXPECT_TRUE(lesson_heard_it());
    EXPECT_FALSE(app_->exercises().replaying());
    EXPECT_TRUE(app_->document().history.can_undo());
    return std::tuple(app_->document().mesh.num_faces(), app_->document().message.text);
  };
  const auto by_menu = triangulated(true);
  const auto by_verb = triangulated(false);
  EXPECT_EQ(by_menu, by_verb);
  EXPECT_NE(std::get<1>(by_menu).find("every face was already a triangle"), std::string::npos) << std::get<1>(by_menu);
}

}  // namespace
}  // namespace meshedit
