// The entries the page's Web Worker calls (web/student_code_worker.js, in its own copy of the program, started without
// main): one test of a suite run on a submission, as a child of `meshedit grade` runs it, for Check my work (the
// page's thread scores the run and makes the report: check_process_web.cpp); and one call of the student's code, for
// Run mine and a lesson's your_turn (the page's side: document/student_call_work_web.cpp); and the write-up of the
// student's files, for File > Write-up (the page's side: writeup_room_web.cpp).
//
// Invariants:
// - The suite and the submission are read afresh for every test, so no test sees what an earlier one left in the
//   suite's Lua state: each desktop test runs in a child forked from the parent as it was before any test.
// - A student call loads its files afresh into a fresh StudentCode, as a your_turn on the desktop does; the scripted
//   exercises the page knows (scripts/exercises) are registered before the first call, so the call's name is found.
// - Never throws: a suite, submission or call that cannot be read here is the test's or the call's error.
#include <emscripten/emscripten.h>

#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "core/translation.h"
#include "document/student_file.h"
#include "exercise/exercise_registry.h"
#include "exercise/student_call_text.h"
#include "grade/report_json.h"
#include "grade/submission.h"
#include "grade/suite.h"
#include "script/exception_text.h"
#include "writeup/writeup_text.h"

// Test `index` of the suite file `suite` on the submission in the folder `folder`, its feedback in `language` (the
// page's: "en", "zh"): its TestRun as report_json's text (valid until the next call).
extern "C" EMSCRIPTEN_KEEPALIVE const char* meshedit_check_test(const char* suite, const char* folder, int index,
                                                                const char* language) {
  static std::string text;
  using meshedit::RunEnd;
  using meshedit::TestRun;
  TestRun run;
  try {
    meshedit::set_text_language(meshedit::language_by_code(language).value_or(meshedit::Language::English));
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

namespace {

std::vector<uint8_t>& call_bytes() {
  static std::vector<uint8_t> bytes;
  return bytes;
}

}  // namespace

// Room for a call of `size` bytes, which the worker writes there before meshedit_student_call.
extern "C" EMSCRIPTEN_KEEPALIVE uint8_t* meshedit_student_call_room(int size) {
  try {
    call_bytes().assign(static_cast<size_t>(size), 0);
  } catch (const std::bad_alloc&) {
    call_bytes().clear();
  }
  return call_bytes().data();
}

// Runs the call in the room and leaves its result's bytes there: returns where they start (their size:
// meshedit_student_call_size), or null when memory ran out even for an error.
extern "C" EMSCRIPTEN_KEEPALIVE const uint8_t* meshedit_student_call() {
  meshedit::StudentCallResult result;
  try {
    static const bool registered = [] {
      meshedit::exercise_registry().load_folder(meshedit::default_exercise_folder());  // its errors: the page says them
      return true;
    }();
    (void)registered;
    const meshedit::StudentCall call = meshedit::decode_student_call(call_bytes());
    result = meshedit::run_student_call(call);
  } catch (const std::bad_alloc&) {
    result = meshedit::StudentCallResult{};
    result.out_of_memory = true;
  } catch (const std::exception& e) {
    result.thrown = std::string("the page's worker could not read the call: ") + e.what();
  }
  try {
    call_bytes() = meshedit::encode_student_call_result(result);
  } catch (const std::bad_alloc&) {
    call_bytes().clear();
    return nullptr;
  }
  return call_bytes().data();
}

extern "C" EMSCRIPTEN_KEEPALIVE int meshedit_student_call_size() { return static_cast<int>(call_bytes().size()); }

// File > Write-up: makes the write-up of the request in the room (writeup/writeup_text.h: the student's files, written
// into this worker's file system, then the folder's write-up as `meshedit writeup` makes it) and leaves its bytes
// there, as meshedit_student_call does. A request that cannot be made is a write-up whose notes say why.
extern "C" EMSCRIPTEN_KEEPALIVE const uint8_t* meshedit_writeup() {
  meshedit::Writeup made;
  try {
    made = meshedit::make_requested_writeup(call_bytes());
  } catch (const std::exception& e) {  // std::bad_alloc too: the little left says so
    made = meshedit::Writeup{};
    made.notes.push_back(std::string("the page's worker could not make the write-up: ") + e.what());
  }
  try {
    call_bytes() = meshedit::encode_writeup(made);
  } catch (const std::bad_alloc&) {
    call_bytes().clear();
    return nullptr;
  }
  return call_bytes().data();
}
