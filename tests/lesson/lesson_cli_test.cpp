// `meshedit lesson` end to end: the built binary runs the welcome lesson headless with its answers file
// (exit 0, "5 steps passed"), fails a lesson whose wait has no answer with file:line and the step on stderr
// (exit 1), and refuses to run without --headless (exit 2). Skips when the binary has not been built.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/test_support.h"

namespace meshedit {
namespace {

struct Outcome {
  int status = -1;
  std::string out, err;
};

// Runs meshedit in `dir` (the test's scratch_dir()).
Outcome run_meshedit(const std::filesystem::path& dir, const std::string& arguments) {
  const auto out = dir / "lesson_stdout.txt", err = dir / "lesson_stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(MESHEDIT_BINARY) + "' " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = testing::read_text(out);
  o.err = testing::read_text(err);
  return o;
}

TEST(CliLesson, TheWelcomeLessonPassesHeadlessWithItsAnswers) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto source = testing::source_dir();
  const auto lesson = source / "lessons" / "welcome.lua";
  const auto answers = source / "tests" / "lesson" / "lessons" / "welcome_answers.lua";
  const Outcome o = run_meshedit(testing::scratch_dir(),
                                 "lesson '" + lesson.string() + "' --headless --answers '" + answers.string() + "'");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  EXPECT_EQ(o.out.rfind("Welcome to MeshEdit (welcome.lua, 5 steps)\n", 0), 0u) << o.out;
  EXPECT_NE(o.out.find("\nstep 5/5: Keys for the parts ahead\n"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("  > key N\n"), std::string::npos) << o.out;
  ASSERT_GE(o.out.size(), 16u);
  EXPECT_EQ(o.out.substr(o.out.size() - 16), "\n5 steps passed\n");
}

TEST(CliLesson, AWaitWithoutAnswerExitsOneNamingFileLineAndStep) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto dir = testing::scratch_dir();
  std::ofstream(dir / "lesson.lua") << "step('Look', function() say('A **cube**.') end)\n"
                                       "step('Flip it', function()\n"
                                       "  wait_for { key = 'F' }\n"
                                       "end)\n";
  const Outcome o = run_meshedit(dir, "lesson lesson.lua --headless");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "meshedit: lesson.lua:3: step 2 'Flip it': waiting for key F (no scripted answer)\n");
  EXPECT_EQ(o.out,
            "lesson (lesson.lua, 2 steps)\n\nstep 1/2: Look\n  A cube.\n  done\n\nstep 2/2: Flip it\n\n"
            "1 of 2 steps passed\n");
}

TEST(CliLesson, TheAskingDemoNamesEachMistakeAndAWrongExpectationExitsOne) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto lessons = testing::source_dir() / "tests" / "lesson" / "lessons";
  const auto dir = testing::scratch_dir();
  const Outcome o = run_meshedit(dir, "lesson '" + (lessons / "asking_demo.lua").string() + "' --headless --answers '" +
                                          (lessons / "asking_demo_answers.lua").string() + "'");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  EXPECT_NE(o.out.find("  > choose h6: wrong: h6 is h0's twin on the boundary: it is in no face, and h1 keeps its "
                       "face.\n"),
            std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("  > answer 1/8: wrong: 0.125 is B0(0.5) or B3(0.5): an end point's weight.\n"),
            std::string::npos)
      << o.out;
  EXPECT_EQ(o.out.substr(o.out.size() - 16), "\n4 steps passed\n");

  // An answers file that expects a mistake the lesson does not name fails the run, naming the question's line.
  std::ofstream(dir / "wrong.lua") << "return { ['Choose'] = { {choose = 'h6', feedback = 'before the flip'} } }\n";
  const Outcome wrong =
      run_meshedit(dir, "lesson '" + (lessons / "asking_demo.lua").string() + "' --headless --answers wrong.lua");
  EXPECT_EQ(wrong.status, 1);
  EXPECT_EQ(
      wrong.err,
      "meshedit: asking_demo.lua:15: step 1 'Choose': answer choose = \"h6\" should be judged wrong with "
      "feedback containing 'before the flip', but its feedback was 'h6 is h0's twin on the boundary: it is in no face, "
      "and h1 keeps its face.'\n");
}

TEST(CliLesson, WithoutHeadlessItPointsToTheWindow) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const Outcome o = run_meshedit(testing::scratch_dir(), "lesson welcome.lua");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err,
            "meshedit: lesson runs with --headless here; open a lesson in the window with: meshedit welcome.lua "
            "(see meshedit --help)\n");
  const Outcome none = run_meshedit(testing::scratch_dir(), "lesson --headless");
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(none.err,
            "meshedit: lesson needs one file: meshedit lesson FILE.lua --headless [--answers ANSWERS.lua] "
            "[--student DIR] (see meshedit --help)\n");
}

}  // namespace
}  // namespace meshedit
