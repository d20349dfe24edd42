// The class report (grade/class_report.h): a diagnosis is its feedback's first failed check, mistakes are grouped by
// kind whatever the ids, numbers and mesh, a results file that is not one is named and the rest is made, stopped and
// unloaded submissions are listed apart, and `meshedit class-report` makes the page and the CSV from files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "grade/class_report.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// A results.json with one test per (number, score, output), worth 2 points each.
std::string results(const std::vector<std::tuple<std::string, double, std::string>>& tests) {
  std::string text = "{\"max_score\": " + std::to_string(2 * tests.size()) + ", \"tests\": [";  // the score: the sum
  for (size_t i = 0; i < tests.size(); ++i) {
    const auto& [number, score, output] = tests[i];
    text += std::string(i ? "," : "") + "{\"number\": \"" + number + "\", \"name\": \"t" + number +
            "\", \"score\": " + std::to_string(score) + ", \"max_score\": 2, \"output\": \"" + output + "\"}";
  }
  return text + "]}";
}

TEST(ClassReport, TheDiagnosisIsTheFirstFailedCheckAndItsKindPutsAsideIdsNumbersAndTheMesh) {
  const std::string markdown =
      "**Failed:**\\n\\n- flip\\\\_edge(`e2`) of a 1x1 grid: after your flip\\\\_edge the mesh is not valid (1 "
      "problem): `f0.halfedge` is `h0`, but `h0.face` is `f1`\\n\\n0 checks of 1 passed.\\n\\n![pic](data:x)";
  const ClassResult read = read_class_result("bob", results({{"4.1", 0, markdown}}));
  ASSERT_EQ(read.problem, "");
  const std::string diagnosis = diagnosis_of(read.tests.at(0).output);
  EXPECT_EQ(diagnosis,
            "flip_edge(e2) of a 1x1 grid: after your flip_edge the mesh is not valid (1 problem): f0.halfedge is h0, "
            "but h0.face is f1");
  EXPECT_EQ(mistake_kind(diagnosis),
            "after your flip_edge the mesh is not valid (N problem): fN.halfedge is hN, but hN.face is fN");
  EXPECT_EQ(mistake_kind("flip_edge(e8637) in the middle of an 80x70 grid (11200 triangles): after your flip_edge the "
                         "mesh is not valid (1 problem): f40.halfedge is h9, but h9.face is f7"),
            mistake_kind(diagnosis));
  // The mesh a check ran on is put aside too; the words of the mistake are kept.
  EXPECT_EQ(mistake_kind("cube: 3 of your edges join two new vertices"),
            mistake_kind("tetrahedron: 12 of your edges join two new vertices"));
  EXPECT_EQ(mistake_kind("evaluate_step of 2 points at t = 0: the weights are swapped: point i ..."),
            "the weights are swapped: point i ...");
  EXPECT_EQ(mistake_kind("split_edge(e0) of a cube: the average of the corners v0 v2 v3 v6"),
            mistake_kind("split_edge(e0) on the boundary: the average of the corners v0 v1 v4"));
  EXPECT_TRUE(stopped_diagnosis(diagnosis_of("**Timed out:** stopped after 5 s (time limit)")));
  EXPECT_EQ(test_outcome(ClassTestResult{"1.1", "t", 0, 2, "**Timed out:** stopped after 5 s"}), TestOutcome::TimedOut);
  EXPECT_EQ(test_outcome(ClassTestResult{"1.1", "t", 1, 2, "**Failed:**\\n\\n- x"}), TestOutcome::Partly);
}

TEST(ClassReport, MistakesAreRankedByStudentsAndABadFileIsNamedWithTheRestMade) {
  const std::string forgets = "**Failed:**\\n\\n- flip(e2): your flip left h3.face = f0";
  const std::string forgets_elsewhere = "**Failed:**\\n\\n- flip(e9): your flip left h30.face = f4";
  const std::string swapped = "**Failed:**\\n\\n- evaluate_step(cubic, 0.5): the weights are swapped";
  std::vector<ClassResult> class_results = {
      read_class_result("alice", results({{"1.1", 2, "ok"}, {"4.1", 2, "ok"}})),
      read_class_result("bob", results({{"1.1", 2, "ok"}, {"4.1", 0, forgets}})),
      read_class_result("carol", results({{"1.1", 0, swapped}, {"4.1", 0, forgets_elsewhere}})),
      read_class_result("dave", results({{"1.1", 0, "**Load error:** the submission has no curve.lua"},
                                         {"4.1", 0, "**Timed out:** stopped after 5 s"}})),
      read_class_result("eve", "{\"score\": 3, \"tests\": [{\"name\""),
      read_class_result("frank", "{\"suites\": []}"),
  };
  const ClassReport report = make_class_report(std::move(class_results));
  ASSERT_EQ(report.mistakes.size(), 2u);
  EXPECT_EQ(report.mistakes[0].kind, "your flip left hN.face = fN");
  EXPECT_EQ(report.mistakes[0].students, (std::vector<std::string>{"bob", "carol"}));
  EXPECT_EQ(report.mistakes[1].students, (std::vector<std::string>{"carol"}));
  ASSERT_EQ(report.stopped.size(), 1u);
  EXPECT_EQ(report.stopped[0].student, "dave");
  EXPECT_EQ(report.stopped[0].tests, 2u);
  EXPECT_EQ(report.stopped[0].diagnosis, "Load error: the submission has no curve.lua");
  EXPECT_NE(report.results[4].problem.find("not JSON, or truncated"), std::string::npos);
  EXPECT_EQ(report.results[5].problem, "not a Gradescope results.json (no \"tests\" list)");
  ASSERT_EQ(report.tests.size(), 2u);
  EXPECT_EQ(report.tests[1].outcomes.at(TestOutcome::Failed), 2u);
  EXPECT_EQ(report.tests[1].outcomes.at(TestOutcome::TimedOut), 1u);
  EXPECT_EQ(report.parts, (std::vector<std::string>{"1", "4"}));

  const std::string page = class_report_html(report);
  EXPECT_NE(page.find("2 students (50%): bob, carol"), std::string::npos);  // of the 4 files read
  EXPECT_NE(page.find("<b>eve</b>"), std::string::npos);
  EXPECT_NE(page.find("<b>dave</b>: 2 tests, the first 1.1 t1.1: Load error: the submission has no curve.lua"),
            std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(class_report_html(make_class_report(report.results)), page);  // the same bytes again
  const std::string csv = class_report_csv(report);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "student,score,max_score,1.1,4.1,problem");
  EXPECT_NE(csv.find("\nbob,2,4,2,0,\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nfrank,,,,,\"not a Gradescope results.json (no \"\"tests\"\" list)\"\n"), std::string::npos)
      << csv;
}

TEST(ClassReport, TheCommandMakesTheReportFromFilesAndNamesOneItCannotRead) {
  const fs::path dir = testing::scratch_dir();
  testing::write_text(dir / "marks" / "bob" / "results.json",
                      results({{"4.1", 0, "**Failed:**\\n\\n- flip(e2): your flip left h3.face = f0"}}));
  testing::write_text(dir / "alice.json", results({{"4.1", 2, "ok"}}));
  const testing::Outcome o =
      testing::run_meshedit(dir, "class-report marks/bob/results.json alice.json gone.json -o report");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out, "2 of 3 results files read; 1 kind of mistake; the report is report/class.html and class.csv\n");
  const std::string page = testing::read_text(dir / "report" / "class.html");
  EXPECT_NE(page.find("1 student (50%): bob"), std::string::npos) << page;
  EXPECT_NE(page.find("<b>gone</b>: <span class=\"problem\">gone.json: "), std::string::npos) << page;
  EXPECT_EQ(testing::run_meshedit(dir, "class-report").status, 2);

  // Against earlier marks: bob got better, his old mistake went away and a new one came.
  testing::write_text(dir / "before" / "bob" / "results.json",
                      results({{"4.1", 0, "**Failed:**\\n\\n- flip(e2): h5.next is still h3 after your flip"},
                               {"4.2", 0, "**Failed:**\\n\\n- flip(e4): h5.next is still h3 after your flip"}}));
  testing::write_text(dir / "before" / "carol" / "results.json", results({{"4.1", 2, "ok"}}));
  const testing::Outcome compared =
      testing::run_meshedit(dir, "class-report marks/bob/results.json alice.json -o report --compare before");
  EXPECT_EQ(compared.status, 0) << compared.err;
  const std::string changed = testing::read_text(dir / "report" / "class.html");
  EXPECT_NE(changed.find("<h2>Since the earlier marks</h2>"), std::string::npos) << changed;
  EXPECT_NE(changed.find("New in these marks: alice"), std::string::npos) << changed;
  EXPECT_NE(changed.find("Not in these marks: carol"), std::string::npos) << changed;
  EXPECT_NE(changed.find("<h3>Mistakes that went away</h3>\n<ul>\n<li>flip(e2): h5.next is still h3 after your flip "
                         "(1 to 0 students)"),
            std::string::npos)
      << changed;
  EXPECT_NE(changed.find("<h3>New mistakes</h3>\n<ul>\n<li>flip(e2): your flip left h3.face = f0 (0 to 1 students)"),
            std::string::npos)
      << changed;
  EXPECT_EQ(testing::run_meshedit(dir, "class-report alice.json --compare nowhere").status, 2);
}

TEST(ClassReport, AStudentWhoImprovedIsSaidWithBothScores) {
  std::vector<ClassResult> before = {read_class_result("bob", results({{"4.1", 0, "**Failed:**\\n\\n- x(e1): y"}}))};
  std::vector<ClassResult> now = {read_class_result("bob", results({{"4.1", 2, "ok"}}))};
  const ClassChanges changes = compare_class_reports(make_class_report(before), make_class_report(now));
  ASSERT_EQ(changes.improved.size(), 1u);
  EXPECT_EQ(changes.improved[0].student, "bob");
  EXPECT_EQ(changes.improved[0].now, 2.0);
  EXPECT_EQ(changes.gone.size(), 1u);
  EXPECT_NE(class_report_html(make_class_report(now), &changes).find("Improved: bob (0 to 2)"), std::string::npos);
}

}  // namespace
}  // namespace meshedit
