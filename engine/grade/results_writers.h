// The report of a graded submission in each format it is read in: Gradescope's results.json, JUnit XML for
// CI, TAP, the readable text printed by `meshedit grade`, and the summary line.
//
// Invariants:
// - results.json follows Gradescope's spec (gradescope-autograders.readthedocs.io/en/latest/specs): top level
//   score, max_score, execution_time (whole seconds), output, visibility, stdout_visibility, tests[] with
//   number, name, score, max_score, status ("passed" / "failed"), output, visibility (and tags when set).
//   Extra credit follows Gradescope's convention of a test with max_score 0 whose score adds: its name ends in
//   "(extra credit)" and its tags hold "extra credit"; the top-level score includes it, the top-level max_score
//   is the base points only. The texts are Markdown (output_format and test_output_format "md": test_feedback.h).
//   The text is valid UTF-8 whatever the student printed (invalid bytes are replaced).
// - JUnit has no score field: each test case carries properties score and max_score; failed checks are
//   <failure>, errors, timeouts and crashes <error>.
// - TAP 14: the plan first, one "ok"/"not ok" line per test, YAML diagnostics for failures, a closing
//   "# N passed, N failed" comment; only TAP text, so it can be the whole of stdout.
// - The readable report ends with the line "N passed, N failed".
// - Files are written atomically (a temporary file in the same folder, then rename): a reader never sees
//   half a results.json.
#pragma once

#include <filesystem>
#include <string>

#include "grade/grade_types.h"

namespace meshedit {

std::string gradescope_json(const GradeReport& report);
std::string junit_xml(const GradeReport& report);
std::string tap_text(const GradeReport& report);
std::string text_report(const GradeReport& report);
std::string summary_line(const GradeReport& report);  // "3 passed, 1 failed"
// "Score: 31 / 33" (with the extra credit's note when there is some), as the readable report ends.
std::string score_line(const GradeReport& report);
// A test's points as the readable report gives them: "2/2", "0/3", "+1 of 1" (extra credit).
std::string points_text(const TestResult& test);

// Throws GradeError when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace meshedit
