// TestFeedback: what a graded test tells the student, in its parts, and the two ways it is written: the plain text of
// the readable report, JUnit and TAP, and the Markdown Gradescope shows (results.json's output_format "md").
//
// Invariants:
// - Both say the same words in the same order: why the run stopped and the window's hint for it, the first failed
//   checks, how many more failed, the tally, the extra-credit line, what the student's code printed.
// - The Markdown puts each failed check's headline (its context and first difference, the likely mistake: the
//   diagnosis the window gives) first and folds the further differences below it (<details>); element ids and their
//   fields (h12, v3.halfedge) and what a message quotes in backticks are code; everything else is escaped, so
//   nothing a message or a student prints turns into Markdown or HTML. What the student's code printed is a fenced
//   block longer than any run of backticks in it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "grade/grade_types.h"

namespace meshedit {

struct TestFeedback {
  std::string stopped;                // "Timed out: ..." when the run did not complete, else ""
  std::string hint;                   // the window's words for an unfinished run, or ""
  std::vector<CheckResult> failures;  // the first failed checks
  size_t more_failures = 0;           // the failed checks not listed
  std::string tally;                  // "Passed: 2 checks.", "1 check of 2 passed." or ""
  std::string extra_credit;           // "Extra credit: 0 of 1 point, added on top of the base score." or ""
  std::string printed;                // what the student's code printed, ending in a newline, or ""
};

std::string feedback_text(const TestFeedback& feedback);
std::string feedback_markdown(const TestFeedback& feedback);

// `text` as Markdown: each line a paragraph, escaped, element ids as code.
std::string markdown_paragraphs(const std::string& text);

}  // namespace meshedit
