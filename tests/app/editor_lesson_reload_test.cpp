// Hot reload in the window (EditorApp on a surfaceless EGL context, its frames run through a headless ImGui): a lesson
// saved with a new lesson{title=} renames the window at the next check, keeping the step (the lesson panel draws the
// runner's title every frame); a save that breaks the file keeps the version that ran under its title, with the error
// in the panel; while the window is titled after a file opened since, a reload keeps that file's title; and going
// back to the lesson list drops a lesson's title. Skipped where no EGL context can be made.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1280, kHeight = 800;

class EditorLessonReload : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
    file_ = testing::scratch_dir() / "renamed.lua";
  }
  void TearDown() override { app_.reset(); }  // its GL objects go while the context is current

  // Saves the lesson with a modification time past the last one (some file systems keep whole seconds).
  void save(const std::string& text) {
    const bool existed = fs::exists(file_);
    const fs::file_time_type before = existed ? fs::last_write_time(file_) : fs::file_time_type{};
    std::ofstream(file_, std::ios::binary) << text;
    if (existed) fs::last_write_time(file_, before + std::chrono::seconds(2));
  }
  static std::string lesson(const std::string& title) {
    return "lesson { title = \"" + title +
           "\" }\n"
           "step(\"One\", function() say(\"one\") end)\n"
           "step(\"Two\", function() say(\"two, from " +
           title + "\") end)\n";
  }

  // Frames of 250 ms (the most a frame advances the lesson), enough for hot reload's half-second check.
  void frames(int count) {
    for (int i = 0; i < count; ++i) harness_.frame([&] { app_->frame(kWidth, kHeight, 250.0f); });
  }

  ui_testing::ImGuiHarness harness_{ImVec2(kWidth, kHeight)};
  std::unique_ptr<EditorApp> app_;
  fs::path file_;
};

TEST_F(EditorLessonReload, ASavedTitleRenamesTheWindowAndABrokenSaveKeepsIt) {
  save(lesson("Before the save"));
  ASSERT_TRUE(app_->open(file_)) << app_->lesson().error();
  app_->lesson().next();
  frames(1);
  EXPECT_EQ(app_->title(), "MeshEdit - Before the save");

  save(lesson("After the save"));
  frames(3);
  EXPECT_EQ(app_->lesson().title(), "After the save");
  EXPECT_EQ(app_->title(), "MeshEdit - After the save");
  EXPECT_EQ(app_->lesson().current_step(), 1u);
  EXPECT_EQ(app_->lesson().said(), std::vector<std::string>{"two, from After the save"});

  // A save that breaks the file: the version that ran goes on under its title; the panel shows the error.
  save("lesson { title = \"Broken\" }\nstep(\"One\", function() end\n");
  frames(3);
  EXPECT_EQ(app_->title(), "MeshEdit - After the save");
  EXPECT_EQ(app_->lesson().title(), "After the save");
  EXPECT_EQ(app_->lesson().error().rfind("renamed.lua:", 0), 0u) << app_->lesson().error();

  // Fixed: the next save renames both again.
  save(lesson("Fixed"));
  frames(3);
  EXPECT_EQ(app_->lesson().title(), "Fixed");
  EXPECT_EQ(app_->title(), "MeshEdit - Fixed");
  EXPECT_EQ(app_->lesson().error(), "");
}

TEST_F(EditorLessonReload, AWindowTitledAfterAFileOpenedSinceKeepsItsTitle) {
  save(lesson("Before the save"));
  ASSERT_TRUE(app_->open(file_)) << app_->lesson().error();
  app_->show_mesh(build_halfedge_mesh(make_torus(5, 7)), "torus.obj");
  EXPECT_EQ(app_->title(), "MeshEdit - torus.obj");
  save(lesson("After the save"));
  frames(3);
  EXPECT_EQ(app_->lesson().title(), "After the save");  // what the panel shows
  EXPECT_EQ(app_->title(), "MeshEdit - torus.obj");     // the window is the file's
}

TEST_F(EditorLessonReload, GoingBackToTheListDropsTheLessonsTitle) {
  save(lesson("A lesson"));
  ASSERT_TRUE(app_->open(file_)) << app_->lesson().error();
  EXPECT_EQ(app_->title(), "MeshEdit - A lesson");
  app_->lessons().show_list();
  EXPECT_EQ(app_->title(), "MeshEdit");
  // A file's title stays: going back to the list does not rename a window that names a file.
  ASSERT_TRUE(app_->open(file_)) << app_->lesson().error();
  app_->show_mesh(build_halfedge_mesh(make_torus(5, 7)), "torus.obj");
  app_->lessons().show_list();
  EXPECT_EQ(app_->title(), "MeshEdit - torus.obj");
}

}  // namespace
}  // namespace meshedit
