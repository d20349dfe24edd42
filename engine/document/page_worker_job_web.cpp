// PageWorkerJob in a page (see page_worker_job.h): the bytes go to a Web Worker (web/student_code_worker.js) with the
// name of the entry to call on them, and the worker's news comes back through Module.jobSlots.
#include <emscripten/emscripten.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "document/page_worker_job.h"

// The page's side of the workers (clang-format would space its operators as C++). Each PageWorkerJob is a `slot`, with
// at most one worker and the news that worker sent, waiting in Module.jobSlots[slot] until read.
// clang-format off
// Sends the bytes to the slot's worker (an idle one, or a new one); "" when they were sent, else why not.
EM_JS(char*, page_job_send, (int slot, const char* entry, const uint8_t* bytes, int size), {
  try {
    Module.jobSlots = Module.jobSlots || {};
    Module.idleJobWorkers = Module.idleJobWorkers || [];
    const job = {worker: Module.idleJobWorkers.pop() || new Worker('student_code_worker.js'), news: []};
    job.worker.onmessage = (event) => job.news.push(event.data);
    job.worker.onerror = (event) => {
      event.preventDefault();
      job.news.push({kind: 'crash', text: String(event.message)});
    };
    Module.jobSlots[slot] = job;
    const call = HEAPU8.slice(bytes, bytes + size);
    job.worker.postMessage({call: call, entry: UTF8ToString(entry)}, [call.buffer]);
    return allocateUTF8("");
  } catch (e) {
    return allocateUTF8(String(e && e.message ? e.message : e));
  }
});
// The slot's oldest news: "started", "result" (its bytes wait for page_job_copy_result), "crash\nTEXT", or "".
EM_JS(char*, page_job_news, (int slot), {
  const job = Module.jobSlots && Module.jobSlots[slot];
  const news = job ? job.news.shift() : undefined;
  if (!news) return allocateUTF8("");
  if (news.kind === 'result') {
    job.result = news.bytes;
    return allocateUTF8("result");
  }
  return allocateUTF8(news.kind + (news.text ? "\n" + String(news.text) : ""));
});
EM_JS(int, page_job_result_size, (int slot), { return Module.jobSlots[slot].result.length; });
EM_JS(void, page_job_copy_result, (int slot, uint8_t* into), { HEAPU8.set(Module.jobSlots[slot].result, into); });
// The slot's job is over: its worker waits, idle, for the next job when `keep` (the page keeps one), else it ends.
EM_JS(void, page_job_release, (int slot, int keep), {
  const job = Module.jobSlots[slot];
  if (!job) return;
  delete Module.jobSlots[slot];
  job.worker.onmessage = null;
  job.worker.onerror = null;
  if (keep && Module.idleJobWorkers.length === 0) Module.idleJobWorkers.push(job.worker);
  else job.worker.terminate();
});
// Ends the slot's worker at once (Stop, a job past its time, a dead worker, the object's end).
EM_JS(void, page_job_end_worker, (int slot), {
  const job = Module.jobSlots && Module.jobSlots[slot];
  if (!job) return;
  job.worker.terminate();
  delete Module.jobSlots[slot];
});
// clang-format on

namespace meshedit {
namespace {

constexpr double kGraceSeconds = 1.0;          // past the job's seconds, before its worker is ended
constexpr double kWorkerStartSeconds = 120.0;  // a worker that has not begun its job by then never will

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

}  // namespace

struct PageWorkerJob::Host {
  int slot = next_slot();
  bool running = false;
  End end = End::None;
  double seconds = 0.0;
  double sent = 0.0;
  double began = 0.0;  // when the worker said it began the job (0: not yet)
  std::vector<uint8_t> answer;
  std::string died;

  void finish(End how, bool end_worker) {
    if (end_worker) page_job_end_worker(slot);
    running = false;
    end = how;
  }
};

PageWorkerJob::PageWorkerJob() : host_(std::make_unique<Host>()) {}

PageWorkerJob::~PageWorkerJob() {
  if (host_->running) page_job_end_worker(host_->slot);
}

std::string PageWorkerJob::start(const char* entry, const std::vector<uint8_t>& bytes, double seconds) {
  if (host_->running) return "a job is running";
  Host& host = *host_;
  host.end = End::None;
  host.answer.clear();
  host.died.clear();
  host.began = 0.0;
  host.sent = now();
  host.seconds = seconds;
  const std::string why =
      take_page_string(page_job_send(host.slot, entry, bytes.data(), static_cast<int>(bytes.size())));
  host.running = why.empty();
  return why;
}

bool PageWorkerJob::running() const { return host_->running; }

PageWorkerJob::End PageWorkerJob::end() const { return host_->end; }

double PageWorkerJob::seconds_since_start() const { return now() - host_->sent; }

PageWorkerJob::End PageWorkerJob::poll() {
  Host& host = *host_;
  while (host.running) {
    const std::string news = take_page_string(page_job_news(host.slot));
    if (news.empty()) break;
    if (news == "started") {
      host.began = now();
    } else if (news == "result") {
      host.answer.resize(static_cast<size_t>(page_job_result_size(host.slot)));  // std::bad_alloc: the caller's
      page_job_copy_result(host.slot, host.answer.data());
      host.finish(End::Answered, false);
    } else {
      host.died = news.substr(news.find('\n') + 1);
      host.finish(End::Died, true);
    }
  }
  if (!host.running) return host.end;
  if (host.began > 0.0 && now() - host.began > host.seconds + kGraceSeconds) {
    host.finish(End::Overdue, true);
  } else if (host.began == 0.0 && now() - host.sent > kWorkerStartSeconds) {
    host.finish(End::NeverStarted, true);
  }
  return host.end;
}

void PageWorkerJob::stop() {
  if (host_->running) host_->finish(End::Stopped, true);
}

std::vector<uint8_t> PageWorkerJob::take_answer() { return std::move(host_->answer); }

void PageWorkerJob::release(bool keep_worker) { page_job_release(host_->slot, keep_worker ? 1 : 0); }

const std::string& PageWorkerJob::died_words() const { return host_->died; }

}  // namespace meshedit
