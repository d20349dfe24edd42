// `meshedit lesson`: declared apart from cli_commands.h only because that header belongs to another job;
// it can move there (same signature and contract as the other commands).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace meshedit {

// `lesson FILE --headless [--answers ANSWERS.lua] [--student DIR]`: every step with scripted answers, your_turn with
// the student folder DIR; 0 when all pass.
// Throws UsageError (bad arguments, or no --headless) and ScriptError (a step failed: its file:line line).
int run_lesson(const std::vector<std::string>& args, std::ostream& out);

}  // namespace meshedit
