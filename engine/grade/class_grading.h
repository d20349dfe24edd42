// Grading a whole class: many submission folders against one suite, several at a time, each in its own
// worker process, with one results.json per submission and a summary of all of them (CSV and JSON).
//
// Invariants:
// - A worker grades one submission (grade() forks its tests as usual) and writes that submission's own
//   results.json (in out/<name>/); student code never runs in a worker, only in the workers' children. The
//   summary is written by the calling process alone, from the results files, after every worker ended.
// - At most `jobs` workers run at once. A worker that fails (its results.json is missing or unreadable) is
//   listed with status "error" and a reason; the others are unaffected.
// - A path that is not a folder (a stray file among the folders) is listed with status "not a folder" and why: no
//   worker grades it and nothing is written for it (no out/<name>/).
// - Submission names are the folders' base names; two folders with the same base name get "name", "name-2".
// - Rows are in the order the folders were given.
// - `finish`, when given, sees each report in its worker before its results.json is written and may change its
//   feedback (the command line adds the failure pictures there, into out/<name>/pictures/); what it returns, when
//   not "", goes to stderr as "meshedit grade: <name>: ..." and the submission is graded all the same.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "grade/class_report.h"
#include "grade/grader.h"
#include "grade/suite.h"

namespace meshedit {

struct ClassEntry {
  std::string name;  // the submission's name (its folder's base name)
  std::filesystem::path folder;
  std::filesystem::path results;  // out/<name>/results.json
  std::string status = "error";   // "graded", "error" or "not a folder"
  std::string problem;            // why, when not "graded"
  double score = 0.0;
  double max_score = 0.0;
  size_t passed = 0;
  size_t failed = 0;
};

// Given a report and the folder its results.json goes to; returns "" or a sentence on what it could not do.
using FinishReport = std::function<std::string(GradeReport& report, const std::filesystem::path& folder)>;

std::vector<ClassEntry> grade_class(Suite& suite, const std::vector<std::filesystem::path>& folders,
                                    const std::filesystem::path& out, int jobs, const GradeOptions& options = {},
                                    const FinishReport& finish = nullptr);

std::string class_summary_csv(const std::vector<ClassEntry>& entries);
// The entries' results files read for the class report (grade/class_report.h); a submission not graded is one not
// read, with its problem.
std::vector<ClassResult> class_results(const std::vector<ClassEntry>& entries);
std::string class_summary_json(const std::vector<ClassEntry>& entries);

}  // namespace meshedit
