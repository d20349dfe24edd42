// data_folders: where the program finds the files it ships with (lessons/, shaders/, assets/, scripts/student,
// scripts/exercises, fonts/, tests/grading/suites), wherever it runs from. The candidates for a folder NAME, in order:
//   1. <the running program's folder>/NAME: a program copied beside its files;
//   2. <the running program's folder>/../share/meshedit/NAME: the installed layout (`cmake --install`: bin/meshedit
//      and share/meshedit/...);
//   3. <MESHEDIT_DATA_DIR>/NAME, compiled in: the source tree, so a program run from its build tree finds the sources'
//      files (on the web, the folder of the page's packaged files).
// The running program's folder is known on Linux (/proc/self/exe), macOS and Windows; elsewhere, and on the web, only
// the compiled-in folder is a candidate. Nothing here caches: each call looks again.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

namespace meshedit {

// The folder of the running program's file, or empty where it cannot be known.
std::filesystem::path program_folder();

// Every candidate for NAME (a relative path such as "shaders" or "scripts/student"), in the order above.
std::vector<std::filesystem::path> data_folder_candidates(std::string_view name);

// The first candidate for NAME that is a folder, or the compiled-in one when none is.
std::filesystem::path data_folder(std::string_view name);

}  // namespace meshedit
