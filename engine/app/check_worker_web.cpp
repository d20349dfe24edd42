// The page's Check my work worker's entry (web/check_worker.js calls it in its own copy of the program, started
// without main): one test of a suite run on a submission, here, as a child of `meshedit grade` runs it. The page's
// thread scores the run and makes the report (check_process_web.cpp).
//
// Invariants:
// - The suite and the submission are read afresh for every test, so no test sees what an earlier one left in the
//   suite's Lua state: each desktop test runs in a child forked from the parent as it was before any test.
// - Never throws: a suite or submission that cannot be read here is the test's error.
#include <emscripten/emscripten.h>

#include <exception>
#include <memory>
#include <new>
#include <string>

#include "grade/report_json.h"
#include "grade/submission.h"
#include "grade/suite.h"
#include "script/exception_text.h"

// Test `index` of the suite file `suite` on the submission in the folder `folder`: its TestRun as report_json's text
// (valid until the next call).
extern "C" EMSCRIPTEN_KEEPALIVE const char* meshedit_check_test(const char* suite, const char* folder, int index) {
  static std::string text;
  using meshedit::RunEnd;
  using meshedit::TestRun;
  TestRun run;
  try {
    const std::unique_ptr<meshedit::Suite> loaded = meshedit::Suite::load(suite);
    const meshedit::Submission submission = meshedit::Submission::read(folder);
    run = loaded->run_test_here(static_cast<size_t>(index), submission);
  } catch (const std::exception& e) {
    run = TestRun{};
    run.end = RunEnd::Error;
    run.error = std::string("the grader could not run this test: ") + meshedit::exception_text(e);
  }
  try {
    text = meshedit::encode_test_run(run);
  } catch (const std::bad_alloc&) {
    text.clear();  // an empty report: the page's thread calls it a crash
  }
  return text.c_str();
}
