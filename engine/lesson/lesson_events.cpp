// Matching app events against what a lesson step waits for, and the words the panel and the headless
// command use for a wait (see lesson_events.h).
#include "lesson/lesson_events.h"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "core/value_format.h"

namespace meshedit {
namespace {

std::string with_article(ElementKind kind) {
  const std::string noun = kind_name(kind);
  return (kind == ElementKind::Edge ? "an " : "a ") + noun;
}

// "a vertex", "e7" or "an element".
std::string element_words(const LessonWait& wait) {
  if (wait.element.valid()) return format_id(wait.element);
  if (wait.element_kind) return with_article(*wait.element_kind);
  return "an element";
}

bool element_matches(const LessonWait& wait, ElementRef element) {
  if (!element.valid()) return false;
  if (wait.element.valid()) return element == wait.element;
  if (wait.element_kind) return element.kind == *wait.element_kind;
  return true;
}

}  // namespace

bool same_key(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

bool LessonWait::matches(const LessonEvent& event) const {
  switch (kind) {
    case Kind::Command: return event.kind == LessonEvent::Kind::Command && event.name == name;
    case Kind::Key: return event.kind == LessonEvent::Kind::Key && same_key(event.name, name);
    case Kind::Button: return event.kind == LessonEvent::Kind::Button && event.name == name;
    case Kind::Click: return event.kind == LessonEvent::Kind::Click && element_matches(*this, event.element);
    case Kind::Selection: return event.kind == LessonEvent::Kind::Selection && element_matches(*this, event.element);
    case Kind::Choice:
      return event.kind == LessonEvent::Kind::Choice &&
             std::find(options.begin(), options.end(), event.name) != options.end();
    case Kind::Pick: return event.kind == LessonEvent::Kind::Click && event.element.valid();
    case Kind::CurvePick: return event.kind == LessonEvent::Kind::CurveClick;
    case Kind::Answer: return event.kind == LessonEvent::Kind::Value;
    default: return false;
  }
}

bool LessonWait::selection_matches(ElementRef selected) const {
  return kind == Kind::Selection && element_matches(*this, selected);
}

std::string LessonWait::describe() const {
  switch (kind) {
    case Kind::None: return "";
    case Kind::Key: return "key " + name;
    case Kind::Command: {
      const Command* waited = find_lesson_command(name);
      return "the command " + name + (waited ? " (" + command_place(*waited) + ")" : std::string());
    }
    case Kind::Click: return "a click on " + element_words(*this);
    case Kind::Selection: return "the selection of " + element_words(*this);
    case Kind::Condition: return "a condition";
    case Kind::Button: return "the " + name + " button";
    case Kind::Animation: {
      return "an animation (" + format_rounded(seconds) + " s)";
    }
    case Kind::Choice: {
      std::string list;
      for (const std::string& option : options) list += (list.empty() ? "" : ", ") + option;
      return "a choice (" + list + ") in '" + question + "'";
    }
    case Kind::Pick: return "a click answering '" + question + "'";
    case Kind::CurvePick: return "a click on the curve answering '" + question + "'";
    case Kind::Answer: return (components == 1 ? "a number answering '" : "a point answering '") + question + "'";
    case Kind::YourTurn: return "the student's " + name + " to give the reference's answer";
    case Kind::YourTurnRunning: return "the student's " + name + " to finish running";
  }
  return "";
}

}  // namespace meshedit
