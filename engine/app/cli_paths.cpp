// `meshedit paths`: the folders the program reads its own files from, one line each ("lessons  /usr/share/..."), as
// core/data_folders.h finds them for this binary: beside it, in the installed layout, or in the source tree.
#include <filesystem>
#include <iomanip>
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/data_folders.h"
#include "document/student_file.h"
#include "ui/fonts.h"

namespace meshedit {

int run_paths(const std::vector<std::string>& args, std::ostream& out) {
  reject_unknown_options(args);
  if (!args.empty()) throw UsageError("paths takes no arguments");
  const struct {
    const char* name;
    std::filesystem::path folder;
  } folders[] = {
      {"lessons", lessons_dir()},
      {"assets", assets_dir()},
      {"shaders", data_folder("shaders")},
      {"scripts/student", default_student_folder()},
      {"scripts/exercises", default_exercise_folder()},
      {"fonts", font_folder()},
      {"tests/grading/suites", data_folder("tests/grading/suites")},
  };
  for (const auto& [name, folder] : folders) out << std::left << std::setw(22) << name << folder.string() << "\n";
  return 0;
}

}  // namespace meshedit
