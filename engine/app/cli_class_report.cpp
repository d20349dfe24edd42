// `meshedit class-report RESULTS.json... [-o FOLDER] [--compare PREVIOUS_MARKS]`: the class at a glance
// (grade/class_report.h) from results files made anywhere (`meshedit grade --submissions`, Gradescope's export, any job
// runner): FOLDER/class.html and FOLDER/class.csv (FOLDER defaults to ./class-report). A file is named after its folder
// when it is called results.json (marks/alice/results.json is alice), else after its own name. A file that cannot be
// read is listed as not read, with why, and the rest of the report is made. --compare adds what changed since the marks
// in PREVIOUS_MARKS (a folder `grade --submissions --out` wrote: PREVIOUS_MARKS/NAME/results.json). Prints how many
// were read and where the report is. Exit status: 0 the report was written (whatever the files held), 1 it could not be
// written, 2 bad arguments.
#include <filesystem>
#include <optional>
#include <ostream>

#include "app/cli_commands.h"
#include "grade/class_report.h"
#include "grade/results_writers.h"

namespace meshedit {

int run_class_report(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const std::filesystem::path folder = take_option(args, "--output", "-o").value_or("class-report");
  const auto compare = take_option(args, "--compare");
  reject_unknown_options(args);
  if (args.empty()) throw UsageError("class-report needs results files (marks/*/results.json)");
  if (compare && !std::filesystem::is_directory(*compare))
    throw UsageError("--compare " + *compare + ": no such folder");
  std::vector<ClassResult> results;
  for (const std::string& file : args) results.push_back(read_class_result_file(file));
  const ClassReport report = make_class_report(std::move(results));
  const std::optional<ClassChanges> changes =
      compare ? std::optional(compare_class_reports(make_class_report(read_class_folder(*compare)), report))
              : std::nullopt;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  write_file_atomically(folder / "class.html", class_report_html(report, changes ? &*changes : nullptr));
  write_file_atomically(folder / "class.csv", class_report_csv(report));
  size_t read = 0;
  for (const ClassResult& result : report.results) read += result.problem.empty() ? 1 : 0;
  out << read << " of " << report.results.size() << " results files read; " << report.mistakes.size()
      << (report.mistakes.size() == 1 ? " kind of mistake" : " kinds of mistake") << "; the report is "
      << (folder / "class.html").string() << " and class.csv\n";
  return 0;
}

}  // namespace meshedit
