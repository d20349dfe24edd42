// What a step shows in the lesson panel, in the order the step made it: say() text, live() text, plot{} pictures and
// the questions the student has answered (choose, pick, answer); and each your_turn run with its verdict and the
// exercise's input. Plain data: the runner fills it, the panel, the window and the headless command read it.
//
// Invariants:
// - A step's blocks belong to that step: the runner empties them when a step starts (Next, Back, go_to, reload), with
//   the host's marks, so a step rebuilds everything it shows.
// - LessonBlock::index is an index into the runner's list of that kind (said, lives, plots, answered), which only grows
//   while the step runs.
// - A live block or a plot's marker with an `error` is never evaluated again in its step; its text or marker keeps the
//   last value it had.
// - A plot's samples are taken once, when plot{} runs (x from x_min to x_max in equal steps, every value finite); only
//   its marker follows the view.
// - A YourTurnVerdict's exercise_input is the input both runs of it worked on: the copy your_turn made when it was
//   called, shared by every run of that your_turn and never changed (its mesh is const), so the window can run the
//   same check on the same input (the Exercises tab, the curve and patch views' "mine").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/translation.h"
#include "exercise/exercises.h"
#include "script/file_stamp.h"

namespace meshedit {

struct LessonBlock {
  enum class Kind { Text, Live, Plot, Answered };
  Kind kind = Kind::Text;
  size_t index = 0;
};

// live(function() ... end): the function's value as text, evaluated again every frame.
struct LessonLive {
  int function_ref = -2;  // LUA_NOREF: the function in the registry
  std::string where;      // "lesson.lua:12", where live() was called
  std::string text;       // the latest value (tostring, or the English of a table of languages)
  LocalText local;        // the latest value in each language (local.english() == text)
  std::string error;      // "lesson.lua:13: ..." once it failed: it is not evaluated again
};

struct LessonPlotCurve {
  std::string label;
  glm::vec3 colour{1.0f};          // a dark-theme swatch for a colour name (the panel shows it in its theme's shade)
  std::vector<glm::dvec2> points;  // (x, f(x)), x increasing
};

// plot{...}: curves sampled once, and an optional marker (a vertical line at x = marker()) that follows the view.
struct LessonPlot {
  std::string title;
  std::string where;  // "lesson.lua:20", where plot{} was called
  glm::dvec2 x_range{0.0, 1.0};
  glm::dvec2 y_range{0.0, 1.0};  // the lesson's y = {lo, hi}, or the samples' own range
  std::vector<LessonPlotCurve> curves;
  int marker_ref = -2;           // LUA_NOREF when the plot has no marker
  std::optional<double> marker;  // the marker's latest x (nullopt: its function gave nil)
  std::string error;             // the marker's error, once it failed
};

// One judgement of an answer to choose{}, pick{} or answer{}.
struct LessonJudgement {
  std::string question;  // the question's text
  std::string given;     // what the student gave: the option, the element's id, the text typed
  bool right = false;
  std::string feedback;  // what the lesson says about it ("" when it says nothing about a right answer)
};

// One run of the student's file by your_turn (lesson_your_turn.h): the same verdict and words as the Exercises tab.
struct YourTurnVerdict {
  Exercise exercise = Exercise::FlipEdge;
  ExerciseInput exercise_input;  // what mine and the reference ran on (for a mesh: its mesh and element)
  std::string file;              // "flip.lua"
  std::string function;          // "flip_edge"
  std::string input;             // ExerciseInput::describe: "e0 of a mesh with 2 faces"
  bool right = false;
  std::string feedback;  // wrong: compare()'s diagnosis (or the file's error, file:line); right: ""
  std::string where;     // "4_edge_flip.lua:370": the your_turn call
  size_t block = 0;      // how many blocks the step showed before this run (where it goes among them)
  std::string path;      // the file run, and its stamp before the run (what a wait watches)
  FileStamp stamp;
};

// The value of a plot's curve at x, by straight lines between its samples (clamped to its ends); nullopt when it has
// no samples.
std::optional<double> plot_value(const LessonPlotCurve& curve, double x);

}  // namespace meshedit
