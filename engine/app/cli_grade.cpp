// `meshedit grade`: grades Lua submissions with an instructor's suite.
//
//   meshedit grade --suite SUITE.lua --submission DIR [--results results.json] [--junit FILE] [--tap] [--visible-only]
//                  [--report FILE] [--progress]
//   meshedit grade --suite SUITE.lua --submissions DIR... [--out FOLDER] [--jobs N] [--compare PREVIOUS_MARKS]
//
// --visible-only runs only the tests a student sees before the due date (a student's check before handing in); the
// report says how many tests and points it left out and when they will be shown. --report writes the whole report as
// MeshEdit's JSON (grade/report_json.h: each test's text and failing case), what the window's Check my work reads;
// --progress prints "meshedit grade: test 3 of 14 running: NAME" on stderr before each test and "... done: NAME" after.
// Before grading, each test worth points that the suite hides from students is a warning on stderr (Gradescope
// then hides the student's total too).
// One submission: prints the readable report (or, with --tap, only TAP) on `out`, ending with
// "N passed, N failed", and writes Gradescope's results.json (--results; default ./results.json) and JUnit XML
// (--junit). Each failed test whose input the grader kept gets a picture of it beside the reference's result and the
// student's, in its Markdown feedback and in pictures/ beside results.json (failure_pictures.h). A class: grades every
// folder in parallel processes (--jobs, default: the number of processors), writes FOLDER/<submission>/results.json for
// each, FOLDER/summary.csv + summary.json and the class report FOLDER/class.html + class.csv (grade/class_report.h;
// FOLDER defaults to ./grading-results; --compare adds what changed since the marks in PREVIOUS_MARKS), and prints one
// line per submission.
// The exit status says whether grading worked, not the score: 0 graded (even a submission that fails to
// load, crashes, hangs or runs out of memory: those tests fail, results.json is still written), 1 the grader
// could not grade (the suite does not load, a folder is missing, a file cannot be written), 2 bad arguments.
// Without a display or GL; nothing but the result files is written; student code runs only in child
// processes (engine/grade).
#include "app/cli_commands.h"

#include <iostream>
#include <memory>
#include <optional>

#include "app/failure_pictures.h"
#include "core/parallel_for.h"
#include "core/value_format.h"
#include "grade/class_grading.h"
#include "grade/class_report.h"
#include "grade/grader.h"
#include "grade/report_json.h"
#include "grade/results_writers.h"
#include "grade/submission.h"
#include "grade/suite.h"

namespace meshedit {
namespace {

// Removes `--submissions A B C` (every argument up to the next option) and returns the folders.
std::vector<std::string> take_list(std::vector<std::string>& args, const std::string& name) {
  std::vector<std::string> values;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != name) continue;
    size_t j = i + 1;
    while (j < args.size() && args[j].rfind("--", 0) != 0) values.push_back(args[j++]);
    if (values.empty()) throw UsageError(name + " needs at least one folder");
    args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(j));
    break;
  }
  return values;
}

int grade_one(Suite& suite, const std::string& folder, std::vector<std::string>& args, std::ostream& out) {
  const std::string results = take_option(args, "--results").value_or("results.json");
  const auto junit = take_option(args, "--junit");
  const bool tap = take_flag(args, "--tap");
  const auto report_file = take_option(args, "--report");
  GradeOptions options;
  options.visible_only = take_flag(args, "--visible-only");
  if (take_flag(args, "--progress")) {
    size_t total = 0;
    for (const TestSpec& spec : suite.tests()) total += !options.visible_only || spec.visibility == "visible" ? 1 : 0;
    auto done = std::make_shared<size_t>(0);
    options.on_test_start = [total, done](const TestSpec& spec) {
      std::cerr << "meshedit grade: test " << *done + 1 << " of " << total << " running: " << spec.name << std::endl;
    };
    options.on_test = [total, done](const TestResult& result) {
      std::cerr << "meshedit grade: test " << ++*done << " of " << total << " done: " << result.name << std::endl;
    };
  }
  reject_unknown_options(args);
  if (!args.empty()) throw UsageError("unexpected argument '" + args.front() + "'");
  const Submission submission = Submission::read(folder);
  out.flush();
  GradeReport report = grade(suite, submission, options);
  const std::string no_pictures = add_failure_pictures(report, std::filesystem::absolute(results).parent_path());
  if (!no_pictures.empty()) std::cerr << "meshedit grade: " << no_pictures << "\n";
  write_file_atomically(results, gradescope_json(report));
  if (junit) write_file_atomically(*junit, junit_xml(report));
  if (report_file) write_file_atomically(*report_file, encode_grade_report(report));
  out << (tap ? tap_text(report) : text_report(report));
  out.flush();
  return 0;
}

int grade_many(Suite& suite, const std::vector<std::string>& folders, std::vector<std::string>& args,
               std::ostream& out) {
  const std::string folder = take_option(args, "--out").value_or("grading-results");
  const auto compare = take_option(args, "--compare");
  if (compare && !std::filesystem::is_directory(*compare))
    throw UsageError("--compare " + *compare + ": no such folder");
  int jobs = hardware_threads();
  if (const auto text = take_option(args, "--jobs")) jobs = parse_count(*text, "--jobs", 256);
  if (jobs < 1) throw UsageError("--jobs must be at least 1");
  if (take_flag(args, "--visible-only")) throw UsageError("--visible-only is a student's check of one --submission");
  for (const char* single : {"--results", "--junit", "--tap", "--report", "--progress"}) {
    for (const auto& a : args) {
      if (a == single) throw UsageError(std::string(single) + " is for one --submission; a class gets --out");
    }
  }
  reject_unknown_options(args);
  if (!args.empty()) throw UsageError("unexpected argument '" + args.front() + "'");
  std::vector<std::filesystem::path> paths(folders.begin(), folders.end());
  out.flush();
  const std::vector<ClassEntry> entries = grade_class(suite, paths, folder, jobs, {}, add_failure_pictures);
  write_file_atomically(std::filesystem::path(folder) / "summary.csv", class_summary_csv(entries));
  write_file_atomically(std::filesystem::path(folder) / "summary.json", class_summary_json(entries));
  const ClassReport class_report = make_class_report(class_results(entries));
  const std::optional<ClassChanges> changes =
      compare ? std::optional(compare_class_reports(make_class_report(read_class_folder(*compare)), class_report))
              : std::nullopt;
  write_file_atomically(std::filesystem::path(folder) / "class.html",
                        class_report_html(class_report, changes ? &*changes : nullptr));
  write_file_atomically(std::filesystem::path(folder) / "class.csv", class_report_csv(class_report));
  size_t graded = 0, left_out = 0;
  for (const auto& e : entries) {
    if (e.status == "graded") {
      ++graded;
      out << e.name << ": " << format_number(e.score) << " / " << format_number(e.max_score) << " (" << e.passed
          << " passed, " << e.failed << " failed)\n";
    } else if (e.status == "not a folder") {
      ++left_out;
      out << e.name << ": left out: " << e.folder.string() << " is " << e.problem << "\n";
    } else {
      out << e.name << ": not graded: " << e.problem << "\n";
    }
  }
  out << graded << " of " << entries.size() - left_out << " submissions graded"
      << (left_out > 0 ? " (" + std::to_string(left_out) + " left out: not a folder)" : std::string())
      << "; summary in " << (std::filesystem::path(folder) / "summary.csv").string() << ", the class at a glance in "
      << (std::filesystem::path(folder) / "class.html").string() << "\n";
  out.flush();
  return graded + left_out == entries.size() ? 0 : 1;  // a stray file is named, not a failure of grading
}

}  // namespace

int run_grade(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const std::vector<std::string> many = take_list(args, "--submissions");
  const auto suite_path = take_option(args, "--suite");
  const auto one = take_option(args, "--submission");
  if (!suite_path) throw UsageError("grade needs --suite SUITE.lua");
  if (one.has_value() == !many.empty()) {
    throw UsageError("grade needs either --submission DIR or --submissions DIR...");
  }
  const auto language_option = take_option(args, "--language");
  std::optional<Language> language;
  if (language_option) {
    language = language_by_code(*language_option);
    if (!language || *language_option != language_code(*language)) {
      throw UsageError("--language " + *language_option + ": the feedback is written in en or zh");
    }
  }
  std::unique_ptr<Suite> suite = Suite::load(*suite_path);
  // The feedback's language: --language (the window's Check my work gives its own), else the suite's.
  for (const std::string& problem : set_text_language(language.value_or(suite->language()))) {
    std::cerr << "meshedit grade: warning: " << problem << "\n";
  }
  for (const std::string& warning : suite_warnings(*suite)) {
    std::cerr << "meshedit grade: warning: " << suite_path->c_str() << ": " << warning << "\n";
  }
  return one ? grade_one(*suite, *one, args, out) : grade_many(*suite, many, args, out);
}

}  // namespace meshedit
