// `meshedit run SCRIPT.lua [ARGS...]`: runs a Lua script with no window. Everything after the script path
// is the script's (in `arg` and `...`, as lua.c does), even words starting with '-'. `print` writes to
// `out`; a Lua error (with its file:line) propagates as ScriptError, which run_cli prints on stderr with
// exit status 1.
// `meshedit run REPORT.meshedit`: a bug report's last run made again with the student's code in it, its diagnosis
// printed (document/bug_report.h); exit status 0 once it ran, whatever the diagnosis, 1 for a report that cannot be
// read.
#include <iostream>
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "core/translation.h"
#include "document/bug_report.h"
#include "document/settings.h"
#include "document/student_file.h"
#include "exercise/exercise_registry.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"

namespace meshedit {
namespace {

int replay_report(const std::filesystem::path& path, std::ostream& out) {
  const std::string name = path.filename().string();
  const BugReport report = read_bug_report(path);
  // The replay's diagnosis in the words the student's window used, so the two compare.
  set_text_language(language_by_code(report.language).value_or(Language::English));
  // Its run may be of an exercise defined in Lua: each one that does not load is named, and left out.
  for (const std::string& error : load_exercise_folder(default_exercise_folder())) {
    std::cerr << "meshedit: exercise: " << error << '\n';
  }
  out << replay_bug_report(report, name, window_student_limits(Settings::kDefaultStudentCodeSeconds)).text;
  out.flush();
  return 0;
}

}  // namespace

int run_run(const std::vector<std::string>& args, std::ostream& out) {
  if (args.empty()) throw UsageError("run needs a script: meshedit run SCRIPT.lua [ARGS...]");
  if (std::filesystem::path(args.front()).extension() == kBugReportExtension) {
    if (args.size() > 1) throw UsageError("run " + args.front() + " takes no more arguments");
    return replay_report(args.front(), out);
  }
  const std::vector<std::string> script_args(args.begin() + 1, args.end());
  ScriptRuntime lua;
  lua.set_print([&out](const std::string& line) { out << line << '\n'; });
  try {
    lua.run_file(args.front(), script_args);
  } catch (...) {
    out.flush();  // what the script printed before failing comes before the error
    throw;
  }
  out.flush();
  return 0;
}

}  // namespace meshedit
