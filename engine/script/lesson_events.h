// What a lesson step waits for (LessonWait) and what the app tells the runner (LessonEvent).
//
// Invariants:
// - Key names compare without regard to case, whole: "f" matches "F", "shift+L" matches "Shift+L", but
//   "L" never matches "shift+L". The app sends the names scripted actions use: "F", "ctrl+Z", "shift+L".
// - A click also selects: the app sends a Click and then a Selection for the same element. A click wait
//   is met only by a Click; a selection wait by a Selection (or by the selection already being right).
// - A wait on an element kind ("vertex") is met by any element of that kind; on an id ("e7") only by it;
//   "any" (or no kind and no id) by any element.
#pragma once

#include <optional>
#include <string>

#include "core/ids.h"

namespace meshedit {

struct LessonEvent {
  enum class Kind { Key, Click, Selection, Button };
  Kind kind = Kind::Key;
  std::string name;     // the key ("F", "shift+L") or the button label ("Continue")
  ElementRef element;   // Click and Selection

  static LessonEvent key(std::string name) { return {Kind::Key, std::move(name), {}}; }
  static LessonEvent click(ElementRef element) { return {Kind::Click, {}, element}; }
  static LessonEvent selection(ElementRef element) { return {Kind::Selection, {}, element}; }
  static LessonEvent button(std::string label) { return {Kind::Button, std::move(label), {}}; }
};

struct LessonWait {
  enum class Kind { None, Key, Click, Selection, Condition, Button, Animation };
  Kind kind = Kind::None;
  std::string name;                         // Key: the key; Button: the label
  std::optional<ElementKind> element_kind;  // Click/Selection on any element of this kind
  ElementRef element;                       // Click/Selection on exactly this element (when valid)
  double seconds = 0.0, elapsed = 0.0;      // Animation: its length and how far it got
  std::string hint;                         // one line for the panel (the lesson's `hint`, or a default)
  std::string where;                        // "welcome.lua:12": where wait_for / animate was called

  bool waiting() const { return kind != Kind::None; }
  // Whether `event` is what this wait is for (never true for Condition, Animation or None).
  bool matches(const LessonEvent& event) const;
  // Whether the selection being `element` meets this wait (Selection waits only).
  bool selection_matches(ElementRef element) const;
  // "key F", "a click on a vertex", "a click on e7", "the selection of an edge", "the selection of e7",
  // "a condition", "the Continue button", "an animation (2 s)"; "" for None.
  std::string describe() const;
};

// True when the two key names are the same, ignoring case.
bool same_key(const std::string& a, const std::string& b);

}  // namespace meshedit
