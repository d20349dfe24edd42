// CheckRoom: File > Check my work. Owns the check's run (check_process.h: the grader in a process of its own), the
// suite it runs (the course's whole assignment, tests/grading/suites/all.lua found as the program's other files are, or
// the suite the window was started with: meshedit --suite FILE), the last verdict, and the Check tab's state.
//
// Invariants:
// - The check runs the student's saved files in the Exercises tab's folder: unsaved text in Your code is never run, and
//   the status line says which files were not saved when a check starts.
// - The window never waits for it: poll() (once per frame) takes the progress and the verdict; Stop ends it at once.
// - The verdict is the grader's: the tab's rows come from the report `meshedit grade --visible-only` writes, word for
//   word, and the status line gives its total.
// - Nothing here throws; every outcome is in the status line and the tab.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "app/check_process.h"
#include "core/check.h"
#include "grade/grade_types.h"
#include "ui/check_panel.h"

namespace meshedit {

class DocumentRoom;
class ExerciseRoom;

class CheckRoom {
 public:
  CheckRoom(DocumentRoom& document, ExerciseRoom& exercises);

  // The suite the check runs, and the program that runs it (tests point it at the built meshedit).
  const std::filesystem::path& suite() const { return suite_; }
  void set_suite(std::filesystem::path suite) { suite_ = std::move(suite); }
  void set_program(std::filesystem::path program) { program_ = std::move(program); }

  static bool available() { return CheckProcess::available(); }
  // Starts a check (a running one is stopped first) and opens the tab; refused when the suite is missing or the grader
  // cannot be started.
  Check start();
  void stop();
  bool running() const { return process_.running(); }
  // Per frame: the progress, and the verdict once the run ended (said in the status line).
  void poll();

  const std::optional<GradeReport>& report() const { return process_.report(); }
  CheckPanelState& panel() { return panel_; }
  // The tab's contents: Check again and Stop are done here; "Open in Exercises" is kept for the window, which opens
  // the case (take_case_request).
  void draw_tab(UiProbe& probe);
  std::optional<size_t> take_case_request() { return std::exchange(case_request_, std::nullopt); }
  // The failing case of row `row` of the last report, and that row's test ("1.2 flip: interior edge"); nullptr when
  // it has none.
  const FailingCase* failing_case(size_t row) const;
  std::string test_name(size_t row) const;
  // The tab's words (ui/check_panel.h's check_panel_text), and the row of test `number` ("4.1"), if any.
  std::string text() const { return check_panel_text(view()); }
  std::optional<size_t> row_of(const std::string& number) const;

 private:
  CheckPanelView view() const;

  DocumentRoom& document_;
  ExerciseRoom& exercises_;
  std::filesystem::path suite_;
  std::filesystem::path program_;
  CheckProcess process_;
  std::filesystem::path checked_folder_;
  bool started_ = false;   // a check was started since the window opened
  bool announced_ = true;  // the last run's end was said in the status line
  CheckPanelState panel_;
  std::optional<size_t> case_request_;
};

}  // namespace meshedit
