// LessonRunner when memory runs out while a lesson loads (a broken one, a working one) or a step starts
// (FailingAllocations fails the Nth allocation and every later one, for N = 1, 2, ...): whatever the call does then,
// afterwards, with memory to spare, the same lesson loads and runs its steps. The runner is never left busy
// (refusing every later load) by an exception thrown while it reported another.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "script/headless_host.h"
#include "script/lesson_runner.h"
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

}  // namespace
}  // namespace meshedit
