// The grader's own JSON: a test run as the child sends it to the parent, and a whole graded report as
// `meshedit grade --report FILE` writes it for the window's Check my work (the readable text of each test, what a
// visible-only run left out, and each failed test's input as a case to open). Gradescope's results.json is
// results_writers.h's; this one carries what the window shows and results.json has no field for.
//
// Invariants:
// - decode(encode(x)) == x for every field; a text that is not this JSON, or misses a field, throws GradeError naming
//   the field, never gives a half-read value.
// - Student text may hold any bytes: invalid UTF-8 is replaced, never a failure to write.
// - A report starts with "format": "meshedit check report" and "version": 1; another format or a newer version is
//   refused with a sentence saying which.
#pragma once

#include <string>

#include "grade/grade_types.h"

namespace meshedit {

std::string encode_test_run(const TestRun& run);
// Throws GradeError for a malformed report.
TestRun decode_test_run(const std::string& text);

std::string encode_grade_report(const GradeReport& report);
// Throws GradeError for a text that is not a check report of this version.
GradeReport decode_grade_report(const std::string& text);

}  // namespace meshedit
