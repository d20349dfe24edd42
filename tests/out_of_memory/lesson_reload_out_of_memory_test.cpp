// Hot reload (ui/lesson_panel.h) when memory runs out: the instructor saves the lesson and the check that sees the new
// file reloads it with its Nth allocation failing (FailingAllocations), or the Nth and every later one, for
// N = 1, 2, ... until the reload gets through without a failure. Nothing escapes; the new lesson runs (its step, or
// the step's error that says memory ran out), or the old one goes on and says memory ran out; and a reload that ran
// out of memory is tried again at the next check, with memory to spare, without the file having to be saved again.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/failing_allocations.h"
#include "support/test_support.h"
#include "ui/lesson_panel.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::FailingAllocations;
using Later = FailingAllocations::Later;

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(LessonReloadOutOfMemory, AReloadThatRanOutIsTriedAgainAtTheNextCheck) {
  const fs::path file = testing::scratch_dir() / "hot.lua";
  const std::string before = "lesson { title = \"Before the save\" }\nstep(\"One\", function() say(\"one\") end)\n";
  const std::string after = "lesson { title = \"After the save\" }\nstep(\"One\", function() say(\"uno\") end)\n";
  HeadlessHost host;
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      write(file, before);
      LessonRunner runner(host);
      LessonPanelState state;
      ASSERT_TRUE(load_lesson(runner, state, file));
      write(file, after);
      fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          (void)reload_if_changed(runner, state, 1.0);
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      if (runner.title() != "After the save") {
        EXPECT_EQ(runner.title(), "Before the save");
        EXPECT_NE(runner.error().find("memory"), std::string::npos) << runner.error();
        // With memory to spare, at the next check.
        EXPECT_TRUE(reload_if_changed(runner, state, 1.0)) << runner.error();
      }
      EXPECT_EQ(runner.title(), "After the save");
      if (runner.step_state() == LessonRunner::StepState::Failed) {  // reloaded, its step stopped short of memory
        EXPECT_NE(runner.error().find("memory"), std::string::npos) << runner.error();
      } else {
        EXPECT_EQ(runner.said(), std::vector<std::string>{"uno"}) << runner.error();
      }
      if (!failed || HasFailure()) break;
    }
  }
}

}  // namespace
}  // namespace meshedit
