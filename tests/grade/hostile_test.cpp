// Every hostile submission in tests/grading/hostile/ (a correct flip.lua plus one hostile split.lua) graded
// with hostile_suite.lua: the two tests that do not call split_edge keep their full points, whatever the file
// did when it loaded or while it ran; the split test scores 0, ends the way the attack forces it to, and its
// output says what happened. Each case below is one attack a submission can make on the grader.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "grade/results_writers.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

using testing::grading_dir;
using testing::read_text;

struct HostileCase {
  const char* file;
  RunEnd end;            // how the split test ends
  const char* reported;  // a part of the split test's output
  // For an attack two limits can stop (which comes first depends on the machine's load): the other way it may end.
  RunEnd other_end = RunEnd::Completed;
  const char* other_reported = nullptr;
};

void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.file; }

class Hostile : public ::testing::TestWithParam<HostileCase> {};

TEST_P(Hostile, OtherTestsKeepTheirGradeAndTheAttackIsReported) {
  const HostileCase& c = GetParam();
  auto suite = Suite::load(grading_dir() / "hostile" / "hostile_suite.lua");
  const Submission submission =
      testing::submission_of({{"flip.lua", read_text(grading_dir() / "students" / "flip_correct.lua")},
                              {"split.lua", read_text(grading_dir() / "hostile" / c.file)}});
  const GradeReport report = grade(*suite, submission, testing::quick_options());
  ASSERT_EQ(report.tests.size(), 3u);
  const TestResult& flip = report.tests[0];
  const TestResult& split = report.tests[1];
  const TestResult& boundary = report.tests[2];
  EXPECT_TRUE(flip.passed) << flip.output;
  EXPECT_EQ(flip.score, 2.0);
  EXPECT_TRUE(boundary.passed) << boundary.output;
  EXPECT_EQ(boundary.score, 1.0);
  EXPECT_FALSE(split.passed);
  EXPECT_EQ(split.score, 0.0);
  const bool other = c.other_reported != nullptr && split.end == c.other_end;
  EXPECT_EQ(split.end, other ? c.other_end : c.end) << run_end_name(split.end) << "\n" << split.output;
  EXPECT_NE(split.output.find(other ? c.other_reported : c.reported), std::string::npos) << split.output;
  EXPECT_EQ(report.score, 3.0);
  EXPECT_EQ(report.max_score, 6.0);
  EXPECT_EQ(summary_line(report), "2 passed, 1 failed");
  // Whatever the student printed, a test's output stays small (output_kb = 4 in the suite).
  EXPECT_LT(split.output.size(), 6000u);
}

INSTANTIATE_TEST_SUITE_P(
    Attacks, Hostile,
    ::testing::Values(
        HostileCase{"os_execute.lua", RunEnd::Error, "split.lua:3: attempt to call a nil value (field 'execute')"},
        HostileCase{"io_open_results.lua", RunEnd::Error, "split.lua:3: attempt to index a nil value (global 'io')"},
        HostileCase{"require_module.lua", RunEnd::Error, "split.lua:3: attempt to call a nil value (global 'require')"},
        HostileCase{"bytecode.lua", RunEnd::Error, "split.lua:5: attempt to load a binary chunk (mode is 't')"},
        HostileCase{"string_dump.lua", RunEnd::Error, "split.lua:3: attempt to call a nil value (field 'dump')"},
        HostileCase{"debug_library.lua", RunEnd::Error, "split.lua:3: attempt to index a nil value (global 'debug')"},
        // Its load-time patches fail quietly (pcall); the suite's string methods are checked in test 1.
        HostileCase{"string_metatable.lua", RunEnd::Error, "split.lua:10: attempt to index a boolean value"},
        // Its fake `expect` lives in its own state: the real checks run and fail.
        HostileCase{"overwrite_globals.lua", RunEnd::Completed,
                    "FAILED: split e0: the reference has 5 vertices, yours 4"},
        HostileCase{"read_hidden_tests.lua", RunEnd::Error,
                    "split.lua:7: meshedit.load is hidden from your code (in the window and in grading): student code "
                    "cannot read or write files"},
        HostileCase{"os_exit.lua", RunEnd::Error, "split.lua:3: attempt to call a nil value (field 'exit')"},
        HostileCase{"pcall_loop.lua", RunEnd::Timeout, "time limit exceeded (0.5 s)"},
        HostileCase{"string_rep_bomb.lua", RunEnd::Memory, "memory limit exceeded (32 MB)"},
        // One C call that never returns: only the parent's kill stops it.
        HostileCase{"pattern_bomb.lua", RunEnd::Timeout, "stopped after 0.5 s (time limit)"},
        // The Lua stack grows until the 32 MB cap (before Lua's own "stack overflow").
        HostileCase{"deep_recursion.lua", RunEnd::Memory, "memory limit exceeded (32 MB)"},
        // Live coroutines fill the 32 MB in about 0.4 s here, close to the 0.5 s limit: on a busy machine the clock
        // can stop it first, which contains it just as well.
        HostileCase{"coroutine_bomb.lua", RunEnd::Memory, "memory limit exceeded (32 MB)", RunEnd::Timeout,
                    "time limit exceeded (0.5 s)"},
        HostileCase{"error_object.lua", RunEnd::Error, "Error: (error object is a table value)"},
        HostileCase{"print_flood.lua", RunEnd::Completed, "[output truncated: more than 4096 bytes printed]"},
        HostileCase{"gc_finalizer.lua", RunEnd::Error, "split.lua:3: __gc metamethods are not allowed in scripts"},
        HostileCase{"hostile_result.lua", RunEnd::Error, "nested more than 32 tables deep (a cycle?)"}),
    [](const ::testing::TestParamInfo<HostileCase>& param_info) {
      const std::string file = param_info.param.file;
      return file.substr(0, file.find('.'));
    });

// Every fixture in the folder is in the list above (a new attack file cannot be forgotten).
TEST(Hostile, EveryFixtureIsTested) {
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(grading_dir() / "hostile")) {
    if (entry.path().extension() == ".lua" && entry.path().filename() != "hostile_suite.lua") ++files;
  }
  EXPECT_EQ(files, 19u);
}

}  // namespace
}  // namespace meshedit
