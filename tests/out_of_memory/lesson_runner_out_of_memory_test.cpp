// LessonRunner when memory runs out while a lesson loads (a broken one, a working one) or a step starts
// (FailingAllocations fails the Nth allocation and every later one, for N = 1, 2, ...): whatever the call does then,
// afterwards, with memory to spare, the same lesson loads and runs its steps. The runner is never left busy
// (refusing every later load) by an exception thrown while it reported another. A load or a reload while a lesson
// runs is whole or nothing, and nothing escapes it.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/failing_allocations.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;

TEST(LessonRunnerOutOfMemory, ALoadThatRanOutLeavesTheRunnerReady) {
  const std::filesystem::path dir = testing::scratch_dir();
  const std::filesystem::path path = dir / "short_of_memory.lua";
  std::ofstream(path) << "lesson { title = \"Memory\" }\n"
                         "step(\"One\", function() say(\"first step, with a long enough sentence\") end)\n"
                         "step(\"Two\", function() say(\"second\") end)\n";
  // A lesson that fails as it loads: its error's long message is copied as the runner reports it, and that copy
  // may be what runs out.
  const std::filesystem::path broken = dir / "broken_on_purpose.lua";
  std::ofstream(broken) << "error(\"this lesson stops on purpose, with a message longer than any inline buffer\")\n";
  const std::vector<std::filesystem::path> lessons = {broken, path};  // made here: nothing may allocate below but
                                                                      // the calls under test
  HeadlessHost host;
  LessonRunner runner(host);
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    bool failed = false;
    {
      const FailingAllocations failing(n, FailingAllocations::Later::Fail);
      for (const std::filesystem::path& lesson : lessons) {
        try {
          (void)runner.load(lesson);
          runner.next();
        } catch (const std::exception&) {
          // What escapes here is the window's frame guard's to report; the runner must still work below.
        }
      }
      failed = failing.failed();
    }
    ASSERT_TRUE(runner.load(path)) << runner.error();
    EXPECT_EQ(runner.title(), "Memory");
    EXPECT_EQ(runner.said(), (std::vector<std::string>{"first step, with a long enough sentence"}));
    runner.next();
    EXPECT_EQ(runner.said(), (std::vector<std::string>{"second"}));
    if (!failed || HasFailure()) break;
  }
}

// A load while a lesson runs: the new lesson runs (it is its path, title and first step), or the earlier one goes on
// at its step, as it was, with an error that says memory ran out; nothing escapes. Reloading works the same way.
TEST(LessonRunnerOutOfMemory, ALoadIsWholeOrNothing) {
  const std::filesystem::path dir = testing::scratch_dir();
  const std::filesystem::path earlier = dir / "earlier.lua";
  std::ofstream(earlier) << "lesson { title = \"An earlier lesson\" }\n"
                            "step(\"One\", function() say(\"one\") end)\n"
                            "step(\"Two\", function() say(\"the earlier lesson's second step\") end)\n";
  const std::filesystem::path later = dir / "later_lesson.lua";
  std::ofstream(later) << "lesson { title = \"A lesson loaded later\" }\n"
                          "step(\"First\", function() say(\"the later lesson's first step, a long sentence\") end)\n";
  const std::vector<std::string> earlier_said = {"the earlier lesson's second step"};
  const std::vector<std::string> later_said = {"the later lesson's first step, a long sentence"};
  HeadlessHost host;
  for (const bool reload : {false, true}) {
    for (const FailingAllocations::Later when : {FailingAllocations::Later::Succeed, FailingAllocations::Later::Fail}) {
      for (size_t n = 1;; ++n) {
        SCOPED_TRACE(::testing::Message() << "reload " << reload << ", allocation " << n);
        LessonRunner runner(host);
        ASSERT_TRUE(runner.load(earlier));
        runner.next();
        ASSERT_EQ(runner.said(), earlier_said);
        const std::filesystem::path& asked = reload ? earlier : later;
        bool loaded = false, escaped = false, failed = false;
        {
          const FailingAllocations failing(n, when);
          try {
            loaded = reload ? runner.reload() : runner.load(later);
          } catch (...) {
            escaped = true;
          }
          failed = failing.failed();
        }
        EXPECT_FALSE(escaped);
        // The file asked for is the one hot reload watches, unless memory ran out copying its name.
        EXPECT_TRUE(runner.path() == asked || (!loaded && runner.path() == earlier)) << runner.path();
        if (loaded && !reload) {
          EXPECT_EQ(runner.title(), "A lesson loaded later");
          EXPECT_EQ(runner.current_step(), 0u);
        } else {
          EXPECT_EQ(runner.title(), "An earlier lesson");
          EXPECT_EQ(runner.current_step(), 1u);
        }
        if (!loaded) {
          EXPECT_NE(runner.error().find("memory"), std::string::npos) << runner.error();
          EXPECT_EQ(runner.said(), earlier_said);
          EXPECT_EQ(runner.step_state(), LessonRunner::StepState::Finished);
        } else if (runner.step_state() == LessonRunner::StepState::Failed) {
          EXPECT_NE(runner.error().find("memory"), std::string::npos) << runner.error();
        } else {
          EXPECT_TRUE(runner.error().empty()) << runner.error();
          EXPECT_EQ(runner.said(), reload ? earlier_said : later_said);
        }
        if (!failed || HasFailure()) break;
      }
    }
  }
}

}  // namespace
}  // namespace meshedit
