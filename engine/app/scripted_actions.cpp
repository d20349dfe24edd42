// Parsing of scripted GUI actions (see scripted_actions.h).
#include "app/scripted_actions.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace meshedit {
namespace {

// Number of arguments each verb takes; -1 means "the rest of the line, at least one word".
const std::map<std::string, int>& arities() {
  static const std::map<std::string, int> table = {
      {"frames", 1},          {"key", 1},           {"select", 1},         {"click", 2},
      {"hover", 2},           {"open", 1},          {"save", 1},           {"screenshot", 1},
      {"expect-selected", 1}, {"expect-field", 3},  {"expect-changed", 2}, {"expect-message", -1},
      {"expect-valid", 0},    {"quit", 0},           {"console", -1},       {"expect-console", -1},
      {"lesson-next", 0},     {"lesson-back", 0},   {"lesson-button", -1}, {"expect-lesson-step", 2},
      {"expect-lesson-said", -1}, {"exercise", 2},  {"run-mine", 0},      {"run-reference", 0},
      {"replay-start", 0},    {"replay-step", 1},   {"replay-finish", 0}, {"expect-mine", -1},
      {"orbit", 2},           {"expect-gpu-update", 1}, {"click-on", 1},     {"layout-json", 1},
      {"window-size", 2},     {"up-axis", 1},       {"expect-up-axis", -1},
      {"animate-edits", 1},   {"lesson-choose", -1},    {"lesson-answer", -1},    {"expect-lesson-feedback", -1},
      {"expect-lesson-hint", -1}, {"expect-lesson-live", -1}, {"curve-t", 1},     {"lesson-show-mine", 0},
      {"expect-exercise-run", -1}, {"open-repaired", 0}, {"triangulate", 0},
      {"repair-row", 1},
  };
  return table;
}

}  // namespace

std::vector<ScriptedAction> parse_actions(const std::string& text, const std::string& name) {
  std::vector<ScriptedAction> actions;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    ScriptedAction action;
    if (!(words >> action.verb) || action.verb[0] == '#') continue;
    action.source = name + ":" + std::to_string(number);
    for (std::string word; words >> word;) action.args.push_back(word);
    const auto arity = arities().find(action.verb);
    if (arity == arities().end()) throw std::runtime_error(action.source + ": unknown action '" + action.verb + "'");
    const int wanted = arity->second;
    if ((wanted >= 0 && int(action.args.size()) != wanted) || (wanted < 0 && action.args.empty())) {
      throw std::runtime_error(action.source + ": '" + action.verb + "' takes " +
                               (wanted < 0 ? std::string("some text") : std::to_string(wanted) + " argument(s)"));
    }
    actions.push_back(std::move(action));
  }
  return actions;
}

std::vector<ScriptedAction> read_actions(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the action script");
  std::stringstream text;
  text << in.rdbuf();
  return parse_actions(text.str(), path);
}

}  // namespace meshedit
