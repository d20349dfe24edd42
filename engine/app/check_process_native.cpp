// CheckProcess on the desktop: `meshedit grade --visible-only` in a child process (see check_process.h).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <sstream>
#include <system_error>
#include <vector>

#include "app/check_process.h"
#include "app/spawned_program.h"
#include "core/data_folders.h"
#include "core/translation.h"
#include "grade/report_json.h"
#include "grade/submission.h"
#include "io/file_access.h"

namespace meshedit {
namespace {

constexpr const char* kProgressPrefix = "meshedit grade: test ";

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// A folder of its own under the system's temporary folder, or empty.
std::filesystem::path make_run_folder() {
  std::error_code ec;
  std::string pattern = (std::filesystem::temp_directory_path(ec) / "meshedit-check-XXXXXX").string();
  if (ec) return {};
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) return {};
  return std::filesystem::path(buffer.data());
}

// What the child said besides its progress: the grader's own error ("meshedit grade: SUITE:3: ...").
std::string words_besides_progress(const std::string& printed) {
  std::istringstream lines(printed);
  std::string line, words;
  while (std::getline(lines, line)) {
    if (line.rfind(kProgressPrefix, 0) == 0 || line.empty()) continue;
    words += (words.empty() ? "" : "\n") + line;
  }
  return words;
}

}  // namespace

struct CheckProcess::Host {
  SpawnedProgram child;
  std::filesystem::path folder;
};

CheckProcess::CheckProcess() : host_(std::make_unique<Host>()) {}

bool CheckProcess::available() { return true; }

std::filesystem::path check_program() {
  const std::filesystem::path folder = program_folder();
  if (folder.empty()) return "meshedit";
  return folder / "meshedit";
}

CheckProcess::~CheckProcess() { stop(); }

double CheckProcess::seconds() const { return (running() ? now() : ended_) - started_; }

bool CheckProcess::start(const std::filesystem::path& meshedit, const std::filesystem::path& suite,
                         const std::filesystem::path& submission) {
  stop();
  report_.reset();
  problem_.clear();
  stopped_ = false;
  done_ = total_ = 0;
  running_test_.clear();
  started_ = ended_ = now();
  host_->folder = make_run_folder();
  if (host_->folder.empty()) {
    problem_ = tr("Check my work could not make a temporary folder for the grader's files");
    return false;
  }
  const std::vector<std::string> args = {meshedit.string(),
                                         "grade",
                                         "--suite",
                                         suite.string(),
                                         "--submission",
                                         submission.string(),
                                         "--visible-only",
                                         "--results",
                                         (host_->folder / "results.json").string(),
                                         "--report",
                                         (host_->folder / "check.json").string(),
                                         "--progress",
                                         "--language",
                                         language_code(text_language())};
  if (const std::string why = host_->child.start(args, SpawnedProgram::Output::StderrOnly); !why.empty()) {
    problem_ = tr_format("Check my work could not start the grader {program}: {why}",
                         {{"program", meshedit.string()}, {"why", why}});
    forget_files();
    return false;
  }
  running_ = true;
  return true;
}

void CheckProcess::read_progress() {
  // The last whole progress line: "meshedit grade: test 3 of 14 running: NAME" or "... done: NAME".
  const std::string& progress = host_->child.printed();
  const size_t end = progress.rfind('\n');
  if (end == std::string::npos) return;
  const size_t begin = progress.rfind(kProgressPrefix, end);
  if (begin == std::string::npos) return;
  const std::string line =
      progress.substr(begin + std::strlen(kProgressPrefix), end - begin - std::strlen(kProgressPrefix));
  unsigned long number = 0, total = 0;  // NOLINT(google-runtime-int): sscanf's type
  int rest = 0;
  if (std::sscanf(line.c_str(), "%lu of %lu %n", &number, &total, &rest) < 2 || rest <= 0) return;
  const std::string words = line.substr(static_cast<size_t>(rest));
  total_ = total;
  for (const char* state : {"running: ", "done: "}) {
    if (words.rfind(state, 0) != 0) continue;
    const bool running = state[0] == 'r';
    done_ = running ? number - 1 : number;
    running_test_ = running ? words.substr(std::strlen(state)) : std::string();
  }
}

void CheckProcess::poll() {
  if (!running()) return;
  const bool ended = host_->child.poll();
  read_progress();
  if (ended) finish(host_->child.status());
}

void CheckProcess::finish(int status) {
  running_ = false;
  ended_ = now();
  // status -1: the child was reaped elsewhere (SIGCHLD ignored): its report, when it wrote one, says how it went.
  std::error_code ec;
  const bool graded =
      status != -1 ? host_->child.exit_code() == 0 : std::filesystem::exists(host_->folder / "check.json", ec);
  if (graded) {
    try {
      report_ = decode_grade_report(read_file(host_->folder / "check.json"));
    } catch (const std::exception& e) {  // a GradeError, or a FileError for a report that was never written
      problem_ = tr_format("the grader's report could not be read: {error}", {{"error", e.what()}});
    }
  } else {
    const std::string words = words_besides_progress(host_->child.printed());
    problem_ = words.empty() ? "the grader " + host_->child.end_words() : words;
  }
  forget_files();
}

void CheckProcess::stop() {
  if (running()) {
    host_->child.stop();
    running_ = false;
    ended_ = now();
    stopped_ = true;
  }
  forget_files();
}

void CheckProcess::forget_files() {
  if (host_->folder.empty()) return;
  std::error_code ec;
  std::filesystem::remove_all(host_->folder, ec);
  host_->folder.clear();
}

}  // namespace meshedit
