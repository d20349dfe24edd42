// What a lesson step waits for (LessonWait) and what the app tells the runner (LessonEvent).
//
// Invariants:
// - Key names compare without regard to case, whole: "f" matches "F", "shift+L" matches "Shift+L", but
//   "L" never matches "shift+L". The app sends the names scripted actions use: "F", "ctrl+Z", "shift+L".
// - A click also selects: the app sends a Click and then a Selection for the same element. A click wait
//   is met only by a Click; a selection wait by a Selection (or by the selection already being right).
// - A wait on an element kind ("vertex") is met by any element of that kind; on an id ("e7") only by it;
//   "any" (or no kind and no id) by any element.
// - The questions (choose, pick, answer: lesson_questions.h) take any answer of their kind: a Choice event naming one
//   of the options, any Click, any Value text; a pick on the curve view (CurvePick) any CurveClick. Whether it is right
//   is the lesson's to say: a wrong one leaves the step waiting on the same question, with `tries` one more (a Value
//   that cannot be read as a number: not counted) and `feedback` saying what is wrong.
// - A question's hint is held back until the student has tried once (hint_shown); a wait_for's hint is the
//   instruction itself ("Press F") and shows at once.
// - A command wait is met by a Command event of the same name: the window sends one whenever that command
//   (document/command_table.h, lesson_can_wait) ran, from its menu, its key or a scripted verb (each also sends the
//   command's key as a Key event), and the headless answers that stand for them send it too.
// - A your_turn wait (lesson_your_turn.h) takes no event: the runner runs the student's file again when its stamp
//   (watched_stamp, read at most twice a second) changes. `name` is the file's name, `feedback` the last diagnosis.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/ids.h"
#include "document/command_table.h"
#include "script/file_stamp.h"

namespace meshedit {

struct LessonEvent {
  enum class Kind { Key, Click, Selection, Button, Choice, Value, Command, CurveClick };
  Kind kind = Kind::Key;
  std::string name;    // the key ("F", "shift+L"), the button label ("Continue"), the option chosen, the text typed,
                       // the command (a command_table.h name a lesson can wait for)
  ElementRef element;  // Click and Selection
  // CurveClick: where the curve view was clicked (curve coordinates), and how far from the curve (curve units) a
  // click still counts as on it (the window's pick radius in pixels over the view's scale).
  glm::dvec2 point{0.0};
  double radius = 0.0;

  static LessonEvent key(std::string name) { return {Kind::Key, std::move(name), {}}; }
  static LessonEvent click(ElementRef element) { return {Kind::Click, {}, element}; }
  static LessonEvent selection(ElementRef element) { return {Kind::Selection, {}, element}; }
  static LessonEvent button(std::string label) { return {Kind::Button, std::move(label), {}}; }
  static LessonEvent choice(std::string option) { return {Kind::Choice, std::move(option), {}}; }
  static LessonEvent value(std::string text) { return {Kind::Value, std::move(text), {}}; }
  static LessonEvent command(std::string name) { return {Kind::Command, std::move(name), {}}; }
  static LessonEvent curve_click(glm::dvec2 point, double radius) { return {Kind::CurveClick, {}, {}, point, radius}; }
};

struct LessonWait {
  enum class Kind {
    None,
    Key,
    Click,
    Selection,
    Condition,
    Button,
    Animation,
    Choice,
    Pick,
    CurvePick,
    Answer,
    YourTurn,
    YourTurnRunning,  // the student's code of a your_turn runs (LessonRunner::student_code_running)
    Command
  };
  Kind kind = Kind::None;
  std::string name;                         // Key: the key; Button: the label; Command: the command's name
  std::optional<ElementKind> element_kind;  // Click/Selection on any element of this kind
  ElementRef element;                       // Click/Selection on exactly this element (when valid)
  double seconds = 0.0, elapsed = 0.0;      // Animation: its length and how far it got
  std::string hint;                         // one line for the panel (the lesson's `hint`, or a default)
  std::string where;                        // "welcome.lua:12": where wait_for / animate / a question was called

  // The questions (Choice, Pick, Answer).
  std::string question;              // the text asked
  std::vector<std::string> options;  // Choice: the options, in the lesson's order
  size_t components = 1;             // Answer: 1 for a number, 2 or 3 for a point
  int tries = 0;                     // wrong answers so far
  std::string feedback;              // what the lesson said about the last wrong answer ("" before any)

  // YourTurn: the student's file and its stamp when it last ran (script/file_stamp.h), and the seconds since the
  // stamp was last read.
  std::string watched_file;
  FileStamp watched_stamp;
  double since_checked = 0.0;

  bool waiting() const { return kind != Kind::None; }
  bool is_question() const {
    return kind == Kind::Choice || kind == Kind::Pick || kind == Kind::CurvePick || kind == Kind::Answer;
  }
  // Whether the panel shows the hint: a question's only after one try; any other wait's at once.
  bool hint_shown() const { return !hint.empty() && (!is_question() || tries > 0); }
  // Whether `event` is what this wait is for (never true for Condition, Animation or None).
  bool matches(const LessonEvent& event) const;
  // Whether the selection being `selected` meets this wait (Selection waits only).
  bool selection_matches(ElementRef selected) const;
  // "key F", "the command linear (Subdivide > Linear subdivision)", "a click on a vertex", "a click on e7", "the
  // selection of an edge", "the selection of e7", "a condition", "the Continue button", "an animation (2 s)", "a
  // choice (h1, h2, h4) in 'Which...?'", "a click answering 'Click...'", "a click on the curve answering 'Click...'",
  // "a number answering 'What...?'", "a point answering 'Where...?'", "the student's flip.lua to give the reference's
  // answer"; "" for None.
  std::string describe() const;
};

// True when the two key names are the same, ignoring case.
bool same_key(const std::string& a, const std::string& b);

}  // namespace meshedit
