// Scripted actions: how GUI tests (and bug reports) drive the window without a person, through the same
// handlers a key press or a click reaches. `meshedit FILE --actions script.txt` runs one action per line
// between frames, then closes the window; the exit status is 0 when every `expect` held, 3 otherwise.
//
// A script is one action per line: a verb and its words, separated by spaces; `#` starts a comment line. The verbs,
// their words and what each does are the table in action_verbs.cpp ("click-on h12", "expect-message TEXT...").
#pragma once

#include <string>
#include <vector>

namespace meshedit {

struct ScriptedAction {
  std::string verb;
  std::vector<std::string> args;
  std::string source;  // "script.txt:12", for messages
  // The arguments from args[first] on, joined by single spaces ("" when there are none): a verb's text argument.
  std::string words(size_t first = 0) const;
};

// Parses a script; throws std::runtime_error("script.txt:4: unknown action 'klick'") on a bad line.
std::vector<ScriptedAction> parse_actions(const std::string& text, const std::string& name);
std::vector<ScriptedAction> read_actions(const std::string& path);

}  // namespace meshedit
