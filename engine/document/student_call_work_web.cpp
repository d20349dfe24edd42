// StudentCallWork in a page (see student_call_work.h): the call, as bytes (exercise/student_call_text.h), goes to a Web
// Worker running another copy of the program (web/student_code_worker.js, which hands it to meshedit_student_call of
// app/student_call_worker_web.cpp) and its result comes back as bytes, so the student's code never runs on the page's
// thread. A worker that ended its call well waits, idle, for the next (the page keeps one); a stopped, overdue or dead
// one is ended, and the next call gets a new one.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "document/student_call_work.h"
#include "exercise/student_call_text.h"

// The page's side of the workers (clang-format would space its operators as C++). Each StudentCallWork is a `slot`,
// with at most one worker and the news that worker sent, waiting in Module.callSlots[slot] until read.
// clang-format off
// Sends the call to the slot's worker (an idle one, or a new one); "" when it was sent, else why not.
EM_JS(char*, page_call_send, (int slot, const uint8_t* bytes, int size), {
  try {
    Module.callSlots = Module.callSlots || {};
    Module.idleCallWorkers = Module.idleCallWorkers || [];
    const entry = {worker: Module.idleCallWorkers.pop() || new Worker('student_code_worker.js'), news: []};
    entry.worker.onmessage = (event) => entry.news.push(event.data);
    entry.worker.onerror = (event) => {
      event.preventDefault();
      entry.news.push({kind: 'crash', text: String(event.message)});
    };
    Module.callSlots[slot] = entry;
    const call = HEAPU8.slice(bytes, bytes + size);
    entry.worker.postMessage({call: call}, [call.buffer]);
    return allocateUTF8("");
  } catch (e) {
    return allocateUTF8(String(e && e.message ? e.message : e));
  }
});
// The slot's oldest news: "started", "result" (its bytes wait for page_call_copy_result), "crash\nTEXT", or "".
EM_JS(char*, page_call_news, (int slot), {
  const entry = Module.callSlots && Module.callSlots[slot];
  const news = entry ? entry.news.shift() : undefined;
  if (!news) return allocateUTF8("");
  if (news.kind === 'result') {
    entry.result = news.bytes;
    return allocateUTF8("result");
  }
  return allocateUTF8(news.kind + (news.text ? "\n" + String(news.text) : ""));
});
EM_JS(int, page_call_result_size, (int slot), { return Module.callSlots[slot].result.length; });
EM_JS(void, page_call_copy_result, (int slot, uint8_t* into), { HEAPU8.set(Module.callSlots[slot].result, into); });
// The slot's call is over: its worker waits, idle, for the next call when `keep` (the page keeps one), else it ends.
EM_JS(void, page_call_release, (int slot, int keep), {
  const entry = Module.callSlots[slot];
  delete Module.callSlots[slot];
  entry.worker.onmessage = null;
  entry.worker.onerror = null;
  if (keep && Module.idleCallWorkers.length === 0) Module.idleCallWorkers.push(entry.worker);
  else entry.worker.terminate();
});
// Ends the slot's worker at once (Stop, a call past its time, a dead worker, the object's end).
EM_JS(void, page_call_end_worker, (int slot), {
  const entry = Module.callSlots && Module.callSlots[slot];
  if (!entry) return;
  entry.worker.terminate();
  delete Module.callSlots[slot];
});
// clang-format on

namespace meshedit {
namespace {

constexpr double kGraceSeconds = 1.0;          // past the call's wall time, before its worker is ended
constexpr double kWorkerStartSeconds = 120.0;  // a worker that has not begun its call by then never will

double now() { return emscripten_get_now() / 1000.0; }

// Takes a string the page's JavaScript made.
std::string take_page_string(char* text) {
  std::string taken = text != nullptr ? text : "";
  std::free(text);  // NOLINT(cppcoreguidelines-no-malloc): allocateUTF8's memory
  return taken;
}

int next_slot() {
  static int slots = 0;
  return ++slots;
}

// A result whose outcome is only an error (the worker could not give one).
StudentCallResult failed(std::string error, ScriptError::Limit limit = ScriptError::Limit::None) {
  StudentCallResult result;
  result.outcome.error = std::move(error);
  result.outcome.limit = limit;
  return result;
}

}  // namespace

struct StudentCallWork::Host {
  int slot = next_slot();
  bool busy = false;
  bool done = false;
  double wall_seconds = 0.0;
  double sent = 0.0;
  double began = 0.0;  // when the worker said it began the call (0: not yet)
  StudentCallResult result;
  std::unique_ptr<StudentCode> code;  // lent, kept only to give back

  void end(StudentCallResult ended) {
    result = std::move(ended);
    done = true;
  }
  void end_worker(StudentCallResult ended) {
    page_call_end_worker(slot);
    end(std::move(ended));
  }
  void read_news();
};

void StudentCallWork::Host::read_news() {
  while (busy && !done) {
    const std::string news = take_page_string(page_call_news(slot));
    if (news.empty()) break;
    if (news == "started") {
      began = now();
    } else if (news == "result") {
      try {
        std::vector<uint8_t> bytes(static_cast<size_t>(page_call_result_size(slot)));
        page_call_copy_result(slot, bytes.data());
        end(decode_student_call_result(bytes));
      } catch (const std::bad_alloc&) {
        end(StudentCallResult{});
        result.out_of_memory = true;
      } catch (const std::exception& e) {
        end(failed(std::string("the page's worker for your code sent what the page cannot read: ") + e.what()));
      }
      // A worker whose memory grew to the limit keeps it (a WebAssembly memory never shrinks): it ends instead.
      const bool spent =
          result.out_of_memory || result.outcome.out_of_memory || result.outcome.limit == ScriptError::Limit::Memory;
      page_call_release(slot, spent ? 0 : 1);
    } else {
      end_worker(failed("the page's worker for your code stopped: " + news.substr(news.find('\n') + 1)));
    }
  }
  if (!busy || done) return;
  if (began > 0.0 && now() - began > wall_seconds + kGraceSeconds) {
    std::ostringstream words;
    words << "time limit exceeded (" << wall_seconds << " s)";  // LuaRuntime's words
    end_worker(failed(words.str(), ScriptError::Limit::Time));
  } else if (began == 0.0 && now() - sent > kWorkerStartSeconds) {
    end_worker(failed("the page's worker for your code did not start within 120 s"));
  }
}

StudentCallWork::StudentCallWork() : host_(std::make_unique<Host>()) {}

StudentCallWork::~StudentCallWork() {
  if (host_->busy && !host_->done) page_call_end_worker(host_->slot);
}

bool StudentCallWork::off_the_callers_thread() { return true; }

bool StudentCallWork::start(StudentCall call, std::unique_ptr<StudentCode> code) {
  if (host_->busy) return false;
  Host& host = *host_;
  host.code = std::move(code);
  host.busy = true;
  host.done = false;
  host.began = 0.0;
  host.sent = now();
  host.wall_seconds = call.limits.wall_seconds;
  const std::vector<uint8_t> bytes = encode_student_call(call);
  const std::string why = take_page_string(page_call_send(host.slot, bytes.data(), static_cast<int>(bytes.size())));
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
    host_->end_worker(failed("stopped: you pressed Stop", ScriptError::Limit::Stopped));
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
