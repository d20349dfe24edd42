// The lesson panel without a window: the lesson list (welcome first), hot reload when the file's
// modification time changes (and not before the check interval), and the panel drawing a lesson that waits
// for a button, then a lesson in an error state, in a headless ImGui frame.
#include <gtest/gtest.h>

#include <fstream>

#include "lesson/headless_host.h"
#include "support/test_support.h"
#include "ui/lesson_panel.h"
#include "ui/ui_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(LessonPanel, ListsLuaFilesWelcomeFirst) {
  const fs::path dir = testing::scratch_dir();
  for (const char* name : {"2_b.lua", "1_a.lua", "welcome.lua", "notes.txt"}) write(dir / name, "");
  LessonPanelState state;
  state.lessons_dir = dir;
  refresh_lessons(state);
  ASSERT_EQ(state.lesson_files.size(), 3u);
  EXPECT_EQ(state.lesson_files[0].filename(), "welcome.lua");
  EXPECT_EQ(state.lesson_files[1].filename(), "1_a.lua");
  EXPECT_EQ(state.lesson_files[2].filename(), "2_b.lua");
  state.lessons_dir = dir / "missing";
  refresh_lessons(state);
  EXPECT_TRUE(state.lesson_files.empty());
}

TEST(LessonPanel, ReloadsWhenTheFileChangesAndKeepsTheStep) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "l.lua";
  write(file, "step('One', function() say('one') end)\nstep('Two', function() say('two') end)\n");
  HeadlessHost host;
  LessonRunner runner(host);
  LessonPanelState state;
  ASSERT_TRUE(load_lesson(runner, state, file));
  runner.next();
  write(file, "step('One', function() say('one') end)\nstep('Two', function() say('second') end)\n");
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  EXPECT_FALSE(reload_if_changed(runner, state, 0.1));  // checked at most every half second
  EXPECT_TRUE(reload_if_changed(runner, state, 0.5));
  EXPECT_EQ(runner.current_step(), 1u);
  ASSERT_EQ(runner.said().size(), 1u);
  EXPECT_EQ(runner.said()[0], "second");
  EXPECT_FALSE(reload_if_changed(runner, state, 1.0));  // unchanged since
}

// A reload that ran out of memory is tried again at the next check; a lesson whose own error says "memory ran out" is
// a broken file like any other, and waits for the next save instead of reloading at every check.
TEST(LessonPanel, ALessonThatSaysMemoryRanOutItselfWaitsForTheNextSave) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "l.lua";
  write(file, "lesson{title='Before'}\nstep('One', function() say('one') end)\n");
  HeadlessHost host;
  LessonRunner runner(host);
  LessonPanelState state;
  ASSERT_TRUE(load_lesson(runner, state, file));
  write(file, "lesson{title='After'}\nerror('memory ran out')\n");
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  EXPECT_TRUE(reload_if_changed(runner, state, 0.5));
  EXPECT_EQ(runner.error(), "l.lua:2: memory ran out");
  EXPECT_FALSE(runner.out_of_memory());
  EXPECT_EQ(runner.title(), "Before");
  EXPECT_FALSE(reload_if_changed(runner, state, 0.5));  // not tried again until the file is saved
  EXPECT_FALSE(reload_if_changed(runner, state, 0.5));
  write(file, "lesson{title='After'}\nstep('One', function() say('uno') end)\n");
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(4));
  EXPECT_TRUE(reload_if_changed(runner, state, 0.5));
  EXPECT_EQ(runner.error(), "");
  EXPECT_EQ(runner.title(), "After");
  EXPECT_EQ(runner.said(), std::vector<std::string>{"uno"});
}

TEST(LessonPanel, DrawsAWaitingStepAndAnError) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "l.lua";
  write(file,
        "lesson{title='T'}\nstep('One', function() say('**bold** text') wait_for{button='Go on'} end)\n"
        "step('Two', function() error('broken') end)\n");
  HeadlessHost host;
  LessonRunner runner(host);
  LessonPanelState state;
  ASSERT_TRUE(load_lesson(runner, state, file));
  ui_testing::ImGuiHarness harness;
  harness.frame([&] { draw_lesson_panel(runner, state); });
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Waiting);
  runner.next();
  harness.frame([&] { draw_lesson_panel(runner, state); });
  EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Failed);
  EXPECT_EQ(runner.error(), "l.lua:3: broken");
}

}  // namespace
}  // namespace meshedit
