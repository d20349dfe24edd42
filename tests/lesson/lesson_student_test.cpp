// your_turn end to end: the built binary runs each of lessons 1 to 7 (`meshedit lesson ... --headless --student
// DIR`) with the correct solutions (every your_turn is right, every step passes) and with every buggy fixture of
// tests/grading/students and tests/grading/scripted, each in a student folder of its own (the correct solutions, with
// the fixture as its part's file). The lesson that asks for that function names the mistake in the words tests/grade/
// window_grader_agreement_test.cpp holds the Exercises tab and the grader to: an answers file that expects those words
// passes, and the shipped answers (which expect "right") fail naming the step. A Lua error is reported at the
// student's file:line. Skips when the binary is not built. A fixture added without a case here fails
// EveryBuggyFixtureHasALessonCase.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string out, err;
};

Outcome run_meshedit(const fs::path& dir, const std::string& arguments) {
  const auto out = dir / "lesson_stdout.txt", err = dir / "lesson_stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(MESHEDIT_BINARY) + "' " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = testing::read_text(out);
  o.err = testing::read_text(err);
  return o;
}

const fs::path& source() {
  static const fs::path dir = testing::source_dir();
  return dir;
}

const fs::path& solutions() {
  static const fs::path dir = source() / "tests" / "exercise" / "solutions";
  return dir;
}

// The lessons that end with your_turn, by the part their student file belongs to, and how many steps each has.
struct Lesson {
  const char* part;  // "flip": flip.lua, the fixtures flip_*.lua
  const char* stem;  // "4_edge_flip"
  size_t steps;
};
const std::vector<Lesson> kLessons = {
    {"curve", "1_de_casteljau", 10},
    {"patch", "2_bezier_patches", 7},
    {"normals", "3_halfedge_walks", 7},
    {"flip", "4_edge_flip", 7},
    {"split", "5_edge_split", 7},
    {"upsample", "6_loop_subdivision", 12},
    {"catmull_clark", "7_catmull_clark", 9},
};

void PrintTo(const Lesson& lesson, std::ostream* out) { *out << lesson.stem; }

const Lesson& lesson_of(const std::string& part) {
  for (const Lesson& lesson : kLessons) {
    if (part == lesson.part) return lesson;
  }
  throw std::runtime_error("no lesson for the part " + part);
}

fs::path shipped_answers(const Lesson& lesson) {
  return source() / "tests" / "lesson" / "lessons" / (std::string(lesson.stem) + "_answers.lua");
}

Outcome run_lesson(const fs::path& dir, const Lesson& lesson, const fs::path& answers, const fs::path& student) {
  const fs::path file = source() / "lessons" / (std::string(lesson.stem) + ".lua");
  return run_meshedit(dir, "lesson '" + file.string() + "' --headless --answers '" + answers.string() +
                               "' --student '" + student.string() + "'");
}

// The longest of `names` that the fixture's name starts with, followed by "_"; "" when none does.
std::string longest_prefix(const std::string& fixture, const std::vector<std::string>& names) {
  std::string found;
  for (const std::string& name : names) {
    if (fixture.rfind(name + "_", 0) == 0 && name.size() > found.size()) found = name;
  }
  return found;
}

// "flip_forgets_faces" -> "flip", "catmull_clark_moves_in_place" -> "catmull_clark": the longest lesson part the
// fixture's name starts with.
std::string part_of(const std::string& fixture) {
  static const std::vector<std::string> parts = [] {
    std::vector<std::string> all;
    for (const Lesson& lesson : kLessons) all.emplace_back(lesson.part);
    return all;
  }();
  return longest_prefix(fixture, parts);
}

// The buggy files: tests/grading/students/ (the built-in exercises') and tests/grading/scripted/ (the exercises of
// scripts/exercises/).
const fs::path kFixtureFolders[] = {fs::path("tests") / "grading" / "students",
                                    fs::path("tests") / "grading" / "scripted"};

fs::path fixture_file(const std::string& fixture) {
  for (const fs::path& folder : kFixtureFolders) {
    if (fs::exists(source() / folder / (fixture + ".lua"))) return source() / folder / (fixture + ".lua");
  }
  throw std::runtime_error("no fixture " + fixture + ".lua");
}

// A student folder in `dir`: the correct solutions, with the fixture FIXTURE.lua as its part's file.
fs::path student_folder(const fs::path& dir, const std::string& fixture) {
  const fs::path folder = dir / fixture;
  fs::create_directories(folder);
  for (const auto& entry : fs::directory_iterator(solutions())) {
    fs::copy_file(entry.path(), folder / entry.path().filename(), fs::copy_options::overwrite_existing);
  }
  fs::copy_file(fixture_file(fixture), folder / (part_of(fixture) + ".lua"), fs::copy_options::overwrite_existing);
  return folder;
}

// The shipped answers with their your_turn answers, in order, replaced by `verdicts`: "right", or words a wrong
// verdict's feedback must contain (the last verdict; the lesson's step goes on after it).
fs::path answers_expecting(const fs::path& dir, const Lesson& lesson, const std::vector<std::string>& verdicts) {
  std::string text = testing::read_text(shipped_answers(lesson));
  const std::string right = "{your_turn = \"right\"}";
  size_t at = 0;
  for (const std::string& verdict : verdicts) {
    at = text.find(right, at);
    EXPECT_NE(at, std::string::npos) << lesson.stem << ": fewer your_turn answers than verdicts";
    if (at == std::string::npos) break;
    const std::string replacement =
        verdict == "right" ? right : "{your_turn = \"wrong\", feedback = \"" + verdict + "\"}";
    text.replace(at, right.size(), replacement);
    at += replacement.size();
  }
  // A step goes on after the first wrong verdict the answers expect: the your_turns after it in the step never run.
  const std::string unused = ", " + right;
  for (size_t rest = text.find(unused, at); rest != std::string::npos; rest = text.find(unused, rest)) {
    text.erase(rest, unused.size());
  }
  EXPECT_EQ(text.find(right, at), std::string::npos) << lesson.stem << ": more your_turn answers than verdicts";
  const fs::path path = dir / "answers.lua";
  std::ofstream(path) << text;
  return path;
}

std::string passed_line(const Lesson& lesson) { return "\n" + std::to_string(lesson.steps) + " steps passed\n"; }

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// ---- the correct solutions pass every lesson --------------------------------------------------------------------

class CorrectSolutions : public ::testing::TestWithParam<Lesson> {};

TEST_P(CorrectSolutions, PassEveryStepAndEveryYourTurn) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const Lesson& lesson = GetParam();
  const Outcome o = run_lesson(testing::scratch_dir(), lesson, shipped_answers(lesson), solutions());
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "");
  EXPECT_NE(o.out.find("  > your turn " + std::string(lesson.part) + ".lua: right\n"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("  > your turn " + std::string(lesson.part) + ".lua: wrong"), std::string::npos) << o.out;
  EXPECT_TRUE(ends_with(o.out, passed_line(lesson))) << o.out;
}

INSTANTIATE_TEST_SUITE_P(Lessons, CorrectSolutions, ::testing::ValuesIn(kLessons),
                         [](const ::testing::TestParamInfo<Lesson>& lesson) { return std::string(lesson.param.part); });

// ---- every buggy fixture is told its mistake --------------------------------------------------------------------

struct BuggyCase {
  const char* fixture;                // tests/grading/students/FIXTURE.lua
  std::vector<std::string> verdicts;  // per your_turn of its lesson, in order: "right"s, then words of the wrong one
};

// The fixtures that are correct (for the lessons: boundary rules are extra credit, which no lesson requires).
const std::set<std::string> kCorrect = {"flip_correct",           "split_correct",    "split_reordered",
                                        "split_without_boundary", "upsample_correct", "upsample_without_boundary"};

const std::vector<BuggyCase>& buggy_cases() {
  static const std::vector<BuggyCase> all = {
      {"curve_drops_last", {"point 3 of the step is missing"}},
      {"curve_swapped_weights", {"the weights are swapped"}},
      {"patch_columns_first", {"u and v are swapped"}},
      {"normals_unit_average", {"is the average of the faces' unit normals; the reference"}},
      // The lesson's fan is regular in its angles: angle weights and unit normals give the same normal there.
      {"normals_angle_weighted",
       {"on this mesh that is also the normalised sum of the unit normals of the 6 faces around v0, each weighted by "
        "its face's angle at v0"}},
      {"normals_last_face_only", {"is the normal of f1 alone, one of the 6 faces around v0"}},
      {"normals_skips_a_face", {"leaves out f1, one of the 6 faces around v0; the reference"}},
      // The diamond's middle edge is flipped right; the boundary edge a-c must be left alone.
      {"flip_boundary", {"right", "the reference does not flip e2 (e2 is on the boundary"}},
      {"flip_breaks_face_cycle",
       {"h5.next is still h3 after your flip_edge, as before the call; the reference changes it: that pointer breaks "
        "the face cycle"}},
      // Lesson 4's verdict ends with the diagram's labels of the ids it names (the builder's h1 is the diagram's h2);
      // the words before them are the grader's (window_grader_agreement_test.cpp).
      {"flip_forgets_faces", {"(the diagram's labels: h1 is labelled h2)"}},
      {"flip_forgets_vertices", {"v0.halfedge is h0, but h0 leaves v3"}},
      // Right on the diamond and its boundary edge; the big grid's edge is where looping over the mesh shows.
      {"flip_scans_the_mesh",
       {"right", "right",
        "elements of a mesh of 11200 faces (it wrote 9 of them and only read the rest); a flip changes a fixed "
        "handful"}},
      {"split_scans_the_mesh", {"right", "elements of a mesh of 11200 faces: mesh:validate() reads every one"}},
      {"split_corner_average", {"the average of the corners v0 v1 v2 v3; it belongs at the midpoint of v0 and v1"}},
      {"split_wrong_face", {"h12.face is f0, but h12 is in f2's next-cycle"}},
      // Upsample runs on the cube, then on the tetrahedron (every vertex of degree 3).
      {"upsample_flip_one_check", {"a new edge whose ends were both new was flipped"}},
      {"upsample_flips_split_halves", {"an edge that was not new (a half of a split edge) was flipped"}},
      {"upsample_flags_halves", {"an edge that was not new (a half of a split edge) was flipped"}},
      {"upsample_integer_division",
       {"your weight u is 0 for degrees other than 3 (in Lua 3 // (8 * n) is 0, an integer division: write "
        "3 / (8 * n)): 8 of the 8 original vertices kept their old positions"}},
      {"upsample_integer_edge_weights",
       {"your edge weights 3/8 and 1/8 are 0 (in Lua 3 // 8 and 1 // 8 are 0, integer divisions: write 3 / 8 and "
        "1 / 8)"}},
      {"upsample_marks_by_handle",
       {"your upsample flipped none of the 12 new edges the reference flips: 12 of your edges still join an original "
        "and a new vertex"}},
      {"upsample_one_way_test", {"the old/new test accepts one order only (a old and b new, but not a new and b old"}},
      {"upsample_splits_new_edges", {"upsample did not finish: split only the edges of the original mesh"}},
      {"upsample_wrong_vertices", {"a position computed for a new vertex (step 2) was written to an original one"}},
      {"upsample_wrong_weight", {"right", "moved as if u = 0.125"}},
      {"catmull_clark_moves_in_place", {"your vertices read neighbours you had already moved"}},
  };
  return all;
}

void PrintTo(const BuggyCase& c, std::ostream* out) { *out << c.fixture; }

class BuggyFixture : public ::testing::TestWithParam<BuggyCase> {};

TEST_P(BuggyFixture, TheLessonNamesTheMistake) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const BuggyCase& c = GetParam();
  const Lesson& lesson = lesson_of(part_of(c.fixture));
  const fs::path dir = testing::scratch_dir();
  const fs::path student = student_folder(dir, c.fixture);

  const Outcome o = run_lesson(dir, lesson, answers_expecting(dir, lesson, c.verdicts), student);
  EXPECT_EQ(o.status, 0) << o.err;
  // Each your_turn prints its verdict in order: "right", or "wrong: " and the diagnosis holding the case's words.
  const std::string run = "  > your turn " + part_of(c.fixture) + ".lua: ";
  size_t at = 0;
  for (const std::string& verdict : c.verdicts) {
    at = o.out.find(run, at);
    ASSERT_NE(at, std::string::npos) << o.out;
    at += run.size();
    if (verdict == "right") {
      EXPECT_EQ(o.out.compare(at, 6, "right\n"), 0) << o.out.substr(at, 200);
    } else {
      EXPECT_EQ(o.out.compare(at, 7, "wrong: "), 0) << o.out.substr(at, 200);
      EXPECT_NE(o.out.substr(at, o.out.find("\n  >", at) - at).find(verdict), std::string::npos) << o.out.substr(at);
    }
  }
  EXPECT_NE(o.out.find("  (wrong, as the answers expect: going on)\n"), std::string::npos) << o.out;
  EXPECT_TRUE(ends_with(o.out, passed_line(lesson))) << o.out;

  // The shipped answers expect the right answer: the buggy file fails the run at its step, quoting the diagnosis.
  const std::string& first_wrong =
      *std::find_if(c.verdicts.begin(), c.verdicts.end(), [](const std::string& v) { return v != "right"; });
  const Outcome failed = run_lesson(dir, lesson, shipped_answers(lesson), student);
  EXPECT_EQ(failed.status, 1) << failed.out;
  EXPECT_NE(failed.err.find(std::string(lesson.stem) + ".lua:"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("step " + std::to_string(lesson.steps) + " '"), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("your_turn should be judged right, but it was judged wrong: "), std::string::npos)
      << failed.err;
  EXPECT_NE(failed.err.find(first_wrong), std::string::npos) << failed.err;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BuggyFixture, ::testing::ValuesIn(buggy_cases()),
                         [](const ::testing::TestParamInfo<BuggyCase>& fixture) {
                           return std::string(fixture.param.fixture);
                         });

TEST(LessonStudent, EveryBuggyFixtureOfALessonsPartHasALessonCase) {
  std::set<std::string> covered(kCorrect);
  for (const BuggyCase& c : buggy_cases()) covered.insert(c.fixture);
  // A scripted fixture belongs to the exercise of scripts/exercises/ whose name is the longest its name starts with
  // (patch_normal_flipped is patch_normal's, not part 2's); one no lesson asks for (collapse, hodograph) needs none.
  std::vector<std::string> scripted;
  for (const auto& entry : fs::directory_iterator(source() / "scripts" / "exercises")) {
    scripted.push_back(entry.path().stem().string());
  }
  for (const fs::path& folder : kFixtureFolders) {
    const bool is_scripted = folder.filename() == "scripted";
    for (const auto& entry : fs::directory_iterator(source() / folder)) {
      const std::string fixture = entry.path().stem().string();
      if (is_scripted && longest_prefix(fixture, scripted) != part_of(fixture)) continue;
      EXPECT_TRUE(covered.count(fixture)) << entry.path().filename() << " has no case here";
    }
  }
}

TEST(LessonStudent, TheCorrectFixturesPassTheirLesson) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  for (const std::string& fixture : kCorrect) {
    const Lesson& lesson = lesson_of(part_of(fixture));
    const fs::path dir = testing::scratch_dir() / fixture;
    fs::create_directories(dir);
    const Outcome o = run_lesson(dir, lesson, shipped_answers(lesson), student_folder(dir, fixture));
    EXPECT_EQ(o.status, 0) << fixture << ": " << o.err;
    EXPECT_TRUE(ends_with(o.out, passed_line(lesson))) << fixture << ": " << o.out;
  }
}

// ---- errors and usage -------------------------------------------------------------------------------------------

TEST(LessonStudent, AStudentFileThatFailsIsReportedAtItsLine) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "broken");
  std::ofstream(dir / "broken" / "flip.lua") << "function flip_edge(mesh, e)\n  return e.halfedge.nope.twin\nend\n";
  const Lesson& lesson = lesson_of("flip");
  const Outcome o = run_lesson(dir, lesson, answers_expecting(dir, lesson, {"flip.lua:2:"}), dir / "broken");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("  > your turn flip.lua: wrong: flip.lua:2: "), std::string::npos) << o.out;
}

TEST(LessonStudent, ExpectingOtherWordsFailsAndQuotesTheDiagnosis) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  const Lesson& lesson = lesson_of("flip");
  const Outcome o = run_lesson(dir, lesson, answers_expecting(dir, lesson, {"h2.face"}),
                               student_folder(dir, "flip_forgets_vertices"));
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("your_turn should be judged wrong with feedback containing 'h2.face', but its feedback was "
                       "'after your flip_edge the mesh is not valid (2 problems): v0.halfedge is h0, but h0 leaves v3"),
            std::string::npos)
      << o.err;
}

TEST(LessonStudent, AMissingStudentFolderIsAUsageError) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const fs::path dir = testing::scratch_dir();
  const Outcome o = run_lesson(dir, lesson_of("flip"), shipped_answers(lesson_of("flip")), dir / "nowhere");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "meshedit: --student " + (dir / "nowhere").string() + ": no such folder (see meshedit --help)\n");
}

}  // namespace
}  // namespace meshedit
