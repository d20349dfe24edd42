// `meshedit grade` end to end through the built binary: the report on stdout ending with "N passed, N
// failed", results.json (also for submissions that do not compile, hang or run out of memory while loading),
// --junit and --tap, the exit-status rules (0 graded whatever the score, 1 the grader could not grade, 2 bad
// arguments), a hostile file trying to write results.json, and a whole class with --submissions.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::grading_dir;
using testing::Outcome;
using testing::read_text;
using testing::run_meshedit;
using testing::write_text;

// dir/name/flip.lua from a fixture.
fs::path submission(const fs::path& dir, const std::string& name, const fs::path& fixture) {
  write_text(dir / name / "flip.lua", read_text(fixture));
  return dir / name;
}

std::string suite_arg(const char* relative) { return "--suite '" + (grading_dir() / relative).string() + "'"; }

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(CliGrade, GradesASubmissionAndWritesResults) {
  const fs::path dir = testing::scratch_dir();
  submission(dir, "alice", grading_dir() / "students" / "flip_correct.lua");
  const Outcome o =
      run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission alice --junit junit.xml");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  EXPECT_TRUE(ends_with(o.out, "\nScore: 10 / 10\n5 passed, 0 failed\n")) << o.out;
  const auto results = nlohmann::json::parse(read_text(dir / "results.json"));  // the default path
  EXPECT_EQ(results.at("score"), 10.0);
  EXPECT_EQ(results.at("tests").size(), 5u);
  EXPECT_EQ(results["tests"][4]["visibility"], "after_published");
  const std::string junit = read_text(dir / "junit.xml");
  EXPECT_NE(junit.find("<testsuites name=\"flip_edge\" tests=\"5\" failures=\"0\" errors=\"0\""), std::string::npos)
      << junit;
}

// --visible-only: a student's check before handing in runs the tests they see now and says what it left out.
TEST(CliGrade, AVisibleOnlyRunIsTheStudentsCheck) {
  const fs::path dir = testing::scratch_dir();
  submission(dir, "alice", grading_dir() / "students" / "flip_correct.lua");
  const Outcome o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission alice --visible-only");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("Not run here: 1 more test, 2 points, shown after the due date; 1 more test, 2 points, shown "
                       "once grades are published.\n"),
            std::string::npos)
      << o.out;
  EXPECT_TRUE(ends_with(o.out, "\nScore: 6 / 6\n3 passed, 0 failed\n")) << o.out;
  const auto results = nlohmann::json::parse(read_text(dir / "results.json"));
  EXPECT_EQ(results.at("tests").size(), 3u);
  EXPECT_EQ(results["tests"][2]["number"], "4.3");
  const Outcome many =
      run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submissions alice --visible-only");
  EXPECT_EQ(many.status, 2);
  EXPECT_NE(many.err.find("--visible-only is a student's check of one --submission"), std::string::npos) << many.err;
}

// A suite hiding a test worth points is graded, with a warning for the instructor on stderr.
TEST(CliGrade, ASuiteThatHidesPointsIsWarnedAbout) {
  const fs::path dir = testing::scratch_dir();
  submission(dir, "alice", grading_dir() / "students" / "flip_correct.lua");
  write_text(dir / "secret.lua",
             "suite{ name = 'secret', files = {'flip.lua'} }\n"
             "test{ number = '9.1', name = 'sealed', points = 3, visibility = 'hidden', run = function() end }\n");
  const Outcome o = run_meshedit(dir, "grade --suite secret.lua --submission alice");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("meshedit grade: warning: secret.lua: test 9.1 (sealed) is hidden and worth 3 points"),
            std::string::npos)
      << o.err;
  EXPECT_TRUE(ends_with(o.out, "1 passed, 0 failed\n")) << o.out;
}

TEST(CliGrade, AFailingSubmissionIsStillAGradingThatWorked) {
  const fs::path dir = testing::scratch_dir();
  submission(dir, "bob", grading_dir() / "students" / "flip_forgets_faces.lua");
  const Outcome o =
      run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission bob --results out/r.json --tap");
  EXPECT_EQ(o.status, 0) << o.err;
  // With --tap, stdout is TAP only.
  EXPECT_EQ(o.out.rfind(
                "TAP version 14\n1..5\nnot ok 1 - 4.1 flip the middle edge of two triangles, then one amid 11200\n", 0),
            0u)
      << o.out;
  EXPECT_TRUE(ends_with(o.out, "# score 2 / 10\n# 1 passed, 4 failed\n")) << o.out;
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "out" / "r.json")).at("score"), 2.0);
}

struct Broken {
  const char* fixture;
  const char* message;            // in the output of both tests
  const char* also_ok = nullptr;  // another message the output may start with instead
};

TEST(CliGrade, ResultsAreWrittenWhenTheSubmissionDoesNotLoadHangsOrRunsOutOfMemory) {
  const Broken cases[] = {
      {"syntax_error.lua", "Load error: the submission did not load: flip.lua:4: 'then' expected near 'return'"},
      {"hangs_at_load.lua", "Timed out: the submission did not load: flip.lua:3: time limit exceeded (0.5 s)"},
      // Filling the 32 MB takes ~0.1-0.25 s here; on a busy machine (fresh pages are slow on a VM) the 0.5 s clock can
      // stop it first, which contains it just as well (as in hostile_test.cpp's coroutine bomb).
      {"memory_at_load.lua", "Out of memory: the submission did not load: flip.lua:3: memory limit exceeded (32 MB)",
       "Timed out: the submission did not load: flip.lua:3: time limit exceeded (0.5 s)"},
  };
  for (const Broken& c : cases) {
    SCOPED_TRACE(c.fixture);
    const fs::path dir = testing::scratch_dir();
    submission(dir, "s", grading_dir() / "broken" / c.fixture);
    const Outcome o = run_meshedit(dir, "grade " + suite_arg("broken/broken_suite.lua") + " --submission s");
    EXPECT_EQ(o.status, 0) << o.err;
    EXPECT_TRUE(ends_with(o.out, "0 passed, 2 failed\n")) << o.out;
    const auto results = nlohmann::json::parse(read_text(dir / "results.json"));
    EXPECT_EQ(results.at("score"), 0.0);
    ASSERT_EQ(results.at("tests").size(), 2u);
    for (const auto& t : results.at("tests")) {
      EXPECT_EQ(t.at("status"), "failed");
      // The Markdown feedback: the label in bold, then the grader's words.
      const auto markdown = [](const std::string& message) {
        const size_t colon = message.find(": ");
        return "**" + message.substr(0, colon + 1) + "** " + message.substr(colon + 2);
      };
      const std::string output = t.at("output").get<std::string>();
      EXPECT_TRUE(output.rfind(markdown(c.message), 0) == 0 || (c.also_ok && output.rfind(markdown(c.also_ok), 0) == 0))
          << output;
    }
  }
  // An empty submission: every test says which file is missing.
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "empty");
  const Outcome o = run_meshedit(dir, "grade " + suite_arg("broken/broken_suite.lua") + " --submission empty");
  EXPECT_EQ(o.status, 0) << o.err;
  const auto results = nlohmann::json::parse(read_text(dir / "results.json"));
  EXPECT_EQ(results["tests"][0]["output"],
            "**Load error:** the submission did not load: the submission has no flip.lua\n");
  EXPECT_NE(results.at("output").get<std::string>().find("Missing: flip.lua"), std::string::npos);
}

TEST(CliGrade, AHostileFileCannotWriteTheResults) {
  const fs::path dir = testing::scratch_dir();
  write_text(dir / "eve" / "flip.lua", read_text(grading_dir() / "students" / "flip_correct.lua"));
  write_text(dir / "eve" / "split.lua", read_text(grading_dir() / "hostile" / "io_open_results.lua"));
  const Outcome o = run_meshedit(dir, "grade " + suite_arg("hostile/hostile_suite.lua") + " --submission eve");
  EXPECT_EQ(o.status, 0) << o.err;
  const auto results = nlohmann::json::parse(read_text(dir / "results.json"));
  EXPECT_EQ(results.at("score"), 3.0);
  EXPECT_EQ(results["tests"][1]["output"], "**Error:** split.lua:3: attempt to index a nil value (global 'io')\n");
}

TEST(CliGrade, ExitStatusSaysWhetherGradingWorked) {
  const fs::path dir = testing::scratch_dir();
  submission(dir, "s", grading_dir() / "students" / "flip_correct.lua");
  write_text(dir / "bad_suite.lua", "test{ name = 'x', run = function() end, points = 'many' }\n");
  Outcome o = run_meshedit(dir, "grade --suite bad_suite.lua --submission s");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "meshedit: the suite did not load: bad_suite.lua:1: field 'points' must be a number\n");
  EXPECT_FALSE(fs::exists(dir / "results.json"));  // no results from a grader that did not work
  o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission nowhere");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "meshedit: the submission folder nowhere does not exist\n");
  o = run_meshedit(dir, "grade --submission s");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "meshedit: grade needs --suite SUITE.lua (see meshedit --help)\n");
  o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua"));
  EXPECT_EQ(o.status, 2);
  o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission s --submissions s");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "meshedit: grade needs either --submission DIR or --submissions DIR... (see meshedit --help)\n");
  o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission s --colour");
  EXPECT_EQ(o.status, 2);
  o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") + " --submission s --results /proc/none/r.json");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "meshedit: cannot write /proc/none/r.json\n");
}

TEST(CliGrade, AWholeClassInParallel) {
  const fs::path dir = testing::scratch_dir();
  submission(dir / "class", "alice", grading_dir() / "students" / "flip_correct.lua");
  submission(dir / "class", "bob", grading_dir() / "students" / "flip_forgets_faces.lua");
  submission(dir / "class", "carol", grading_dir() / "students" / "flip_boundary.lua");
  submission(dir / "class", "dave", grading_dir() / "students" / "flip_forgets_faces.lua");
  const Outcome o = run_meshedit(dir, "grade " + suite_arg("suites/flip.lua") +
                                          " --submissions class/alice class/bob class/carol class/dave --jobs 2 --out "
                                          "marks");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out,
            "alice: 10 / 10 (5 passed, 0 failed)\n"
            "bob: 2 / 10 (1 passed, 4 failed)\n"
            "carol: 9 / 10 (4 passed, 1 failed)\n"
            "dave: 2 / 10 (1 passed, 4 failed)\n"
            "4 of 4 submissions graded; summary in marks/summary.csv, the class at a glance in marks/class.html\n");
  EXPECT_EQ(read_text(dir / "marks" / "summary.csv"),
            "submission,status,score,max_score,passed,failed,results,problem\n"
            "alice,graded,10,10,5,0,marks/alice/results.json,\n"
            "bob,graded,2,10,1,4,marks/bob/results.json,\n"
            "carol,graded,9,10,4,1,marks/carol/results.json,\n"
            "dave,graded,2,10,1,4,marks/dave/results.json,\n");
  // The class report: bob's and dave's mistake is one kind, made by both; carol's is another.
  const std::string page = read_text(dir / "marks" / "class.html");
  EXPECT_NE(page.find("2 students (50%): bob, dave"), std::string::npos) << page;
  EXPECT_NE(page.find("1 student (25%): carol"), std::string::npos) << page;
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_NE(page.find("<svg"), std::string::npos);
  const std::string csv = read_text(dir / "marks" / "class.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "student,score,max_score,4.1,4.2,4.3,4.4,4.5,problem");
  EXPECT_NE(csv.find("\ncarol,9,10,"), std::string::npos) << csv;
  const auto summary = nlohmann::json::parse(read_text(dir / "marks" / "summary.json"));
  ASSERT_EQ(summary.size(), 4u);
  EXPECT_EQ(summary[1]["submission"], "bob");
  EXPECT_EQ(summary[1]["score"], 2.0);
  EXPECT_EQ(nlohmann::json::parse(read_text(dir / "marks" / "carol" / "results.json")).at("score"), 9.0);

  // Each submission's failed tests get their pictures, as for one --submission (where EGL can draw them).
  if (o.err.find("no pictures") != std::string::npos) GTEST_SKIP() << o.err;
  EXPECT_EQ(o.err, "");
  const auto bob = nlohmann::json::parse(read_text(dir / "marks" / "bob" / "results.json"));
  EXPECT_EQ(read_text(dir / "marks" / "bob" / "pictures" / "test-4.1.png").substr(1, 3), "PNG");
  EXPECT_NE(bob["tests"][0]["output"].get<std::string>().find("](data:image/png;base64,iVBORw0KGgo"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "marks" / "alice" / "pictures"));  // nothing failed
  EXPECT_TRUE(fs::exists(dir / "marks" / "carol" / "pictures"));
}

TEST(CliGrade, TheGradescopeRunAutograderScript) {
  const fs::path dir = testing::scratch_dir();
  const fs::path solutions = testing::source_dir() / "tests" / "exercise" / "solutions";
  fs::create_directories(dir / "submission");
  for (const auto& f : fs::directory_iterator(solutions))
    fs::copy_file(f.path(), dir / "submission" / f.path().filename());
  const std::string command = "AUTOGRADER_ROOT='" + dir.string() + "' MESHEDIT='" + std::string(MESHEDIT_BINARY) +
                              "' SUITE='" + (grading_dir() / "suites" / "all.lua").string() + "' '" +
                              (grading_dir() / "gradescope" / "run_autograder").string() + "' > '" +
                              (dir / "stdout.txt").string() + "' 2>&1";
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 0) << read_text(dir / "stdout.txt");
  const auto results = nlohmann::json::parse(read_text(dir / "results" / "results.json"));
  EXPECT_EQ(results.at("score"), 56.0);  // 54 base points and the 2 of extra credit
  EXPECT_EQ(results.at("max_score"), 54.0);
  EXPECT_EQ(results.at("tests").size(), 29u);
  EXPECT_TRUE(ends_with(read_text(dir / "stdout.txt"), "29 passed, 0 failed\n"));
}

}  // namespace
}  // namespace meshedit
