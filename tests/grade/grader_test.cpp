// Scoring rules (score_test), the child's report format, the writers (results.json checked field by field
// against Gradescope's spec, JUnit, TAP, the text report) and grade() over child processes.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "grade/grader.h"
#include "grade/report_json.h"
#include "grade/results_writers.h"
#include "grade/submission.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

TestSpec spec(double points, bool partial = false) {
  TestSpec s;
  s.number = "1.2";
  s.name = "flip";
  s.points = points;
  s.partial = partial;
  s.visibility = "after_due_date";
  s.tags = {"flip"};
  return s;
}

TestRun run_with(std::initializer_list<bool> results, RunEnd end = RunEnd::Completed, std::string error = "") {
  TestRun r;
  int i = 0;
  for (bool passed : results) r.checks.push_back({passed, "check " + std::to_string(++i)});
  r.end = end;
  r.error = std::move(error);
  return r;
}

TEST(Scoring, AllOrNothingByDefault) {
  TestResult r = score_test(spec(2), run_with({true, true}), 0.5);
  EXPECT_EQ(r.score, 2.0);
  EXPECT_EQ(r.max_score, 2.0);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.output, "Passed: 2 checks.\n");
  EXPECT_EQ(r.failure, "");
  EXPECT_EQ(r.number, "1.2");
  EXPECT_EQ(r.visibility, "after_due_date");
  EXPECT_EQ(r.tags, std::vector<std::string>{"flip"});
  EXPECT_EQ(r.seconds, 0.5);
  r = score_test(spec(2), run_with({true, false, true}), 0);
  EXPECT_EQ(r.score, 0.0);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.output, "FAILED: check 2\n2 checks of 3 passed.\n");
  EXPECT_EQ(r.failure, "check 2");
  r = score_test(spec(1), run_with({}), 0);  // no checks, no error: passed
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.output, "Passed.\n");
}

TEST(Scoring, PartialCreditAndExplicitFractions) {
  TestResult r = score_test(spec(3, true), run_with({true, false, true}), 0);
  EXPECT_EQ(r.score, 2.0);
  EXPECT_FALSE(r.passed);
  // An error in a partial test counts as one more failed check.
  r = score_test(spec(4, true), run_with({true, true, true}, RunEnd::Error, "x.lua:3: boom"), 0);
  EXPECT_EQ(r.score, 3.0);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.output, "Error: x.lua:3: boom\n3 checks of 3 passed.\n");
  EXPECT_EQ(r.failure, "x.lua:3: boom");
  TestRun f = run_with({true, false});
  f.fraction = 0.25;
  r = score_test(spec(2), f, 0);
  EXPECT_EQ(r.score, 0.5);
  f.fraction = 1.0;
  r = score_test(spec(2), f, 0);
  EXPECT_EQ(r.score, 2.0);
  EXPECT_FALSE(r.passed);  // a failed check keeps the test from passing
  r = score_test(spec(1, true), run_with({true, false, false}), 0);
  EXPECT_EQ(r.score, 0.333333);
}

TEST(Scoring, OnlyTheFirstEightFailuresAreListed) {
  const TestResult r =
      score_test(spec(1), run_with({false, false, false, false, false, false, false, false, false, false, true}), 0);
  EXPECT_EQ(r.output,
            "FAILED: check 1\nFAILED: check 2\nFAILED: check 3\nFAILED: check 4\nFAILED: check 5\nFAILED: check 6\n"
            "FAILED: check 7\nFAILED: check 8\n... and 2 more failed checks\n1 check of 11 passed.\n");
}

TEST(Scoring, StoppedTestsScoreZeroAndSayWhy) {
  const TestResult r =
      score_test(spec(5), run_with({true}, RunEnd::Timeout, "flip.lua:9: time limit exceeded (2 s)"), 2);
  EXPECT_EQ(r.score, 0.0);
  EXPECT_EQ(r.end, RunEnd::Timeout);
  EXPECT_EQ(r.output, "Timed out: flip.lua:9: time limit exceeded (2 s)\n1 check of 1 passed.\n");
  TestRun printed = run_with({false});
  printed.output = "debug 1\n";
  EXPECT_EQ(score_test(spec(1), printed, 0).output,
            "FAILED: check 1\n0 checks of 1 passed.\n\nYour code printed:\ndebug 1\n");
}

TEST(Scoring, ReportsTravelAsJson) {
  TestRun run = run_with({true, false}, RunEnd::Memory, "memory limit exceeded (32 MB)");
  run.fraction = 0.5;
  run.output = std::string("bytes \xff\xfe not UTF-8\n");
  run.output_truncated = true;
  const TestRun back = decode_test_run(encode_test_run(run));
  ASSERT_EQ(back.checks.size(), 2u);
  EXPECT_TRUE(back.checks[0].passed);
  EXPECT_EQ(back.checks[1].message, "check 2");
  EXPECT_EQ(back.fraction, 0.5);
  EXPECT_EQ(back.end, RunEnd::Memory);
  EXPECT_EQ(back.error, "memory limit exceeded (32 MB)");
  EXPECT_EQ(back.output, "bytes \xEF\xBF\xBD\xEF\xBF\xBD not UTF-8\n");  // invalid bytes replaced
  EXPECT_TRUE(back.output_truncated);
  EXPECT_THROW(decode_test_run("{\"checks\": []}"), GradeError);
  EXPECT_THROW(decode_test_run("not json"), GradeError);
}

GradeReport sample_report() {
  GradeReport report;
  report.suite_name = "flip";
  report.output = "Suite flip: 3 tests.\n";
  report.execution_time = 2.2;
  report.tests.push_back(score_test(spec(2), run_with({true}), 0.1));
  TestSpec hidden = spec(3);
  hidden.number = "2";
  hidden.name = "hidden <one> & \"quoted\" # not a directive";
  hidden.visibility = "hidden";
  hidden.tags.clear();
  report.tests.push_back(score_test(hidden, run_with({false}), 0.2));
  TestSpec third = spec(1);
  third.number = "3";
  report.tests.push_back(score_test(third, run_with({}, RunEnd::Crash, "killed by signal 9"), 0.3));
  report.score = 2;
  report.max_score = 6;
  return report;
}

TEST(Results, GradescopeJsonHasTheSpecsFieldsOnly) {
  const nlohmann::json j = nlohmann::json::parse(gradescope_json(sample_report()));
  // Gradescope's top-level keys (gradescope-autograders.readthedocs.io/en/latest/specs), plus max_score.
  const std::set<std::string> top = {"score",
                                     "max_score",
                                     "execution_time",
                                     "output",
                                     "output_format",
                                     "test_output_format",
                                     "test_name_format",
                                     "visibility",
                                     "stdout_visibility",
                                     "extra_data",
                                     "tests",
                                     "leaderboard"};
  for (const auto& [key, value] : j.items()) EXPECT_TRUE(top.count(key)) << key;
  EXPECT_EQ(j.at("score"), 2.0);
  EXPECT_EQ(j.at("max_score"), 6.0);
  EXPECT_TRUE(j.at("execution_time").is_number_integer());
  EXPECT_EQ(j.at("execution_time"), 3);
  EXPECT_EQ(j.at("output"), "Suite flip: 3 tests.\n");
  EXPECT_EQ(j.at("output_format"), "md");
  EXPECT_EQ(j.at("test_output_format"), "md");
  EXPECT_EQ(j.at("visibility"), "visible");
  EXPECT_EQ(j.at("stdout_visibility"), "hidden");
  const std::set<std::string> test_keys = {"score",  "max_score",     "status", "name",       "name_format", "number",
                                           "output", "output_format", "tags",   "visibility", "extra_data"};
  ASSERT_EQ(j.at("tests").size(), 3u);
  for (const auto& t : j.at("tests")) {
    for (const auto& [key, value] : t.items()) EXPECT_TRUE(test_keys.count(key)) << key;
    for (const char* needed : {"number", "name", "score", "max_score", "status", "output", "visibility"}) {
      EXPECT_TRUE(t.contains(needed)) << needed;
    }
    EXPECT_TRUE(t.at("status") == "passed" || t.at("status") == "failed");
  }
  EXPECT_EQ(j["tests"][0]["number"], "1.2");
  EXPECT_EQ(j["tests"][0]["status"], "passed");
  EXPECT_EQ(j["tests"][0]["score"], 2.0);
  EXPECT_EQ(j["tests"][0]["tags"], nlohmann::json::array({"flip"}));
  EXPECT_EQ(j["tests"][1]["name"], "hidden <one> & \"quoted\" # not a directive");
  EXPECT_EQ(j["tests"][1]["visibility"], "hidden");
  EXPECT_EQ(j["tests"][1]["status"], "failed");
  EXPECT_FALSE(j["tests"][1].contains("tags"));
  EXPECT_EQ(j["tests"][2]["output"], "**Crashed:** killed by signal 9\n");
}

TEST(Results, JunitTapAndText) {
  const GradeReport report = sample_report();
  const std::string xml = junit_xml(report);
  EXPECT_NE(xml.find("<testsuites name=\"flip\" tests=\"3\" failures=\"1\" errors=\"1\" time=\"2.2\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase classname=\"flip\" name=\"2 hidden &lt;one&gt; &amp; &quot;quoted&quot; # not a "
                     "directive\" time=\"0.2\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"check 1\" type=\"completed\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<error message=\"killed by signal 9\" type=\"crash\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<property name=\"score\" value=\"2\"/>"), std::string::npos) << xml;
  EXPECT_EQ(tap_text(report),
            "TAP version 14\n1..3\n"
            "ok 1 - 1.2 flip\n"
            "not ok 2 - 2 hidden <one> & \"quoted\"   not a directive\n"
            "  ---\n  message: \"check 1\"\n  severity: fail\n  score: 0\n  max_score: 3\n  ...\n"
            "not ok 3 - 3 flip\n"
            "  ---\n  message: \"killed by signal 9\"\n  severity: error\n  score: 0\n  max_score: 1\n  ...\n"
            "# score 2 / 6\n# 1 passed, 2 failed\n");
  const std::string text = text_report(report);
  EXPECT_NE(text.find("PASS 1.2 flip  2/2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("FAIL 3 flip  0/1\n    Crashed: killed by signal 9\n"), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 32), "Score: 2 / 6\n1 passed, 2 failed\n") << text;
  EXPECT_EQ(summary_line(report), "1 passed, 2 failed");
}

TEST(Results, FilesAreWrittenWhole) {
  const auto dir = testing::scratch_dir();
  write_file_atomically(dir / "out" / "results.json", "{}\n");
  EXPECT_EQ(testing::read_text(dir / "out" / "results.json"), "{}\n");
  write_file_atomically(dir / "out" / "results.json", "{\"score\": 1}\n");
  EXPECT_EQ(testing::read_text(dir / "out" / "results.json"), "{\"score\": 1}\n");
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "out")) ++files;
  EXPECT_EQ(files, 1u);  // no temporary left behind
  EXPECT_THROW(write_file_atomically("/proc/no/such/results.json", "{}"), GradeError);
}

TEST(Grade, EachTestRunsInItsOwnChildAndTheReportAddsUp) {
  auto suite = testing::suite_of(
      "suite{ name = 'demo', files = {'a.lua', 'b.lua'}, time_limit = 1 }\n"
      "test{ name = 'adds', points = 2, run = function(s, expect) expect.equal(s.add(2, 2), 4) end }\n"
      "test{ name = 'global left by the previous test', run = function(s, expect)\n"
      "  expect.is_nil(LEAK, 'the suite state is fresh') LEAK = 1 end }\n"
      "test{ name = 'again', run = function(s, expect) expect.is_nil(LEAK, 'still fresh') end }\n");
  const Submission submission = testing::submission_of({{"a.lua", "function add(x, y) return x + y end"}});
  std::vector<std::string> seen;
  GradeOptions options = testing::quick_options();
  options.on_test = [&](const TestResult& r) { seen.push_back(r.name); };
  const GradeReport report = grade(*suite, submission, options);
  EXPECT_EQ(report.suite_name, "demo");
  EXPECT_EQ(seen, (std::vector<std::string>{"adds", "global left by the previous test", "again"}));
  // b.lua is missing: every test needs it (suite files), so every test fails to load.
  for (const auto& t : report.tests) {
    EXPECT_EQ(t.end, RunEnd::LoadError);
    EXPECT_EQ(t.output, "Load error: the submission did not load: the submission has no b.lua\n");
  }
  EXPECT_EQ(report.output,
            "Suite demo: 3 tests.\nFiles submitted: a.lua.\nMissing: b.lua (the tests that need it fail).\n");
  const GradeReport fixed =
      grade(*suite, testing::submission_of({{"a.lua", "function add(x, y) return x + y end"}, {"b.lua", ""}}),
            testing::quick_options());
  EXPECT_EQ(summary_line(fixed), "3 passed, 0 failed");
  EXPECT_EQ(fixed.score, 4.0);
  EXPECT_EQ(fixed.max_score, 4.0);
}

// Files a Windows editor may save: a UTF-8 file with a byte order mark loads (as lua.c loads it), a UTF-16 file fails
// to load with its error and a sentence that says what it is and what to do, in every test's feedback.
TEST(Grade, AFileThatIsNotUTF8SaysSoAndOneWithAByteOrderMarkLoads) {
  const auto dir = testing::scratch_dir();
  std::ofstream(dir / "a.lua", std::ios::binary) << "\xEF\xBB\xBF"
                                                 << "function add(x, y) return x + y end\n";
  const std::string utf16("\xFF\xFEr\0e\0t\0u\0r\0n\0 \0{\0}\0\n\0", 22);
  std::ofstream(dir / "b.lua", std::ios::binary) << utf16;
  auto suite = testing::suite_of(
      "suite{ name = 'demo', time_limit = 1 }\n"
      "test{ name = 'adds', files = {'a.lua'}, run = function(s, expect) expect.equal(s.add(2, 2), 4) end }\n"
      "test{ name = 'b', files = {'b.lua'}, run = function(s, expect) expect.truthy(true) end }\n");
  const GradeReport report = grade(*suite, Submission::read(dir), testing::quick_options());
  ASSERT_EQ(report.tests.size(), 2u);
  EXPECT_TRUE(report.tests[0].passed) << report.tests[0].output;
  EXPECT_EQ(report.tests[1].end, RunEnd::LoadError);
  EXPECT_NE(report.tests[1].output.find(
                "b.lua:1: unexpected symbol near '<\\255>' (b.lua is UTF-16 text, which Lua cannot read: save it as "
                "UTF-8)"),
            std::string::npos)
      << report.tests[1].output;
}

// A student's check runs the tests they can see now, and says what it left out and when it will be shown; the totals
// are the visible tests'.
TEST(Grade, AVisibleOnlyRunLeavesOutTheTestsStudentsCannotSeeYet) {
  auto suite = testing::suite_of(
      "suite{ name = 'demo', files = {'a.lua'}, time_limit = 1 }\n"
      "test{ name = 'seen', points = 2, run = function(s, expect) expect.equal(s.add(2, 2), 4) end }\n"
      "test{ name = 'after due', points = 3, visibility = 'after_due_date', run = function() end }\n"
      "test{ name = 'after due too', points = 1, visibility = 'after_due_date', run = function() end }\n"
      "test{ name = 'published', points = 1, visibility = 'after_published', run = function() end }\n"
      "test{ name = 'never', points = 0, visibility = 'hidden', run = function() end }\n");
  const Submission submission = testing::submission_of({{"a.lua", "function add(x, y) return x + y end"}});
  GradeOptions options = testing::quick_options();
  options.visible_only = true;
  const GradeReport report = grade(*suite, submission, options);
  ASSERT_EQ(report.tests.size(), 1u);
  EXPECT_EQ(report.tests[0].name, "seen");
  EXPECT_EQ(report.score, 2.0);
  EXPECT_EQ(report.max_score, 2.0);
  ASSERT_EQ(report.not_shown.size(), 3u);
  EXPECT_EQ(report.not_shown[0].visibility, "hidden");
  EXPECT_EQ(report.not_shown[1].visibility, "after_due_date");
  EXPECT_EQ(report.not_shown[1].tests, 2u);
  EXPECT_EQ(report.not_shown[1].points, 4.0);
  EXPECT_EQ(report.not_shown[2].tests, 1u);
  EXPECT_EQ(report.output,
            "Suite demo: 5 tests.\nFiles submitted: a.lua.\nNot run here: 1 more test, 0 points, never shown to "
            "students; 2 more tests, 4 points, shown after the due date; 1 more test, 1 point, shown once grades are "
            "published.\n");
  // The full run runs all five and leaves nothing out.
  const GradeReport full = grade(*suite, submission, testing::quick_options());
  EXPECT_EQ(full.tests.size(), 5u);
  EXPECT_TRUE(full.not_shown.empty());
  EXPECT_EQ(full.max_score, 7.0);
  EXPECT_EQ(not_shown_sentence(full.not_shown), "");
}

// A hidden test worth points hides the student's total on Gradescope: the instructor hears of each one.
TEST(Grade, HiddenTestsWorthPointsAreWarnedAbout) {
  auto suite = testing::suite_of(
      "suite{ name = 'demo', files = {'a.lua'} }\n"
      "test{ number = '1.1', name = 'secret', points = 2, visibility = 'hidden', run = function() end }\n"
      "test{ number = '1.2', name = 'free', points = 0, visibility = 'hidden', run = function() end }\n"
      "test{ number = '1.3', name = 'later', points = 1, visibility = 'after_published', run = function() end }\n");
  EXPECT_EQ(suite_warnings(*suite),
            std::vector<std::string>{"test 1.1 (secret) is hidden and worth 2 points: on Gradescope a hidden test "
                                     "hides the student's total score too; give it visibility after_due_date or "
                                     "after_published (hidden is for tests worth 0 points)"});
}

// The shipped suites hide no points, so students always see their total.
TEST(Grade, TheShippedSuitesHideNoPoints) {
  for (const char* name :
       {"all.lua", "curve.lua", "patch.lua", "normals.lua", "flip.lua", "split.lua", "upsample.lua"}) {
    const auto suite = Suite::load(testing::grading_dir() / "suites" / name);
    EXPECT_EQ(suite_warnings(*suite), std::vector<std::string>{}) << name;
    size_t visible = 0;
    for (const TestSpec& spec : suite->tests()) visible += spec.visibility == "visible" ? 1 : 0;
    EXPECT_GT(visible, 0u) << name << ": a student's check would run nothing";
  }
}

}  // namespace
}  // namespace meshedit
