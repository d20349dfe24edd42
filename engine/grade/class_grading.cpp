// grade_class: worker processes over many submissions, and the class summary (see class_grading.h).
#include "grade/class_grading.h"

#include <cerrno>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/file_bytes.h"
#include "core/text_escapes.h"
#include "core/value_format.h"
#include "grade/results_writers.h"

namespace meshedit {
namespace {

// What a worker does: grade one submission and write its results.json. Returns the exit status.
int work(Suite& suite, const ClassEntry& entry, const GradeOptions& options, const FinishReport& finish) {
  try {
    const Submission submission = Submission::read(entry.folder);
    GradeOptions quiet = options;
    quiet.on_test = nullptr;
    GradeReport report = grade(suite, submission, quiet);
    if (finish) {
      const std::string problem = finish(report, entry.results.parent_path());
      if (!problem.empty()) std::cerr << "meshedit grade: " << entry.name << ": " << problem << "\n";
    }
    write_file_atomically(entry.results, gradescope_json(report));
    return 0;
  } catch (const std::exception& e) {
    // The reason travels as a file next to where results.json would be (the worker is trusted).
    std::ofstream(entry.results.string() + ".error") << e.what() << "\n";
    return 1;
  }
}

void read_back(ClassEntry& entry, int status) {
  const FileBytes results = read_file_bytes(entry.results);
  if (!results.ok()) {
    const FileBytes reason = read_file_bytes(entry.results.string() + ".error");
    const std::string text = reason.bytes.substr(0, reason.bytes.find('\n'));
    entry.problem = !text.empty() ? text : "the grading process ended with status " + std::to_string(status);
    return;
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(results.bytes);
    entry.score = j.at("score").get<double>();
    entry.max_score = j.at("max_score").get<double>();
    for (const auto& t : j.at("tests")) (t.at("status") == "passed" ? entry.passed : entry.failed) += 1;
    entry.status = "graded";
  } catch (const std::exception& e) {
    entry.problem = std::string("unreadable results: ") + e.what();
  }
}

}  // namespace

std::vector<ClassEntry> grade_class(Suite& suite, const std::vector<std::filesystem::path>& folders,
                                    const std::filesystem::path& out, int jobs, const GradeOptions& options,
                                    const FinishReport& finish) {
  std::vector<ClassEntry> entries;
  std::map<std::string, int> seen;
  for (const auto& folder : folders) {
    ClassEntry e;
    e.folder = folder;
    std::string name = std::filesystem::path(folder).lexically_normal().filename().string();
    if (name.empty()) name = std::filesystem::path(folder).lexically_normal().parent_path().filename().string();
    if (name.empty()) name = "submission";
    const int n = ++seen[name];
    e.name = n == 1 ? name : name + "-" + std::to_string(n);
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
      e.status = "not a folder";
      e.problem = std::filesystem::exists(folder, ec)
                      ? "not a folder: a submission is a folder of the student's .lua files"
                      : "no such folder";
      entries.push_back(std::move(e));
      continue;
    }
    e.results = out / e.name / "results.json";
    std::filesystem::create_directories(out / e.name, ec);
    std::filesystem::remove(e.results, ec);
    std::filesystem::remove(e.results.string() + ".error", ec);
    entries.push_back(std::move(e));
  }
  if (jobs < 1) jobs = 1;
  std::map<pid_t, size_t> running;
  size_t next = 0;
  const auto wait_one = [&] {
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) return false;
    auto it = running.find(pid);
    if (it == running.end()) return true;  // not one of ours
    read_back(entries[it->second], status);
    running.erase(it);
    return true;
  };
  while (next < entries.size() || !running.empty()) {
    while (next < entries.size() && static_cast<int>(running.size()) < jobs) {
      if (entries[next].results.empty()) {  // not a folder: nothing to grade
        ++next;
        continue;
      }
      const pid_t pid = fork();
      if (pid == 0) _exit(work(suite, entries[next], options, finish));
      if (pid < 0) {
        entries[next].problem = "cannot start a grading process";
        ++next;
        continue;
      }
      running[pid] = next++;
    }
    if (!running.empty() && !wait_one()) break;
  }
  for (auto& e : entries) {
    std::error_code ec;
    if (!e.results.empty()) std::filesystem::remove(e.results.string() + ".error", ec);
  }
  return entries;
}

std::string class_summary_csv(const std::vector<ClassEntry>& entries) {
  std::ostringstream s;
  s << "submission,status,score,max_score,passed,failed,results,problem\n";
  for (const auto& e : entries) {
    s << csv_field(e.name) << ',' << e.status << ',' << format_number(e.score) << ',' << format_number(e.max_score)
      << ',' << e.passed << ',' << e.failed << ',' << csv_field(e.results.string()) << ',' << csv_field(e.problem)
      << '\n';
  }
  return s.str();
}

std::string class_summary_json(const std::vector<ClassEntry>& entries) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& e : entries) {
    j.push_back({{"submission", e.name},
                 {"folder", e.folder.string()},
                 {"status", e.status},
                 {"score", e.score},
                 {"max_score", e.max_score},
                 {"passed", e.passed},
                 {"failed", e.failed},
                 {"results", e.results.string()},
                 {"problem", e.problem}});
  }
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::vector<ClassResult> class_results(const std::vector<ClassEntry>& entries) {
  std::vector<ClassResult> results;
  for (const ClassEntry& entry : entries) {
    ClassResult result;
    result.name = entry.name;
    if (entry.status == "not a folder") {
      result.problem = entry.folder.string() + ": " + entry.problem;
    } else if (entry.status != "graded") {
      result.problem = "not graded: " + entry.problem;
    } else if (const FileBytes text = read_file_bytes(entry.results); !text.ok()) {
      result.problem = entry.results.string() + ": " + text.error;
    } else {
      result = read_class_result(entry.name, text.bytes);
    }
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace meshedit
