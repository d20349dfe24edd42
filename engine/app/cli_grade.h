// `meshedit grade`: the autograder's command line (cli_grade.cpp); declared apart from cli_commands.h so
// the grading command stays in the files of its own job.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace meshedit {

// See cli_grade.cpp for the arguments. Returns 0 when grading worked, whatever the score; throws UsageError
// for bad arguments and GradeError (exit status 1 through run_cli) when grading itself could not be done.
int run_grade(const std::vector<std::string>& args, std::ostream& out);

}  // namespace meshedit
