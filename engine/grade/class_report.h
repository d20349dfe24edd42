// The class at a glance: the report of many students' results files (Gradescope's results.json, as `meshedit grade`
// writes them, or as Gradescope and any job runner keep them), for course staff: `grade --submissions ... --out
// marks` writes it as marks/class.html and marks/class.csv, and `meshedit class-report FILE...` makes it from results
// made elsewhere.
//
//   std::vector<ClassResult> results = {read_class_result("alice", text), ...};
//   const ClassReport report = make_class_report(results);
//   class_report_html(report); class_report_csv(report);
//
// `--compare PREVIOUS_MARKS` adds what changed since an earlier run: the students who improved or did worse, and the
// mistakes that went away, became rarer or more common, or are new.
//
// Invariants:
// - A results file that is not JSON, is truncated, or is another tool's shape is a student "not read" with the reason
//   (its file and the first thing wrong); the rest of the report is made.
// - A failed test's diagnosis is its feedback's first failed check (the grader's words, the window's too), and the
//   mistakes are grouped by kind: the same sentence once ids (h12, v3, e5, f0, b1) and numbers are put aside, so
//   "h12.face is f0" and "h40.face is f7" are one mistake. Kinds are ranked by how many students made them.
// - The page is one self-contained file: its histograms are inline SVG, no script, no external file.
// - Deterministic: the same files in the same order give the same bytes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace meshedit {

// One test of one student's results.
struct ClassTestResult {
  std::string number;  // "4.1" (Gradescope's "number"; "" when the file has none)
  std::string name;
  double score = 0.0;
  double max_score = 0.0;
  std::string output;  // the feedback, Markdown or text
};

enum class TestOutcome { Passed, Partly, Failed, TimedOut, Crashed };
const char* test_outcome_name(TestOutcome outcome);  // "passed", "partly passed", "failed", "timed out", "crashed"
TestOutcome test_outcome(const ClassTestResult& test);

struct ClassResult {
  std::string name;     // the student (the submission's folder, or the results file's name)
  std::string problem;  // why the file could not be read ("" when it was)
  double score = 0.0;
  double max_score = 0.0;
  std::vector<ClassTestResult> tests;
};

// Reads one results.json's text; never throws for its contents (a bad file is a result with `problem`).
ClassResult read_class_result(const std::string& name, const std::string& text);
// Reads a results file: marks/alice/results.json is alice's, any other file is named after itself; a file that cannot
// be read is a result with `problem` naming it.
ClassResult read_class_result_file(const std::filesystem::path& file);
// The results of a marks folder as `grade --submissions --out` leaves it: each FOLDER/NAME/results.json, by name.
std::vector<ClassResult> read_class_folder(const std::filesystem::path& folder);

// The first failed check of a test's feedback, as plain text ("flip_edge(e2) of a 1x1 grid: after your flip_edge
// ..."), or its first line when it has no list of checks.
std::string diagnosis_of(const std::string& output);
// The kind of a diagnosis: the part after what was checked and on which mesh, ids and numbers put aside ("after your
// flip_edge the mesh is not valid (N problem): fN.halfedge is hN, but hN.face is fN").
std::string mistake_kind(const std::string& diagnosis);
// Whether the diagnosis says the test was stopped or never ran ("Timed out: ...", "Crashed: ...", "Load error: ...",
// "Out of memory: ..."): those are listed per student, not among the mistakes.
bool stopped_diagnosis(const std::string& diagnosis);

struct ClassMistake {
  std::string kind;
  std::string example;                // one student's diagnosis, as the grader wrote it
  std::vector<std::string> tests;     // the tests it failed ("4.1 flip the middle edge ...")
  std::vector<std::string> students;  // who made it, in the results' order
};

struct ClassTestSummary {
  std::string number, name;
  double max_score = 0.0;
  std::map<TestOutcome, size_t> outcomes;
};

// A student whose tests were stopped or did not load, and the first such diagnosis.
struct ClassStopped {
  std::string student;
  std::string test;       // "4.1 flip the middle edge ..."
  std::string diagnosis;  // "Timed out: ...", "Load error: the submission did not load: ..."
  size_t tests = 0;       // how many of the student's tests ended so
};

struct ClassReport {
  std::vector<ClassResult> results;
  std::vector<ClassStopped> stopped;    // in the results' order
  double max_score = 0.0;               // the most any student could get (the largest max_score read)
  std::vector<ClassTestSummary> tests;  // in the order of the first file that has them
  std::vector<ClassMistake> mistakes;   // ranked: most students first, then kind
  std::vector<std::string> parts;       // "1" ... "6": the tests' numbers before their dot
};

ClassReport make_class_report(std::vector<ClassResult> results);

// What changed since an earlier report of the same class (--compare): students by name, mistakes by kind.
struct ClassChanges {
  struct Score {
    std::string student;
    double before = 0.0, now = 0.0;
  };
  std::vector<Score> improved, worse;  // by how much, most first
  std::vector<std::string> new_students, gone_students;
  struct Mistake {
    std::string example;
    size_t before = 0, now = 0;  // students who made it
  };
  std::vector<Mistake> gone, fewer, more, new_mistakes;  // gone: none now; new: none before
};
ClassChanges compare_class_reports(const ClassReport& before, const ClassReport& now);

// The page; with `changes`, a section on what changed since the earlier report.
std::string class_report_html(const ClassReport& report, const ClassChanges* changes = nullptr);
// One row per student: name, score, max score, each test's score (its number as the header), and the problem.
std::string class_report_csv(const ClassReport& report);

}  // namespace meshedit
