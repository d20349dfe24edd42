// PageWorkerJob: bytes handed to an entry of the program in the page's Web Worker for student code
// (web/student_code_worker.js: another copy of the program, which calls the entry on the bytes and answers with the
// bytes it leaves), without the page's thread ever waiting. A page only (page_worker_job_web.cpp): StudentCallWork's
// calls (student_call_work_web.cpp) and File > Write-up (app/writeup_room_web.cpp) go this way.
//
// Invariants:
// - One job at a time: start() while running() is refused. poll() never blocks: it reads the worker's news.
// - A job ends in exactly one of: answered (its bytes in take_answer()), stopped (stop()), overdue (the worker began
//   but did not answer within the job's seconds and a grace second: it is ended), never started (no word from the
//   worker within 120 s, its start-up included), or died (the worker stopped: `died_words()`).
// - A worker that answered waits, idle, for the next job when release(true) says it may (the page keeps one); every
//   other end ends its worker, and the next job gets a new one. The destructor ends a worker still on its job.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace meshedit {

class PageWorkerJob {
 public:
  enum class End { None, Answered, Stopped, Overdue, NeverStarted, Died };

  PageWorkerJob();
  ~PageWorkerJob();
  PageWorkerJob(const PageWorkerJob&) = delete;
  PageWorkerJob& operator=(const PageWorkerJob&) = delete;

  // Sends `bytes` for the worker's `entry` (a C function of worker_entries_web.cpp); "" when sent, else why not.
  std::string start(const char* entry, const std::vector<uint8_t>& bytes, double seconds);
  bool running() const;
  // Reads the worker's news; returns end() (End::None while it runs).
  End poll();
  End end() const;
  void stop();
  double seconds_since_start() const;

  std::vector<uint8_t> take_answer();     // after End::Answered
  void release(bool keep_worker);         // after End::Answered: the worker kept idle for the next job, or ended
  const std::string& died_words() const;  // after End::Died: what the worker said ("the program stopped: ...")

 private:
  struct Host;
  std::unique_ptr<Host> host_;
};

}  // namespace meshedit
