// CheckProcess in a page (see check_process.h): the suite is loaded here and the report made here (grade/grade_run.h,
// as grade() makes it), while each test runs in a Web Worker (web/student_code_worker.js, which runs
// meshedit_check_test of app/worker_entries_web.cpp in its own copy of the program): student code never runs on the
// page's thread, so the page keeps drawing, and a test that outlives its time limit (plus grade()'s grace second) is
// stopped by ending the worker, with the desktop's words for a test its parent killed. A worker that dies (its memory
// ran out, the program aborted) fails its test as a crash; the next test gets a new worker. When the check ends, its
// results.json (Gradescope's shape) is put into the page as the text of <script type="application/json"
// id="check-results">, for a browser that reads the page.
#include <emscripten/emscripten.h>

#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "app/check_process.h"
#include "core/translation.h"
#include "grade/grade_run.h"
#include "grade/report_json.h"
#include "grade/results_writers.h"
#include "grade/submission.h"
#include "grade/suite.h"
#include "script/exception_text.h"

// The page's side of the worker (clang-format would space its operators as C++). The worker's news waits in
// Module.checkNews until poll() takes it, one item a call.
// clang-format off
// Forgets the files of the last check: the next check's submission is sent with page_check_add_file.
EM_JS(void, page_check_begin, (), {
  Module.checkFiles = [];
  Module.checkNews = [];
  Module.checkRun = (Module.checkRun || 0) + 1;
});
// One file of the submission: its path inside the folder and its bytes.
EM_JS(void, page_check_add_file, (const char* relative, const char* bytes, int size), {
  Module.checkFiles.push({relative: UTF8ToString(relative), bytes: HEAPU8.slice(bytes, bytes + size)});
});
// Sends test `index` of `suite` to the worker (made first when there is none); "" when it was sent, else why not.
EM_JS(char*, page_check_send, (const char* suite, int index, const char* language), {
  try {
    if (!Module.checkWorker) {
      const worker = new Worker('student_code_worker.js');
      worker.onmessage = (event) => { if (Module.checkWorker === worker) Module.checkNews.push(event.data); };
      worker.onerror = (event) => {
        event.preventDefault();
        if (Module.checkWorker === worker) Module.checkNews.push({kind: 'crash', text: String(event.message)});
      };
      Module.checkWorker = worker;
    }
    Module.checkWorker.postMessage({run: Module.checkRun, suite: UTF8ToString(suite), index: index,
                                    language: UTF8ToString(language), files: Module.checkFiles});
    return allocateUTF8("");
  } catch (e) {
    return allocateUTF8(String(e && e.message ? e.message : e));
  }
});
// The worker's oldest news as "KIND\nSECONDS\nTEXT" (KIND started, result, crash or log), or "" when there is none.
EM_JS(char*, page_check_news, (), {
  const news = Module.checkNews ? Module.checkNews.shift() : undefined;
  if (!news) return allocateUTF8("");
  return allocateUTF8(news.kind + "\n" + String(news.seconds || 0) + "\n" + String(news.text || ""));
});
// Ends the worker at once (a test past its limit, Stop, the check's end); the next test gets a new one.
EM_JS(void, page_check_end_worker, (), {
  if (Module.checkWorker) Module.checkWorker.terminate();
  Module.checkWorker = null;
  Module.checkNews = [];
});
// The check's results.json as the text of <script type="application/json" id="check-results">.
EM_JS(void, page_show_check_results, (const char* json), {
  let element = document.getElementById('check-results');
  if (!element) {
    element = document.createElement('script');
    element.type = 'application/json';
    element.id = 'check-results';
    document.body.appendChild(element);
  }
  element.textContent = UTF8ToString(json);
});
// clang-format on

namespace meshedit {
namespace {

const double kKillGraceSeconds = GradeOptions{}.kill_grace_seconds;  // grade()'s
constexpr double kWorkerStartSeconds = 120.0;  // a worker that has not begun its test by then never will
constexpr size_t kLogCap = 2000;               // what a crashed test's error keeps of the worker's messages

double now() { return emscripten_get_now() / 1000.0; }

// Takes a string the page's JavaScript made.
std::string take_page_string(char* text) {
  std::string taken = text != nullptr ? text : "";
  std::free(text);  // NOLINT(cppcoreguidelines-no-malloc): allocateUTF8's memory
  return taken;
}

}  // namespace

struct CheckProcess::Host {
  std::unique_ptr<Suite> suite;
  std::optional<Submission> submission;
  std::unique_ptr<GradeRun> grading;
  std::string suite_path;
  std::optional<size_t> test;  // the test the worker has now
  double sent = 0.0;           // when it was sent
  double began = 0.0;          // when the worker said it began it (0: not yet)
  std::string log;             // what the worker printed during this test
};

CheckProcess::CheckProcess() : host_(std::make_unique<Host>()) {}

CheckProcess::~CheckProcess() { stop(); }

bool CheckProcess::available() { return true; }

std::filesystem::path check_program() { return {}; }

double CheckProcess::seconds() const { return (running() ? now() : ended_) - started_; }

bool CheckProcess::start(const std::filesystem::path&, const std::filesystem::path& suite,
                         const std::filesystem::path& submission) {
  stop();
  report_.reset();
  problem_.clear();
  stopped_ = false;
  done_ = total_ = 0;
  running_test_.clear();
  started_ = ended_ = now();
  *host_ = Host{};
  try {
    // What `meshedit grade` says when it cannot grade (cli.cpp: "meshedit: " and the reason).
    host_->suite = Suite::load(suite);
    host_->submission = Submission::read(submission);
    GradeOptions options;
    options.visible_only = true;
    host_->grading = std::make_unique<GradeRun>(*host_->suite, *host_->submission, options);
    host_->suite_path = suite.string();
    total_ = host_->grading->tests_to_run();
    page_check_begin();
    for (const SubmissionFile& file : host_->submission->files()) {
      page_check_add_file(file.relative.c_str(), file.text.data(), static_cast<int>(file.text.size()));
    }
  } catch (const std::exception& e) {
    problem_ = "meshedit: " + exception_text(e);
    *host_ = Host{};
    return true;  // it ended at once, with the problem the desktop's grader would print
  }
  running_ = true;
  run_next_test();
  return true;
}

void CheckProcess::run_next_test() {
  const std::optional<size_t> next = host_->grading->next_test();
  if (!next) {
    page_check_end_worker();
    running_ = false;
    ended_ = now();
    running_test_.clear();
    report_ = host_->grading->finish();
    page_show_check_results(gradescope_json(*report_).c_str());
    *host_ = Host{};
    return;
  }
  host_->test = next;
  host_->sent = now();
  host_->began = 0.0;
  host_->log.clear();
  running_test_ = host_->suite->tests()[*next].name;
  const std::string why = take_page_string(
      page_check_send(host_->suite_path.c_str(), static_cast<int>(*next), language_code(text_language())));
  if (why.empty()) return;
  page_check_end_worker();
  running_ = false;
  ended_ = now();
  problem_ = tr_format("Check my work could not start the page's grader (a Web Worker): {why}", {{"why", why}});
  *host_ = Host{};
}

void CheckProcess::take_worker_news() {
  while (running_) {
    const std::string news = take_page_string(page_check_news());
    if (news.empty()) return;
    const size_t kind_end = news.find('\n');
    const size_t seconds_end = news.find('\n', kind_end + 1);
    const std::string kind = news.substr(0, kind_end);
    const double seconds = std::atof(news.substr(kind_end + 1, seconds_end - kind_end - 1).c_str());
    const std::string text = news.substr(seconds_end + 1);
    if (kind == "started") {
      host_->began = now();
    } else if (kind == "log") {
      if (host_->log.size() < kLogCap) host_->log += (host_->log.empty() ? "" : "\n") + text;
    } else if (kind == "result" || kind == "crash") {
      TestRun run;
      if (kind == "result") {
        try {
          run = decode_test_run(text);
        } catch (const GradeError& e) {
          run.end = RunEnd::Crash;
          run.error = e.what();
        }
      } else {
        page_check_end_worker();
        run.end = RunEnd::Crash;
        run.error = "the test's worker stopped: " + text;
        if (!host_->log.empty()) run.error += "\n" + host_->log.substr(0, kLogCap);
      }
      host_->grading->add_result(*host_->test, run, kind == "result" ? seconds : now() - host_->sent);
      ++done_;
      run_next_test();
    }
  }
}

void CheckProcess::poll() {
  if (!running_) return;
  try {
    take_worker_news();
    if (!running_ || !host_->test) return;
    const TestSpec& spec = host_->suite->tests()[*host_->test];
    if (host_->began > 0.0 && now() - host_->began > spec.time_limit + kKillGraceSeconds) {
      page_check_end_worker();
      TestRun run;
      run.end = RunEnd::Timeout;
      run.error = wall_clock_stop_sentence(spec.time_limit);
      host_->grading->add_result(*host_->test, run, now() - host_->began);
      ++done_;
      run_next_test();
    } else if (host_->began == 0.0 && now() - host_->sent > kWorkerStartSeconds) {
      stop();
      stopped_ = false;
      problem_ = tr("the page's grader (a Web Worker) did not start a test within 120 s");
    }
  } catch (const std::exception& e) {
    stop();
    stopped_ = false;
    problem_ = tr_format("Check my work: {problem}", {{"problem", exception_text(e)}});
  }
}

void CheckProcess::stop() {
  if (!running_) return;
  page_check_end_worker();
  running_ = false;
  ended_ = now();
  stopped_ = true;
  *host_ = Host{};
}

}  // namespace meshedit
