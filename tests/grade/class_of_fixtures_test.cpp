// A whole class made of every shipped student fixture, graded by the built meshedit against the whole assignment
// (`grade --suite suites/all.lua --submissions ... --jobs 2 --out marks`), and the class at a glance read back: each
// student is a copy of the correct solutions with one fixture of tests/grading/students/ in its part's file (the way
// the benchmark of docs/TESTING.md makes its class), two buggy fixtures handed in twice under other names, and
// submissions that are broken: one that does not compile, one that hangs while it loads, an empty folder and a stray
// file that is no folder. marks/class.html must list each buggy fixture's mistake under its own kind (or under the
// kinds written down below, with why), the kind made twice as "2 students" with both names, no correct fixture in any
// list, and the broken ones among the students whose tests were stopped or did not load (or the files not read), each
// with why; summary.csv and class.csv must agree. The unit tests of the report itself are class_report_test.cpp; each
// fixture's own diagnosis is part_suites_test.cpp's, flip_suite_test.cpp's and window_grader_agreement_test.cpp's.
// Grading takes 40 to 45 s on two cores (busy): upsample_splits_new_edges and the hanging submission wait out their 5 s
// time limits (8 tests of 5 s, 40 s of the two workers' time).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::grading_dir;
using testing::Outcome;
using testing::read_text;
using testing::run_meshedit;
using testing::write_text;

using Names = std::set<std::string>;

// The six parts: the file each part's suite loads (suites/<part>.lua, files = {"<part>.lua"}) and its tests' number.
// A fixture's name starts with its part: flip_forgets_faces.lua is a flip.lua.
const std::map<std::string, char> kParts = {{"curve", '1'}, {"patch", '2'}, {"normals", '3'},
                                            {"flip", '4'},  {"split", '5'}, {"upsample", '6'}};

// Buggy fixtures handed in a second time, as copy_of_<fixture>: their kind must say "2 students" with both names.
const char* const kHandedInTwice[] = {"flip_forgets_faces", "upsample_wrong_weight"};

// A buggy fixture whose every test is stopped: its upsample splits the edges it has just made, so it never ends and
// each of its 5 tests hits the 5 s time limit (or, on a faster machine, the 128 MB one). It is listed among the
// students whose tests were stopped, and in no kind of mistake.
const char* const kStoppedFixture = "upsample_splits_new_edges";

// A kind of mistake as the page lists it.
struct Kind {
  std::string example;     // one student's diagnosis, as the grader wrote it
  size_t count = 0;        // the N of "N students"
  std::string count_text;  // "2 students (6%)"
  std::vector<std::string> students;
  std::vector<std::string> tests;  // "6.4 a grid with a boundary, one level (extra credit)"
  std::string kind;                // the sentence with ids and numbers as N
};

// The kinds that are not "each buggy fixture alone in one kind of its own" (nor a fixture and its copy): fixtures
// that share a kind, and fixtures whose failed tests make two kinds. `words` are in the kind's sentence (ids and
// numbers as N). Every other buggy fixture must be alone in exactly one kind.
struct ExpectedKind {
  Names students;
  const char* words;
};
const ExpectedKind kNotOneOfTheirOwn[] = {
    // The same mistake, shared: both flag the halves of each split edge as new, so step 4 flips halves of split
    // edges (upsample_flags_halves also leaves the new edges unflipped; its feedback says so under this headline).
    {{"upsample_flags_halves", "upsample_flips_split_halves"},
     "an edge that was not new (a half of a split edge) was flipped"},
    // The same symptom, shared: neither flips a single new edge (a mark looked up with another handle never hits; a
    // test of one order of the ends never matches), and the feedback names both causes under it.
    {{"upsample_marks_by_handle", "upsample_one_way_test"},
     "your upsample flipped none of the N new edges the reference flips"},
    {{"upsample_flip_one_check"}, "a new edge whose ends were both new was flipped"},
    // upsample_wrong_vertices: its own mistake on the closed meshes; on 6.4's grid the headline is an integer
    // division 1 // 8 that the fixture does not write (its edge points land on original boundary vertices).
    {{"upsample_wrong_vertices"}, "a position computed for a new vertex (step N) was written to an original one"},
    {{"upsample_wrong_vertices"}, "your boundary vertex weight N/N is N (in Lua N // N is N, an integer division"},
    // Two kinds of one fixture, both its mistake: 3 // 16 for degree 3 (the tetrahedron), 3 // (8 * n) otherwise.
    {{"upsample_integer_division"}, "your weight u is N for degree N (in Lua N // N is N"},
    {{"upsample_integer_division"}, "your weight u is N for degrees other than N (in Lua N // (N * n) is N"},
    // Two kinds of one fixture: on the cube (3.1) the angle-weighted normal is also the one that leaves a face out,
    // and the feedback says both (so it is not normals_skips_a_face's kind); elsewhere it is named as angle-weighted.
    {{"normals_angle_weighted"}, "each weighted by its face's angle at vN"},
    {{"normals_angle_weighted"}, "weights each face by its angle at vN (an angle-weighted normal)"},
};

std::string unescaped(std::string text) {
  for (const auto& [entity, c] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}}) {
    for (size_t at = text.find(entity); at != std::string::npos; at = text.find(entity, at + c.size()))
      text.replace(at, entity.size(), c);
  }
  return text;
}

std::vector<std::string> split(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  size_t from = 0;
  for (size_t at; (at = text.find(separator, from)) != std::string::npos; from = at + separator.size())
    parts.push_back(text.substr(from, at - from));
  parts.push_back(text.substr(from));
  return parts;
}

// The text between `from` and `to` after `at` (which moves past `to`); "" and npos when either is missing.
std::string between(const std::string& text, const std::string& from, const std::string& to, size_t& at) {
  const size_t start = text.find(from, at);
  const size_t end = start == std::string::npos ? start : text.find(to, start + from.size());
  if (end == std::string::npos) {
    at = std::string::npos;
    return "";
  }
  at = end + to.size();
  return text.substr(start + from.size(), end - start - from.size());
}

// One section of the page: from its <h2> to the next.
std::string section(const std::string& page, const std::string& heading) {
  const size_t start = page.find("<h2>" + heading + "</h2>");
  if (start == std::string::npos) return "";
  const size_t end = std::min(page.find("<h2>", start + 4), page.find("</body>", start));
  return page.substr(start, end - start);
}

// The ranked mistakes: <li><p><b>EXAMPLE</b></p><p>N students (P%): a, b<br>in TESTS<br>kind: <code>KIND</code></p>.
std::vector<Kind> kinds_of(const std::string& page) {
  const std::string list = section(page, "The mistakes, most common first");
  std::vector<Kind> kinds;
  for (size_t at = 0; at != std::string::npos;) {
    const std::string item = between(list, "<li>", "</li>\n", at);
    if (at == std::string::npos) break;
    Kind k;
    size_t in = 0;
    k.example = unescaped(between(item, "<p><b>", "</b></p><p>", in));
    k.count_text = between(item, "", ": ", in);
    k.count = std::stoul("0" + k.count_text.substr(0, k.count_text.find(' ')));
    for (const std::string& name : split(between(item, "", "<br>in ", in), ", ")) k.students.push_back(unescaped(name));
    k.tests = split(unescaped(between(item, "", "<br>kind: <code>", in)), "; ");
    k.kind = unescaped(between(item, "", "</code></p>", in));
    EXPECT_NE(in, std::string::npos) << "a kind the test cannot read: " << item;
    kinds.push_back(std::move(k));
  }
  return kinds;
}

// A section's <li><b>NAME</b>: WHY</li> items, why with its tags taken off, by name.
std::map<std::string, std::string> listed(const std::string& page, const std::string& heading) {
  const std::string list = section(page, heading);
  std::map<std::string, std::string> out;
  for (size_t at = 0; at != std::string::npos;) {
    const std::string name = between(list, "<li><b>", "</b>: ", at);
    std::string why = between(list, "", "</li>\n", at);
    if (at == std::string::npos) break;
    for (const char* tag : {"<span class=\"problem\">", "</span>"}) {
      if (const size_t t = why.find(tag); t != std::string::npos) why.erase(t, std::string(tag).size());
    }
    out[unescaped(name)] = unescaped(why);
  }
  return out;
}

// A CSV file's rows by their first field (no field here has a comma of its own).
std::map<std::string, std::vector<std::string>> rows_of(const std::string& csv) {
  std::map<std::string, std::vector<std::string>> rows;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);) {
    const std::vector<std::string> fields = split(line, ",");
    rows[fields.front()] = fields;
  }
  return rows;
}

// The fixtures, by name: whether a fixture is correct, correct but for the extra credit, or buggy is what its first
// line says ("-- A correct student flip.lua (test fixture)", "... without the extra credit", "-- A buggy student").
struct Fixtures {
  std::map<std::string, fs::path> all;
  Names correct, without_extra_credit, buggy;
};

Fixtures read_fixtures() {
  Fixtures f;
  for (const auto& entry : fs::directory_iterator(grading_dir() / "students")) {
    if (entry.path().extension() != ".lua") continue;
    const std::string name = entry.path().stem().string();
    EXPECT_TRUE(kParts.contains(name.substr(0, name.find('_')))) << name << " does not start with its part";
    f.all[name] = entry.path();
    const std::string first = read_text(entry.path()).substr(0, 200);
    if (first.starts_with("-- A buggy student")) f.buggy.insert(name);
    else if (first.find("without the extra credit") < first.find('\n')) f.without_extra_credit.insert(name);
    else if (first.starts_with("-- A correct student")) f.correct.insert(name);
    else ADD_FAILURE() << name << ".lua says neither \"A buggy student\" nor \"A correct student\" on its first line";
  }
  return f;
}

// class/NAME: the six correct solutions, with `file` (a part's file name, "flip.lua") replaced by `fixture`.
void hand_in(const fs::path& dir, const std::string& name, const std::string& file, const fs::path& fixture) {
  const fs::path solutions = testing::source_dir() / "tests" / "exercise" / "solutions";
  for (const auto& [part, number] : kParts) {
    const std::string lua = part + ".lua";
    write_text(dir / "class" / name / lua, read_text(lua == file ? fixture : solutions / lua));
  }
}

// Every kind the page lists must be one expected (by its students and, when given, its words), each once.
void expect_the_kinds(const std::vector<Kind>& kinds, const Fixtures& fixtures) {
  std::vector<ExpectedKind> expected(std::begin(kNotOneOfTheirOwn), std::end(kNotOneOfTheirOwn));
  Names written_down;
  for (const ExpectedKind& k : expected) written_down.insert(k.students.begin(), k.students.end());
  Names alone = fixtures.buggy;
  alone.insert(fixtures.without_extra_credit.begin(), fixtures.without_extra_credit.end());
  for (const std::string& name : alone) {
    if (written_down.contains(name) || name == kStoppedFixture) continue;
    Names students = {name};
    for (const char* twice : kHandedInTwice) {
      if (name == twice) students.insert(std::string("copy_of_") + twice);
    }
    expected.push_back({students, ""});
  }
  std::vector<bool> matched(kinds.size(), false);
  for (const ExpectedKind& e : expected) {
    std::string who;
    for (const std::string& s : e.students) who += s + " ";
    size_t found = 0;
    for (size_t i = 0; i < kinds.size(); ++i) {
      const Names students(kinds[i].students.begin(), kinds[i].students.end());
      if (matched[i] || students != e.students || kinds[i].kind.find(e.words) == std::string::npos) continue;
      matched[i] = true;
      ++found;
      break;
    }
    EXPECT_EQ(found, 1u) << "no kind of mistake made by exactly " << who
                         << (*e.words ? "with \"" + std::string(e.words) + "\"" : std::string("(alone in a kind)"));
  }
  for (size_t i = 0; i < kinds.size(); ++i) {
    std::string who;
    for (const std::string& s : kinds[i].students) who += s + " ";
    EXPECT_TRUE(matched[i]) << "a kind not expected: " << who << "in " << kinds[i].kind;
  }
  EXPECT_EQ(kinds.size(), expected.size());
}

// Each kind's headline counts its students; its tests are its students' part's; a kind of a correct fixture
// without the extra credit is in an extra-credit test.
void expect_each_kind_reads_right(const std::vector<Kind>& kinds, const Fixtures& fixtures) {
  for (const Kind& k : kinds) {
    SCOPED_TRACE(k.kind);
    EXPECT_EQ(k.count, k.students.size()) << k.count_text;
    EXPECT_TRUE(k.count_text.starts_with(std::to_string(k.count) + (k.count == 1 ? " student (" : " students (")))
        << k.count_text;
    for (const std::string& student : k.students) {
      const std::string fixture = student.starts_with("copy_of_") ? student.substr(8) : student;
      ASSERT_TRUE(fixtures.all.contains(fixture)) << student << " is no fixture, yet in a kind of mistake";
      EXPECT_FALSE(fixtures.correct.contains(fixture)) << student << " is correct, yet in a kind of mistake";
      const char part = kParts.at(fixture.substr(0, fixture.find('_')));
      for (const std::string& test : k.tests) EXPECT_EQ(test.front(), part) << student << ": " << test;
      if (!fixtures.without_extra_credit.contains(fixture)) continue;
      for (const std::string& test : k.tests) EXPECT_NE(test.find("(extra credit)"), std::string::npos) << test;
    }
  }
  for (const char* twice : kHandedInTwice) {
    const auto made = std::find_if(kinds.begin(), kinds.end(), [&](const Kind& k) {
      return std::find(k.students.begin(), k.students.end(), twice) != k.students.end();
    });
    ASSERT_NE(made, kinds.end()) << twice;
    EXPECT_TRUE(made->count_text.starts_with("2 students (")) << made->count_text;
    EXPECT_EQ(Names(made->students.begin(), made->students.end()), (Names{twice, std::string("copy_of_") + twice}));
  }
}

// The students whose tests were stopped or did not load, each with why and how many tests; the file not read.
void expect_the_stopped_and_unread(const std::string& page) {
  const std::map<std::string, std::string> stopped = listed(page, "Stopped or not loaded");
  ASSERT_EQ(stopped.size(), 4u) << section(page, "Stopped or not loaded");
  const auto says = [&](const std::string& who, const std::string& tests, const std::string& words) {
    const auto it = stopped.find(who);
    ASSERT_NE(it, stopped.end()) << who << " is not among the stopped:\n" << section(page, "Stopped or not loaded");
    EXPECT_TRUE(it->second.starts_with(tests + ", the first ")) << who << ": " << it->second;
    EXPECT_NE(it->second.find(words), std::string::npos) << who << ": " << it->second;
  };
  says("syntax_error", "5 tests",
       ": Load error: the submission did not load: flip.lua:4: 'then' expected near 'return'");
  says("hangs_at_load", "3 tests", ": Timed out: the submission did not load: patch.lua:3: time limit exceeded");
  says("empty_folder", "29 tests", ": Load error: the submission did not load: the submission has no curve.lua");
  says(kStoppedFixture, "5 tests", " upsample.lua:");
  const std::string upsample = stopped.count(kStoppedFixture) ? stopped.at(kStoppedFixture) : "";
  EXPECT_TRUE(upsample.find(": Timed out: ") != std::string::npos ||
              upsample.find(": Out of memory: ") != std::string::npos)
      << upsample;
  const std::map<std::string, std::string> unread = listed(page, "Not read");
  ASSERT_EQ(unread.size(), 1u) << section(page, "Not read");
  EXPECT_EQ(unread.begin()->first, "stray_notes.txt");
  EXPECT_EQ(unread.begin()->second,
            "class/stray_notes.txt: not a folder: a submission is a folder of the student's .lua files");
}

// summary.csv and class.csv: a row each, the fixtures graded, the correct ones with nothing failed.
void expect_the_tables(const fs::path& marks, const Fixtures& fixtures, const std::vector<std::string>& names) {
  const auto summary = rows_of(read_text(marks / "summary.csv"));
  const auto table = rows_of(read_text(marks / "class.csv"));
  EXPECT_EQ(summary.size(), names.size() + 1);
  EXPECT_EQ(table.size(), names.size() + 1);
  ASSERT_TRUE(summary.contains("submission") && table.contains("student"));
  EXPECT_EQ(summary.at("submission")[5], "failed");
  EXPECT_EQ(table.at("student").size(), 3 + 29 + 1u);  // name, score, max_score, the 29 tests, problem
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(summary.contains(name) && table.contains(name));
    const std::vector<std::string>& row = summary.at(name);
    if (name == "stray_notes.txt") {
      EXPECT_EQ(row[1], "not a folder");
      EXPECT_EQ(row[6], "");  // no results file
      EXPECT_EQ(row.back(), "not a folder: a submission is a folder of the student's .lua files");
      EXPECT_EQ(table.at(name).back(),
                "class/stray_notes.txt: not a folder: a submission is a folder of the student's .lua files");
      EXPECT_EQ(table.at(name)[1], "");  // no score
      continue;
    }
    EXPECT_EQ(row[1], "graded");
    EXPECT_EQ(table.at(name).back(), "");  // no problem
    if (fixtures.correct.contains(name)) {
      EXPECT_EQ(row[5], "0");
    } else if (fixtures.without_extra_credit.contains(name)) {
      EXPECT_EQ(row[5], "1");
    } else if (fixtures.buggy.contains(name) || name.starts_with("copy_of_")) {
      EXPECT_NE(row[5], "0");
    }
  }
  EXPECT_EQ(summary.at("empty_folder")[4], "0");  // nothing passed
}

TEST(ClassOfFixtures, EachFixturesMistakeIsListedUnderItsKindAndTheBrokenOnesApart) {
  if (!fs::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const Fixtures fixtures = read_fixtures();
  ASSERT_GE(fixtures.buggy.size(), 20u);
  ASSERT_FALSE(fixtures.correct.empty());
  for (const auto& [part, number] : kParts) {
    EXPECT_NE(read_text(grading_dir() / "suites" / (part + ".lua")).find("files = {\"" + part + ".lua\"}"),
              std::string::npos)
        << part;
  }
  const fs::path dir = testing::scratch_dir();
  for (const auto& [name, path] : fixtures.all) hand_in(dir, name, name.substr(0, name.find('_')) + ".lua", path);
  for (const char* twice : kHandedInTwice) {
    const std::string name = twice;
    hand_in(dir, "copy_of_" + name, name.substr(0, name.find('_')) + ".lua", fixtures.all.at(name));
  }
  // Broken: a flip.lua that does not compile; a patch.lua whose top level never ends (patch.lua: its part has the
  // fewest tests, 3, each waiting out the 5 s time limit); a folder with nothing in it; a file that is no folder.
  hand_in(dir, "syntax_error", "flip.lua", grading_dir() / "broken" / "syntax_error.lua");
  hand_in(dir, "hangs_at_load", "patch.lua", grading_dir() / "broken" / "hangs_at_load.lua");
  fs::create_directories(dir / "class" / "empty_folder");
  write_text(dir / "class" / "stray_notes.txt", "not a submission\n");

  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir / "class")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string folders;
  for (const std::string& name : names) folders += " class/" + name;
  const Outcome o = run_meshedit(dir, "grade --suite '" + (grading_dir() / "suites" / "all.lua").string() +
                                          "' --submissions" + folders + " --jobs 2 --out marks");
  // Every submission graded, and the stray file named and left out: grading worked, exit status 0.
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("\nstray_notes.txt: left out: class/stray_notes.txt is not a folder: a submission is a folder "
                       "of the student's .lua files\n"),
            std::string::npos)
      << o.out;
  EXPECT_TRUE(o.out.ends_with("\n" + std::to_string(names.size() - 1) + " of " + std::to_string(names.size() - 1) +
                              " submissions graded (1 left out: not a folder); summary in marks/summary.csv, the "
                              "class at a glance in marks/class.html\n"))
      << o.out;
  EXPECT_FALSE(fs::exists(dir / "marks" / "stray_notes.txt"));  // nothing written for it

  const std::string page = read_text(dir / "marks" / "class.html");
  const std::vector<Kind> kinds = kinds_of(page);
  expect_the_kinds(kinds, fixtures);
  expect_each_kind_reads_right(kinds, fixtures);
  expect_the_stopped_and_unread(page);
  expect_the_tables(dir / "marks", fixtures, names);
}

}  // namespace
}  // namespace meshedit
