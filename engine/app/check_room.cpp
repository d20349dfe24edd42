// File > Check my work: the run, its verdict in the status line and the Check tab (see check_room.h).
#include "app/check_room.h"

#include <exception>
#include <sstream>

#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/window_host.h"
#include "core/data_folders.h"
#include "core/translation.h"
#include "grade/grader.h"
#include "grade/results_writers.h"

namespace meshedit {
namespace {

std::filesystem::path course_suite() { return data_folder("tests/grading/suites") / "all.lua"; }

}  // namespace

CheckRoom::CheckRoom(DocumentRoom& document, ExerciseRoom& exercises)
    : document_(document), exercises_(exercises), suite_(course_suite()), program_(check_program()) {}

Check CheckRoom::start() {
  try {
    panel_.open = true;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(suite_, ec)) {
      const std::string why = tr_format("Check my work: no suite at {file}", {{"file", suite_.string()}});
      document_.message(Severity::Error, why);
      return Check::no(why);
    }
    checked_folder_ = exercises_.session().folder();
    started_ = true;
    announced_ = false;
    if (!process_.start(program_, suite_, checked_folder_)) {
      announced_ = true;
      document_.message(Severity::Error, tr_format("Check my work: {problem}", {{"problem", process_.problem()}}));
      return Check::no(process_.problem());
    }
    const std::string unsaved = exercises_.unsaved_student_files();
    document_.message(unsaved.empty() ? Severity::Info : Severity::Warning,
                      unsaved.empty() ? std::string(tr("Checking your work with the course's visible tests..."))
                                      : tr_format("Checking your saved files; not saved, so not checked: {files}",
                                                  {{"files", unsaved}}));
    return Check::yes();
  } catch (const std::exception& e) {
    document_.message(Severity::Error, tr_format("Check my work: {problem}", {{"problem", e.what()}}));
    return Check::no(e.what());
  }
}

void CheckRoom::stop() {
  if (!running()) return;
  process_.stop();
  announced_ = true;
  document_.message(Severity::Warning, tr("Check my work stopped: no verdict"));
}

void CheckRoom::poll() {
  process_.poll();
  if (running() || announced_) return;
  announced_ = true;
  if (const std::optional<GradeReport>& report = process_.report()) {
    const bool all = report->failed() == 0;
    document_.message(all ? Severity::Info : Severity::Warning,
                      tr_format("Check my work: {score}; {summary} (the Check tab)",
                                {{"score", score_line(*report)}, {"summary", summary_line(*report)}}));
  } else {
    document_.message(Severity::Error, tr("Check my work: the grader could not check your work (the Check tab)"));
  }
}

const FailingCase* CheckRoom::failing_case(size_t row) const {
  const std::optional<GradeReport>& report = process_.report();
  if (!report || row >= report->tests.size() || !report->tests[row].failing_case) return nullptr;
  return &*report->tests[row].failing_case;
}

CheckPanelView CheckRoom::view() const {
  CheckPanelView view;
  view.suite = suite_;
  // On the page the folder is the browser's own file system, a path that means nothing to the student.
  view.folder = host_files_on_users_disk() ? (started_ ? checked_folder_ : exercises_.session().folder()).string()
                                           : std::string(tr("this browser (the files you edited or dropped here)"));
  if (running()) {
    view.state = CheckPanelView::State::Running;
    view.done = process_.tests_done();
    view.total = process_.tests_total();
    view.running_test = process_.running_test();
    view.seconds = process_.seconds();
    return view;
  }
  if (!started_) return view;
  if (process_.stopped()) {
    view.state = CheckPanelView::State::Stopped;
    return view;
  }
  const std::optional<GradeReport>& report = process_.report();
  if (!report) {
    view.state = CheckPanelView::State::Problem;
    view.problem = process_.problem();
    return view;
  }
  view.state = CheckPanelView::State::Graded;
  view.total_line = score_line(*report) + "; " + summary_line(*report) + ".";
  view.not_shown = not_shown_sentence(report->not_shown);
  view.notes = report->output;
  std::istringstream lines(report->output);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("Missing: ")) view.warnings.push_back(line);
  }
  for (const TestResult& test : report->tests) {
    CheckPanelView::Row row;
    row.number = test.number;
    row.name = test.name;
    row.points = points_text(test);
    row.passed = test.passed;
    row.text = test.output;
    if (test.failing_case) row.case_input = test.failing_case->input;
    view.rows.push_back(std::move(row));
  }
  return view;
}

std::string CheckRoom::test_name(size_t row) const {
  const std::optional<GradeReport>& report = process_.report();
  if (!report || row >= report->tests.size()) return "";
  return report->tests[row].number + " " + report->tests[row].name;
}

std::optional<size_t> CheckRoom::row_of(const std::string& number) const {
  const std::optional<GradeReport>& report = process_.report();
  if (!report) return std::nullopt;
  for (size_t row = 0; row < report->tests.size(); ++row) {
    if (report->tests[row].number == number) return row;
  }
  return std::nullopt;
}

void CheckRoom::draw_tab(UiProbe& probe) {
  const CheckPanelActions actions = draw_check_panel_contents(view(), panel_, &probe);
  if (actions.stop) stop();
  if (actions.check) start();
  if (actions.open_case) case_request_ = actions.open_case;
}

}  // namespace meshedit
