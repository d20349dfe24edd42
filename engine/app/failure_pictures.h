// add_failure_pictures: for each failed test whose input the grader kept (grade/failing_case.h), one picture of the
// failing neighbourhood, three views side by side from the same camera: the input with the element the student's
// function was given highlighted, the reference's result, and the student's. Drawn headless (EGL, no display) by the
// renderer `meshedit render` uses, written to FOLDER/pictures/test-NUMBER.png, and put into the test's Markdown
// feedback as an embedded image (results.json carries it, so Gradescope shows it with no file beside it).
//
// Invariants:
// - Only the Markdown changes: scores, the readable text and the verdict are the grader's as they were.
// - The camera frames the element's neighbourhood (two rings around its corners in the input) in all three; the whole
//   mesh for an exercise on the whole mesh. It looks from the three-quarter view, or, for an element facing away from
//   that view, from the element's outside, so the element is never hidden behind the rest of the mesh. The element is
//   highlighted in each mesh that still has it. A student's mesh is drawn with its records as they are (a broken one as
//   the window draws it).
// - Never stops grading: when no picture can be made (no EGL here, a file that cannot be written), the return value
//   says why (for stderr) and the feedback is as it was.
// - The same report gives the same pictures byte for byte on the same machine.
#pragma once

#include <filesystem>
#include <string>

#include "grade/grade_types.h"

namespace meshedit {

// Returns "" when every picture was made, else one sentence on what was not.
std::string add_failure_pictures(GradeReport& report, const std::filesystem::path& folder);

}  // namespace meshedit
