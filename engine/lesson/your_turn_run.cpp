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

YourTurnRun::YourTurnRun(YourTurnVerdict verdict, DiagramNames names, const LuaLimits& limits, bool in_background)
    : verdict_(std::move(verdict)), names_(std::move(names)) {
  reference_ = run_reference(verdict_.exercise, verdict_.exercise_input);
  started_ = std::chrono::steady_clock::now();
  StudentCall call;
  call.exercise = verdict_.exercise;
  call.input = verdict_.exercise_input;
  call.limits = limits;
  try {
    call.files.push_back(read_student_source(verdict_.path));
  } catch (const ScriptError& error) {  // "cannot open ...": nothing to run
    result_.load_error = error.what();
    ran_here_ = true;
    return;
  }
  if (in_background) {
    work_.start(std::move(call));
  } else {
    result_ = run_student_call(call);
    ran_here_ = true;
  }
}

double YourTurnRun::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

YourTurnVerdict YourTurnRun::finish() {
  if (!ran_here_) result_ = work_.take();
  if (result_.out_of_memory) throw std::bad_alloc();
  YourTurnVerdict verdict = std::move(verdict_);
  if (!result_.load_error.empty() ||
      !result_.thrown.empty()) {  // nothing else is thrown; a bug must not end the window
    verdict.feedback = std::move(result_.load_error.empty() ? result_.thrown : result_.load_error);
    return verdict;
  }
  const ExerciseReport report =
      compare(verdict.exercise, verdict.exercise_input, std::move(result_.outcome), std::move(reference_));
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
