// `meshedit lesson FILE --headless [--answers ANSWERS.lua] [--student DIR]`: runs a lesson through every step with no
// window (engine/lesson/lesson_headless.h), printing what each step says; your_turn runs the student's files from DIR
// (default: scripts/student, the window's Exercises folder). Exit 0 when every step ran to its end, 1 with the
// failing step's file:line on stderr otherwise. The window mode of a lesson is opened with
// `meshedit FILE.lua`; without --headless this command says so (usage error, exit 2).
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "document/student_file.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "lesson/lesson_headless.h"
#include "script/lua_runtime.h"

namespace meshedit {

int run_lesson(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const bool headless = take_flag(args, "--headless");
  const std::optional<std::string> answers = take_option(args, "--answers");
  const std::optional<std::string> student = take_option(args, "--student");
  reject_unknown_options(args);
  if (args.size() != 1) {
    throw UsageError(
        "lesson needs one file: meshedit lesson FILE.lua --headless [--answers ANSWERS.lua] [--student DIR]");
  }
  if (!headless) {
    throw UsageError("lesson runs with --headless here; open a lesson in the window with: meshedit " + args.front());
  }
  std::optional<std::filesystem::path> answers_path;
  if (answers) answers_path = *answers;
  const std::filesystem::path student_folder = student ? std::filesystem::path(*student) : default_student_folder();
  if (!std::filesystem::is_directory(student_folder)) {
    throw UsageError("--student " + student_folder.string() + ": no such folder");
  }
  // your_turn may ask for an exercise defined in Lua: each one that does not load is named, and left out.
  for (const std::string& error : load_exercise_folder(default_exercise_folder())) {
    std::cerr << "meshedit: exercise: " << error << '\n';
  }
  const HeadlessOutcome outcome =
      run_lesson_headless(args.front(), answers_path, out, LessonRunner::default_limits(), student_folder);
  out.flush();
  for (const std::string& problem : outcome.text_problems) std::cerr << "meshedit: warning: " << problem << '\n';
  if (!outcome.failure.empty()) throw ScriptError(outcome.failure);
  return 0;
}

}  // namespace meshedit
