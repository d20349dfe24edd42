// StudentCallWork in a page (see student_call_work.h): the call, as bytes (exercise/student_call_text.h), goes to a Web
// Worker running another copy of the program (document/page_worker_job.h; web/student_code_worker.js hands it to
// meshedit_student_call of app/worker_entries_web.cpp) and its result comes back as bytes, so the student's code never
// runs on the page's thread. A worker that ended its call well waits, idle, for the next (the page keeps one); a
// stopped, overdue or dead one is ended, and the next call gets a new one.
#include <exception>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "document/page_worker_job.h"
#include "document/student_call_work.h"
#include "exercise/student_call_text.h"

namespace meshedit {
namespace {

// A result whose outcome is only an error (the worker could not give one).
StudentCallResult failed(std::string error, ScriptError::Limit limit = ScriptError::Limit::None) {
  StudentCallResult result;
  result.outcome.error = std::move(error);
  result.outcome.limit = limit;
  return result;
}

}  // namespace

struct StudentCallWork::Host {
  PageWorkerJob job;
  bool busy = false;
  bool done = false;
  double wall_seconds = 0.0;
  StudentCallResult result;
  std::unique_ptr<StudentCode> code;  // lent, kept only to give back

  void end(StudentCallResult ended) {
    result = std::move(ended);
    done = true;
  }
  void read_news();
};

void StudentCallWork::Host::read_news() {
  if (!busy || done) return;
  PageWorkerJob::End ended = PageWorkerJob::End::None;
  try {
    ended = job.poll();
  } catch (const std::bad_alloc&) {  // no room for the answer's bytes
    job.stop();
    end(StudentCallResult{});
    result.out_of_memory = true;
    return;
  }
  switch (ended) {
    case PageWorkerJob::End::None: return;
    case PageWorkerJob::End::Answered: {
      try {
        end(decode_student_call_result(job.take_answer()));
      } catch (const std::bad_alloc&) {
        end(StudentCallResult{});
        result.out_of_memory = true;
      } catch (const std::exception& e) {
        end(failed(std::string("the page's worker for your code sent what the page cannot read: ") + e.what()));
      }
      // A worker whose memory grew to the limit keeps it (a WebAssembly memory never shrinks): it ends instead.
      const bool spent =
          result.out_of_memory || result.outcome.out_of_memory || result.outcome.limit == ScriptError::Limit::Memory;
      job.release(!spent);
      return;
    }
    case PageWorkerJob::End::Overdue: {
      std::ostringstream words;
      words << "time limit exceeded (" << wall_seconds << " s)";  // LuaRuntime's words
      end(failed(words.str(), ScriptError::Limit::Time));
      return;
    }
    case PageWorkerJob::End::NeverStarted:
      end(failed("the page's worker for your code did not start within 120 s"));
      return;
    case PageWorkerJob::End::Died: end(failed("the page's worker for your code stopped: " + job.died_words())); return;
    case PageWorkerJob::End::Stopped: end(failed("stopped: you pressed Stop", ScriptError::Limit::Stopped)); return;
  }
}

StudentCallWork::StudentCallWork() : host_(std::make_unique<Host>()) {}

StudentCallWork::~StudentCallWork() = default;  // the job ends a worker still on its call

bool StudentCallWork::off_the_callers_thread() { return true; }

bool StudentCallWork::start(StudentCall call, std::unique_ptr<StudentCode> code) {
  if (host_->busy) return false;
  Host& host = *host_;
  host.code = std::move(code);
  host.busy = true;
  host.done = false;
  host.wall_seconds = call.limits.wall_seconds;
  const std::string why = host.job.start("meshedit_student_call", encode_student_call(call), host.wall_seconds);
  if (!why.empty()) host.end(failed("the page could not start a worker for your code (a Web Worker): " + why));
  return true;
}

bool StudentCallWork::busy() const { return host_->busy; }

bool StudentCallWork::done() const {
  host_->read_news();
  return host_->busy && host_->done;
}

void StudentCallWork::stop() {
  if (host_->busy && !host_->done) {
    host_->job.stop();
    host_->read_news();
  }
}

StudentCallResult StudentCallWork::take() {
  if (!done()) stop();
  host_->busy = false;
  host_->done = false;
  return std::move(host_->result);
}

std::unique_ptr<StudentCode> StudentCallWork::take_code() { return std::move(host_->code); }

}  // namespace meshedit
