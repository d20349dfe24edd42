// One run of a your_turn off the caller's thread (see internal/your_turn_run.h).
#include "lesson/internal/your_turn_run.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <new>
#include <utility>

namespace meshedit {
namespace {

constexpr size_t kDiagnosisLines = 3;  // the first differences shown, the likely mistake first

// The wrong verdict's words: compare()'s first differences, the likely mistake first.
std::string diagnosis(const ExerciseReport& report) {
  std::string text;
  for (size_t i = 0; i < report.differences.size() && i < kDiagnosisLines; ++i) {
    text += (text.empty() ? "" : "\n") + report.differences[i];
  }
  const size_t shown = std::min(report.differences.size(), kDiagnosisLines);
  if (report.total_differences > shown) {
    text += "\n(" + std::to_string(report.total_differences - shown) + " more: the Exercises tab lists them)";
  }
  return text.empty() ? report.summary() : text;
}

}  // namespace

YourTurnRun::YourTurnRun(YourTurnVerdict verdict, DiagramNames names, const LuaLimits& limits)
    : verdict_(std::move(verdict)), names_(std::move(names)), limits_(limits) {
  reference_ = run_reference(verdict_.exercise, verdict_.exercise_input);
  started_ = std::chrono::steady_clock::now();
  work_.start([this] { work(); });
}

YourTurnRun::~YourTurnRun() {
  stop();
  work_.take();
}

double YourTurnRun::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

void YourTurnRun::work() noexcept {
  try {
    StudentCode code(limits_);
    code.runtime().set_stop_request(&stop_);
    try {
      code.load(verdict_.path);
      mine_ = run_mine(code, verdict_.exercise, verdict_.exercise_input);
    } catch (const ScriptError& error) {  // the file does not load: its own file:line
      load_error_ = error.what();
    }
    code.runtime().set_stop_request(nullptr);
  } catch (const std::bad_alloc&) {
    out_of_memory_ = true;
  } catch (const std::exception& e) {  // nothing else is thrown; a bug must not end the window
    try {
      load_error_ = e.what();
    } catch (const std::bad_alloc&) {
      out_of_memory_ = true;
    }
  }
}

YourTurnVerdict YourTurnRun::finish() {
  work_.take();
  if (out_of_memory_) throw std::bad_alloc();
  YourTurnVerdict verdict = std::move(verdict_);
  if (!load_error_.empty()) {
    verdict.feedback = std::move(load_error_);
    return verdict;
  }
  const ExerciseReport report =
      compare(verdict.exercise, verdict.exercise_input, std::move(mine_), std::move(reference_));
  verdict.right = report.equal;
  if (!report.equal) {
    verdict.feedback = diagnosis(report);
    if (std::string legend = diagram_legend(verdict.feedback, names_); !legend.empty()) {
      verdict.feedback += "\n" + legend;
    }
  }
  return verdict;
}

}  // namespace meshedit
