// The "Check" tab: File > Check my work's verdict, as the grader gives it. What it draws comes in a CheckPanelView
// (plain text, made by the window from the grader's report), so the tab shows the grader's words and nothing else.
//
// Invariants:
// - The tab draws and forwards clicks: Check again, Stop and "Open in Exercises" are returned as CheckPanelActions,
//   never done here.
// - While a check runs, the tab says so with its progress and a Stop button; the window keeps drawing (the run is in a
//   process of its own).
// - Each test is one row: passed or not, its points ("2/2"), its number and name; a row opens to the grader's text for
//   it (the same words as `meshedit grade`), with "Open in Exercises" when a failed test's input can be opened. The
//   first failed test's row is open; the others open with a click, so the list stays an overview.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/element_link.h"

namespace meshedit {

struct CheckPanelView {
  enum class State { NotRun, Running, Graded, Problem, Stopped };
  State state = State::NotRun;
  std::filesystem::path suite;  // the suite's file
  std::string folder;           // the student's folder
  size_t done = 0, total = 0;
  std::string running_test;  // the name of the test running now (while running), if known
  double seconds = 0.0;
  std::string total_line;             // "Score: 31 of 33 points; 13 of 14 tests passed."
  std::string not_shown;              // "Not run here: 6 more tests, 8 points, shown after the due date; ..."
  std::string notes;                  // the grader's top-level text (the files found, what is missing)
  std::vector<std::string> warnings;  // its lines the student must see at once: "Missing: split.lua (...)"
  std::string problem;                // why the grader could not grade
  struct Row {
    std::string number, name;
    std::string points;  // "2 / 2", "0 / 3", "+1 (extra credit)"
    bool passed = false;
    std::string text;        // the grader's feedback for the test
    std::string case_input;  // "e5 of a mesh with 12 faces" when the failing case can be opened; "" otherwise
  };
  std::vector<Row> rows;
};

struct CheckPanelActions {
  bool check = false;  // Check my work (again)
  bool stop = false;
  std::optional<size_t> open_case;  // the row whose "Open in Exercises" was clicked
};

struct CheckPanelState {
  bool open = false;
};

// A test's row as the tab shows it: "FAILED (0/2) 4.1: flip: interior edge".
std::string check_row_label(const CheckPanelView::Row& row);
// Every word the tab shows (its state, the total, what was not run, the problem, each row's label and text), one line
// each: what tests and scripted actions read.
std::string check_panel_text(const CheckPanelView& view);

// Draws the tab's contents into the current window.
CheckPanelActions draw_check_panel_contents(const CheckPanelView& view, CheckPanelState& state, UiProbe* probe);

}  // namespace meshedit
