// Parsing of scripted GUI actions (see scripted_actions.h).
#include "app/scripted_actions.h"

#include <sstream>
#include <stdexcept>

#include "app/action_verbs.h"
#include "core/file_bytes.h"

namespace meshedit {

std::string ScriptedAction::words(size_t first) const {
  std::string text;
  for (size_t i = first; i < args.size(); ++i) text += (i > first ? " " : "") + args[i];
  return text;
}

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
    const ActionVerb* verb = find_action_verb(action.verb);
    if (!verb) throw std::runtime_error(action.source + ": unknown action '" + action.verb + "'");
    const int wanted = verb->arity;
    if ((wanted >= 0 && int(action.args.size()) != wanted) || (wanted < 0 && action.args.empty())) {
      throw std::runtime_error(action.source + ": '" + action.verb + "' takes " +
                               (wanted < 0 ? std::string("some text") : std::to_string(wanted) + " argument(s)"));
    }
    actions.push_back(std::move(action));
  }
  return actions;
}

std::vector<ScriptedAction> read_actions(const std::string& path) {
  const FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw std::runtime_error(path + ": cannot open the action script");
  return parse_actions(file.bytes, path);
}

}  // namespace meshedit
