// A test's feedback in its two forms (test_feedback.h): the text the readable report prints, and the Markdown
// results.json carries: the headline first and the other differences folded, ids as code, the rest escaped, what the
// student printed fenced whatever it holds.
#include <gtest/gtest.h>

#include <string>

#include "grade/grader.h"
#include "grade/test_feedback.h"

namespace meshedit {
namespace {

TestFeedback failed_split() {
  TestFeedback f;
  const std::string headline = "split_edge(e2) of a 1x1 grid: h12.face is f0, but h12 is in f2's next-cycle";
  f.failures.push_back({false, headline + "; v4 at (0.5, 0.5, 0) has no match; ... (11 in all)", headline.size()});
  f.failures.push_back({false, "e3 <b>bold</b> *star* _under_ [link](x) #1 | a & b", 0});
  f.more_failures = 2;
  f.tally = "1 check of 5 passed.";
  f.printed = "debug ``` fence\n";
  return f;
}

TEST(TestFeedback, TheTextIsTheReportsWords) {
  EXPECT_EQ(feedback_text(failed_split()),
            "FAILED: split_edge(e2) of a 1x1 grid: h12.face is f0, but h12 is in f2's next-cycle; v4 at (0.5, 0.5, 0) "
            "has no match; ... (11 in all)\n"
            "FAILED: e3 <b>bold</b> *star* _under_ [link](x) #1 | a & b\n"
            "... and 2 more failed checks\n"
            "1 check of 5 passed.\n"
            "\nYour code printed:\ndebug ``` fence\n");
}

TEST(TestFeedback, TheMarkdownPutsTheHeadlineFirstAndFoldsTheRest) {
  EXPECT_EQ(feedback_markdown(failed_split()),
            "**Failed:**\n\n"
            "- split\\_edge(`e2`) of a 1x1 grid: `h12.face` is `f0`, but `h12` is in `f2`'s next-cycle\n"
            "\n  <details><summary>the other differences</summary>\n\n"
            "  `v4` at (0.5, 0.5, 0) has no match; ... (11 in all)\n\n  </details>\n"
            "- `e3` \\<b\\>bold\\</b\\> \\*star\\* \\_under\\_ \\[link\\](x) \\#1 \\| a \\& b\n"
            "- ... and 2 more failed checks\n\n"
            "1 check of 5 passed.\n\n"
            "Your code printed:\n\n"
            "````text\ndebug ``` fence\n````\n");
}

TEST(TestFeedback, AStoppedRunLeadsWithWhyAndKeepsQuotedCode) {
  TestFeedback f;
  f.stopped = "Timed out: flip.lua:3: time limit exceeded (0.5 s)";
  f.hint = "a walk like `repeat h = h.twin.next until h == start` never ends when a pointer is wrong";
  EXPECT_EQ(feedback_text(f), f.stopped + "\n" + f.hint + "\n");
  EXPECT_EQ(feedback_markdown(f),
            "**Timed out:** flip.lua:3: time limit exceeded (0.5 s)\n\n"
            "a walk like `repeat h = h.twin.next until h == start` never ends when a pointer is wrong\n");
}

// score_test writes both forms from one feedback: the same words.
TEST(TestFeedback, ScoringWritesBothForms) {
  TestSpec spec;
  spec.number = "4.1";
  spec.name = "flip";
  spec.points = 2;
  TestRun run;
  run.checks = {{true, "e1 flipped", 0}, {false, "flip_edge(e0): v0.halfedge is h0, but h0 leaves v6", 0}};
  run.output = "hello";
  run.output_truncated = true;
  const TestResult r = score_test(spec, run, 0.1);
  EXPECT_EQ(r.output,
            "FAILED: flip_edge(e0): v0.halfedge is h0, but h0 leaves v6\n1 check of 2 passed.\n\nYour code printed:\n"
            "hello\n");
  EXPECT_EQ(
      r.output_markdown,
      "**Failed:**\n\n- flip\\_edge(`e0`): `v0.halfedge` is `h0`, but `h0` leaves `v6`\n\n1 check of 2 passed.\n\n"
      "Your code printed:\n\n```text\nhello\n```\n");
}

TEST(TestFeedback, TopLevelTextBecomesParagraphs) {
  EXPECT_EQ(markdown_paragraphs("Suite flip: 3 tests.\nMissing: flip.lua (the tests that need it fail).\n"),
            "Suite flip: 3 tests.\n\nMissing: flip.lua (the tests that need it fail).\n");
  EXPECT_EQ(markdown_paragraphs(""), "");
}

}  // namespace
}  // namespace meshedit
