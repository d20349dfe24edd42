// A script's print when memory runs out (FailingAllocations): building the line, the host's callback, or copying the
// message of the exception the callback threw. A print that fails is the Lua error "p.lua:1: print failed: ..." that
// says memory ran out, never a C++ exception crossing the Lua frames (which Lua's C++ build turns into an error whose
// text is whatever value was on the stack); and the runtime prints again with memory to spare.
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "script/lua_runtime.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

constexpr char kPrint[] = "print('a line long enough to live on the heap', 42)";
constexpr char kLine[] = "a line long enough to live on the heap\t42";

TEST(LuaPrintOutOfMemory, APrintThatRunsOutIsALuaErrorThatSaysSo) {
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      LuaRuntime lua;
      std::vector<std::string> printed;
      printed.reserve(4);
      lua.set_print([&](const std::string& line) { printed.push_back(line); });
      std::optional<ScriptError> error;  // a copy of a runtime_error shares its message: no allocation
      bool failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          lua.run_string(kPrint, "p.lua");
        } catch (const ScriptError& e) {
          error.emplace(e);
        } catch (const std::bad_alloc&) {
          // run_string's own C++ work after Lua returned (copying the error's text) ran short: allowed.
        }
        failed = failing.failed();
      }
      if (error) {
        EXPECT_EQ(std::string(error->what()), "p.lua:1: print failed: memory ran out");
        EXPECT_TRUE(error->out_of_memory());
        EXPECT_TRUE(printed.empty());
      } else if (!failed) {
        EXPECT_EQ(printed, std::vector<std::string>{kLine});
      }
      printed.clear();
      lua.run_string(kPrint, "p.lua");  // with memory to spare
      EXPECT_EQ(printed, std::vector<std::string>{kLine});
      if (!failed || HasFailure()) break;
    }
  }
}

TEST(LuaPrintOutOfMemory, ACallbacksErrorWhoseMessageCannotBeCopiedSaysMemoryRanOut) {
  LuaRuntime lua;
  std::optional<FailingAllocations> failing;
  lua.set_print([&](const std::string&) {
    const std::runtime_error error("the console went away, with a message longer than any inline buffer");
    failing.emplace(1, Later::Succeed);  // the next allocation, copying the message, runs out
    throw error;  // the thrown copy lives in memory the C++ runtime takes with malloc, not operator new
  });
  std::optional<ScriptError> error;
  try {
    lua.run_string(kPrint, "p.lua");
  } catch (const ScriptError& e) {
    error.emplace(e);
  }
  const bool ran_out = failing && failing->failed();
  failing.reset();
  EXPECT_TRUE(ran_out);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(std::string(error->what()), "p.lua:1: print failed: memory ran out");
  EXPECT_TRUE(error->out_of_memory());

  // With memory to spare the callback's own message is the error.
  lua.set_print([](const std::string&) { throw std::runtime_error("the console went away"); });
  try {
    lua.run_string(kPrint, "p.lua");
    ADD_FAILURE() << "print did not fail";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()), "p.lua:1: print failed: the console went away");
    EXPECT_FALSE(e.out_of_memory());
  }
}

}  // namespace
}  // namespace meshedit
