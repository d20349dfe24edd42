// The command-line commands, one function each. Each takes the arguments after the command name,
// writes its report to `out`, returns the exit status, and throws UsageError for bad arguments or the
// io/core errors for bad files (run_cli turns both into one line on stderr).
#pragma once

#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshedit {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The window (no command, or a file as the first argument).
int run_window(const std::vector<std::string>& arguments, std::ostream& out);
int run_demo(const std::vector<std::string>& arguments, std::ostream& out);
int run_info(const std::vector<std::string>& arguments, std::ostream& out);
int run_convert(const std::vector<std::string>& arguments, std::ostream& out);
int run_subdivide(const std::vector<std::string>& arguments, std::ostream& out);
int run_triangulate(const std::vector<std::string>& arguments, std::ostream& out);
int run_repair(const std::vector<std::string>& arguments, std::ostream& out);
int run_render(const std::vector<std::string>& arguments, std::ostream& out);
// A Lua script with no window; ScriptError (its file:line message) when the script fails.
int run_run(const std::vector<std::string>& args, std::ostream& out);
// `grade` (cli_grade.cpp lists its arguments): 0 when grading worked, whatever the score; GradeError (exit status 1)
// when grading itself could not be done.
int run_grade(const std::vector<std::string>& arguments, std::ostream& out);
// `writeup --submission DIR -o OUT [--settings FILE]` (cli_writeup.cpp): the write-up made by the student's functions;
// 0 when every figure is the reference's, 1 when some figure is not (the files are still written).
int run_writeup(const std::vector<std::string>& arguments, std::ostream& out);
// app/cli_class_report.cpp
int run_class_report(const std::vector<std::string>& arguments, std::ostream& out);
// `lesson FILE --headless [--answers ANSWERS.lua] [--student DIR]`: every step with scripted answers, your_turn with
// the student folder DIR; 0 when all pass. UsageError without --headless; ScriptError (a step failed: its file:line).
int run_lesson(const std::vector<std::string>& arguments, std::ostream& out);
// `paths`: the folders of lessons, assets, shaders, student and exercise files and fonts this binary uses.
int run_paths(const std::vector<std::string>& args, std::ostream& out);

// Argument helpers shared by the commands.
// Removes `--name VALUE` (or `-n VALUE` for the short name) from args and returns VALUE.
std::optional<std::string> take_option(std::vector<std::string>& args, const std::string& name,
                                       const std::string& short_name = "");
// Removes `--name` from args and says whether it was there.
bool take_flag(std::vector<std::string>& args, const std::string& name);
// Parses a whole non-negative integer no larger than `max`, or throws UsageError naming the option.
int parse_count(const std::string& text, const std::string& option, int max);
// Removes `--resolution N` (tessellation per Bézier patch) and returns N, or the default (16).
int take_resolution_option(std::vector<std::string>& args);
// Throws UsageError if any argument starting with '-' is left.
void reject_unknown_options(const std::vector<std::string>& args);

}  // namespace meshedit
