// StudentCallWork: one call of the student's code at a time (exercise/student_call.h), off the caller's thread, so a
// runaway loop does not hold the window's frames or the page's tab: on the desktop on a thread of its own
// (student_call_work_native.cpp, through background_work.h), in a page in a Web Worker, another copy of the program
// that gets the call as bytes (student_call_work_web.cpp, exercise/student_call_text.h, web/student_code_worker.js).
// The Exercises tab's Run mine and a lesson's your_turn run the student's code through it.
//
// Invariants:
// - busy() from start() until take(); start() while busy() is refused (returns false, nothing runs).
// - done() says the call has ended; it never blocks (in a page it reads the worker's news). take() gives the result
//   once: on the desktop it waits for the call (ask it to stop first); a page cannot wait for its worker, so a call
//   not done yet is stopped there.
// - stop(): on the desktop the code stops at its next line ("stopped: you pressed Stop", at the line, its writes up to
//   there kept); in a page the worker is ended at once and the result says "stopped: you pressed Stop" with nothing
//   else. A worker past the call's wall time (plus a grace second; the code's own limit normally ends it first, at its
//   line) is ended the same way, with the time limit's words; a worker that dies is the call's error.
// - Code lent to start() (the Exercises tab's loaded file) is used where the call runs in this process, and comes
//   back with take_code(); the page's worker loads the call's files afresh, so a call always carries them.
// - The destructor stops a running call and waits for it (the page: ends its worker).
#pragma once

#include <memory>

#include "exercise/student_call.h"

namespace meshedit {

class StudentCallWork {
 public:
  StudentCallWork();
  ~StudentCallWork();
  StudentCallWork(const StudentCallWork&) = delete;
  StudentCallWork& operator=(const StudentCallWork&) = delete;

  // Whether calls run off the caller's thread (false: a native build without threads, where start() returns with the
  // call done).
  static bool off_the_callers_thread();
  bool start(StudentCall call, std::unique_ptr<StudentCode> code = nullptr);
  bool busy() const;
  bool done() const;
  void stop();
  StudentCallResult take();
  std::unique_ptr<StudentCode> take_code();

 private:
  struct Host;
  std::unique_ptr<Host> host_;
};

}  // namespace meshedit
