// GradeRun: a grading one test at a time, its notes and totals (see grade_run.h).
#include "grade/grade_run.h"

#include <sstream>
#include <utility>

#include "core/value_format.h"

namespace meshedit {

GradeRun::GradeRun(Suite& suite, const Submission& submission, GradeOptions options)
    : suite_(suite), options_(std::move(options)), started_(std::chrono::steady_clock::now()) {
  report_.suite_name = suite.name();
  std::ostringstream top;
  top << "Suite " << suite.name() << ": " << plural(suite.tests().size(), "test", "tests") << ".\n";
  std::string files;
  for (const auto& f : submission.files()) files += (files.empty() ? "" : ", ") + f.relative;
  top << "Files submitted: " << (files.empty() ? "none" : files) << ".\n";
  for (const auto& name : suite.named_files()) {
    if (!submission.find(name)) top << "Missing: " << name << " (the tests that need it fail).\n";
  }
  for (const auto& note : submission.notes()) top << "Note: " << note << ".\n";
  top_ = top.str();
  not_shown_ = {{"hidden"}, {"after_due_date"}, {"after_published"}};
  for (const TestSpec& spec : suite.tests()) {
    if (runs(spec)) ++to_run_;
  }
}

std::optional<size_t> GradeRun::next_test() {
  while (next_ < suite_.tests().size()) {
    const size_t index = next_++;
    if (options_.time_limit_cap > 0) suite_.cap_time_limit(index, options_.time_limit_cap);
    const TestSpec& spec = suite_.tests()[index];
    if (runs(spec)) return index;
    for (NotShown& left_out : not_shown_) {
      if (left_out.visibility != spec.visibility) continue;
      ++left_out.tests;
      left_out.points += spec.points;
    }
  }
  return std::nullopt;
}

void GradeRun::add_result(size_t index, const TestRun& run, double seconds) {
  const TestSpec& spec = suite_.tests().at(index);
  TestResult result = score_test(spec, run, seconds);
  report_.score += result.score;
  (spec.extra_credit ? report_.extra_points : report_.max_score) += spec.points;
  if (options_.on_test) options_.on_test(result);
  report_.tests.push_back(std::move(result));
}

void GradeRun::add_note(const std::string& line) { notes_ += line + "\n"; }

GradeReport GradeRun::finish() {
  GradeReport report = report_;
  report.score = round_score(report.score);
  std::ostringstream top;
  top << top_;
  if (report.extra_points > 0) {
    std::string numbers;
    for (const auto& spec : suite_.tests()) {
      if (spec.extra_credit) numbers += (numbers.empty() ? "" : ", ") + spec.number;
    }
    const bool one = numbers.find(',') == std::string::npos;
    top << "Extra credit: " << (one ? "test " : "tests ") << numbers << (one ? " adds" : " add") << " up to "
        << report.extra_points << (report.extra_points == 1.0 ? " point" : " points") << " on top of the "
        << report.max_score << " base points.\n";
  }
  std::vector<NotShown> not_shown = not_shown_;
  std::erase_if(not_shown, [](const NotShown& left_out) { return left_out.tests == 0; });
  report.not_shown = std::move(not_shown);
  if (const std::string sentence = not_shown_sentence(report.not_shown); !sentence.empty()) top << sentence << "\n";
  report.output = top.str() + notes_;
  report.execution_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  return report;
}

std::string wall_clock_stop_sentence(double time_limit) {
  std::ostringstream s;
  s << "stopped after " << time_limit
    << " s (time limit): the test was still running (an endless loop, or one very long call such as a string "
       "pattern)";
  return s.str();
}

}  // namespace meshedit
