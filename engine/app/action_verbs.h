// The verbs of scripted actions (scripted_actions.h) in one table: each verb's arguments, what it does (the table's
// usage text is the verbs' documentation) and its handler. parse_actions checks a script's lines against it and
// ActionPlayer runs each line through it.
//
// Invariants: a handler acts through the same EditorApp calls a key press, a click or a menu reaches; it returns ""
// when the action was done or its expectation held, else what was wrong (a failed expectation); it throws
// std::runtime_error when the action cannot be done at all (an unknown element, no such view). `frames` and `quit`
// steer the player itself and have no handler.
#pragma once

#include <span>
#include <string>

#include "app/scripted_actions.h"

namespace meshedit {

class EditorApp;

struct ActionVerb {
  const char* name;   // "click-on"
  int arity;          // the number of words after the verb; -1: the rest of the line, at least one word
  const char* usage;  // "click-on h12   a click where the element's label anchor is on screen ..."
  std::string (*run)(EditorApp& app, const ScriptedAction& action);  // nullptr for frames and quit
};

std::span<const ActionVerb> action_verbs();
// The verb named `name`, or nullptr.
const ActionVerb* find_action_verb(const std::string& name);

}  // namespace meshedit
