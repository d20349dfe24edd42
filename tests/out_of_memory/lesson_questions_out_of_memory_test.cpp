// A step that asks (choose) and shows live text, when memory runs out at each allocation of answering it and of a
// frame's live evaluation (FailingAllocations, N = 1, 2, ...): nothing escapes, the runner is never left busy or the
// limits of a live block left in place, and with memory to spare the step asks again and takes the right answer.
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

TEST(LessonQuestionsOutOfMemory, AnsweringAndLiveTextLeaveTheRunnerReady) {
  const std::filesystem::path path = testing::scratch_dir() / "asking.lua";
  std::ofstream(path) << R"lua(step("Ask", function()
  live(function() return "selected: " .. tostring(selection()) .. ", a line long enough to allocate" end)
  local got = choose { "Which?", options = { "first", "second" }, answer = "second",
                       feedback = { first = "the first is not it, said at some length" } }
  say("chose " .. got)
end)
)lua";
  HeadlessHost host;
  for (const FailingAllocations::Later when : {FailingAllocations::Later::Succeed, FailingAllocations::Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(::testing::Message() << "allocation " << n);
      LessonRunner runner(host);
      ASSERT_TRUE(runner.load(path)) << runner.error();
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, when);
        try {
          runner.update(0.016);
          runner.deliver(LessonEvent::choice("first"));
          runner.update(0.016);
          runner.deliver(LessonEvent::choice("second"));
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      if (runner.step_state() == LessonRunner::StepState::Failed) {
        EXPECT_NE(runner.error().find("memory"), std::string::npos) << runner.error();
      }
      runner.restart_step();  // with memory to spare: asked again, from scratch
      ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Choice) << runner.error();
      EXPECT_EQ(runner.waiting_for().tries, 0);
      runner.update(0.016);  // a live block runs under the step's limits' memory, not a leftover budget
      EXPECT_EQ(runner.lives().at(0).text, "selected: nil, a line long enough to allocate");
      EXPECT_TRUE(runner.deliver(LessonEvent::choice("first")));
      EXPECT_EQ(runner.waiting_for().feedback, "the first is not it, said at some length");
      EXPECT_TRUE(runner.deliver(LessonEvent::choice("second")));
      EXPECT_EQ(runner.said(), std::vector<std::string>{"chose second"});
      if (!failed || HasFailure()) {
        EXPECT_GT(n, 5u);  // the calls above allocate (Lua's own memory aside): each of those allocations failed once
        break;
      }
    }
  }
}

}  // namespace
}  // namespace meshedit
