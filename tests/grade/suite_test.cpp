// Suite loading (declarations, defaults, errors with file:line) and one test run in this process: the
// `student` proxy, values crossing between the two states, the restricted student API, reference functions,
// load failures and limits. Runs in-process (Suite::run_test_here), without the child the grader adds.
#include <gtest/gtest.h>

#include <string>

#include "grade/submission.h"
#include "grade/suite.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

using testing::submission_of;
using testing::suite_of;

std::string load_error(const std::string& text) {
  try {
    suite_of(text);
  } catch (const GradeError& e) {
    return e.what();
  }
  return "(no error)";
}

// Runs the only test of `suite_text` against one file student.lua.
TestRun run_one(const std::string& suite_text, const std::string& student_text) {
  auto suite = suite_of(suite_text);
  return suite->run_test_here(0, submission_of({{"student.lua", student_text}}));
}

std::string checks_of(const TestRun& run) {
  std::string out;
  for (const auto& c : run.checks) out += std::string(c.passed ? "ok: " : "FAIL: ") + c.message + "\n";
  return out;
}

TEST(Suite, DeclarationsAndDefaults) {
  auto suite = suite_of(
      "test{ name = 'first', run = function() end }\n"
      "suite{ name = 'hw', files = {'a.lua'}, time_limit = 3, memory_mb = 64, visibility = 'hidden',\n"
      "       reference = {'flip_edge'}, partial = true, output_kb = 2 }\n"
      "test{ name = 'second', number = '2.5', points = 4, visibility = 'visible', time_limit = 1,\n"
      "      files = {'b.lua'}, reference = {}, allow_api = {'mesh:flip'}, partial = false, tags = {'x'},\n"
      "      run = function() end }\n");
  EXPECT_EQ(suite->name(), "hw");
  EXPECT_EQ(suite->output_bytes(), 2048u);
  ASSERT_EQ(suite->tests().size(), 2u);
  const TestSpec& a = suite->tests()[0];
  EXPECT_EQ(a.number, "1");  // suite{} applies to tests declared before it too
  EXPECT_EQ(a.name, "first");
  EXPECT_EQ(a.points, 1.0);
  EXPECT_EQ(a.visibility, "hidden");
  EXPECT_EQ(a.time_limit, 3.0);
  EXPECT_EQ(a.memory_mb, 64u);
  EXPECT_TRUE(a.partial);
  EXPECT_EQ(a.reference, std::vector<std::string>{"flip_edge"});
  const TestSpec& b = suite->tests()[1];
  EXPECT_EQ(b.number, "2.5");
  EXPECT_EQ(b.points, 4.0);
  EXPECT_EQ(b.visibility, "visible");
  EXPECT_EQ(b.time_limit, 1.0);
  EXPECT_FALSE(b.partial);
  EXPECT_TRUE(b.reference.empty());
  EXPECT_EQ(b.allow_api, std::vector<std::string>{"mesh:flip"});
  EXPECT_EQ(b.tags, std::vector<std::string>{"x"});
  const Submission s = submission_of({{"a.lua", ""}, {"c.lua", ""}});
  EXPECT_EQ(suite->files_for(a, s), std::vector<std::string>{"a.lua"});
  EXPECT_EQ(suite->files_for(b, s), std::vector<std::string>{"b.lua"});
  EXPECT_EQ(suite->named_files(), (std::vector<std::string>{"a.lua", "b.lua"}));
}

TEST(Suite, WithoutFilesEverySubmittedFileLoads) {
  auto suite = suite_of("test{ name = 't', run = function() end }");
  EXPECT_EQ(suite->files_for(suite->tests()[0], submission_of({{"b.lua", ""}, {"a.lua", ""}})),
            (std::vector<std::string>{"a.lua", "b.lua"}));
}

TEST(Suite, DeclarationErrorsNameTheLine) {
  EXPECT_EQ(load_error("\ntest{ name = 't', point = 1, run = function() end }"),
            "the suite did not load: suite.lua:2: test: unknown field 'point' (fields: allow_api, extra_credit, files, "
            "memory_mb, "
            "name, number, partial, points, reference, run, tags, time_limit, visibility)");
  EXPECT_EQ(load_error("test{ name = 't' }"),
            "the suite did not load: suite.lua:1: test 't': field 'run' must be a function(student, expect)");
  EXPECT_EQ(load_error("test{ run = function() end }"),
            "the suite did not load: suite.lua:1: test: field 'name' is required");
  EXPECT_EQ(load_error("test{ name = 't', visibility = 'secret', run = function() end }"),
            "the suite did not load: suite.lua:1: field 'visibility' must be visible, hidden, after_due_date or "
            "after_published");
  EXPECT_EQ(load_error("suite{ reference = {'flip'} }"),
            "the suite did not load: suite.lua:1: unknown reference function 'flip' (there are: flip_edge, split_edge, "
            "upsample, vertex_normal, evaluate_step, evaluate)");
  EXPECT_EQ(load_error("suite{ allow_api = {'mesh:save'} }"),
            "the suite did not load: suite.lua:1: allow_api: unknown entry 'mesh:save' (there are: mesh:flip, "
            "mesh:split, mesh:collapse, mesh:loop_subdivide, mesh:catmull_clark, meshedit.curve, meshedit.patch)");
  EXPECT_EQ(load_error("test{ name = 't', time_limit = 0, run = function() end }"),
            "the suite did not load: suite.lua:1: field 'time_limit' must be between 0.01 and 600.0");
  EXPECT_EQ(load_error("suite{ name = 'empty' }"), "the suite suite.lua declares no test");
  EXPECT_EQ(load_error("test{"), "the suite did not load: suite.lua:1: unexpected symbol near <eof>");
}

TEST(Suite, StudentFunctionsAreCalledWithCopiesAndShareMeshes) {
  const TestRun run = run_one(
      "test{ name = 't', run = function(student, expect)\n"
      "  expect.equal(student.add(2, 3), 5, 'add')\n"
      "  expect.equal({student.pair()}, {1, 'two'}, 'two results')\n"
      "  local v = meshedit.vec3(1, 2, 3)\n"
      "  expect.equal(student.dot(v, v), 14, 'a vec3 keeps its methods in the student state')\n"
      "  local m = meshedit.cube()\n"
      "  local h = student.move_and_return(m, m:vertex(3))\n"
      "  expect.equal(h, m:vertex(3), 'a handle comes back as the same element')\n"
      "  expect.equal(m:vertex(3).position, meshedit.vec3(9, 9, 9), 'the student moved the suite\\'s vertex')\n"
      "  expect.equal(student.table_result(), {x = 1, list = {3, 2, 1}}, 'tables')\n"
      "  expect.truthy(student.has('add'), 'has add') expect.falsy(student.has('nope'), 'no nope')\n"
      "  expect.equal(student.call('add', 1, 1), 2, 'call by name')\n"
      "  expect.equal(student.output(), 'hello\\t1\\n', 'output')\n"
      "end }\n",
      "print('hello', 1)\n"
      "function add(a, b) return a + b end\n"
      "function pair() return 1, 'two' end\n"
      "function dot(a, b) return a:dot(b) end\n"
      "function move_and_return(mesh, v) v.position = {9, 9, 9} return mesh:vertex(v.id) end\n"
      "function table_result() return {x = 1, list = {3, 2, 1}} end\n");
  EXPECT_EQ(run.end, RunEnd::Completed) << run.error;
  EXPECT_EQ(checks_of(run),
            "ok: add\nok: two results\nok: a vec3 keeps its methods in the student state\n"
            "ok: a handle comes back as the same element\nok: the student moved the suite's vertex\nok: tables\n"
            "ok: has add\nok: no nope\nok: call by name\nok: output\n");
  EXPECT_EQ(run.output, "hello\t1\n");
}

TEST(Suite, AFunctionFromAReturnedTableIsFoundToo) {
  const TestRun run = run_one("test{ name = 't', run = function(student, expect) expect.equal(student.f(), 7) end }",
                              "local M = {}\nfunction M.f() return 7 end\nreturn M\n");
  EXPECT_EQ(run.end, RunEnd::Completed) << run.error;
  EXPECT_EQ(checks_of(run), "ok: \n");
}

TEST(Suite, StudentErrorsStopTheTestWithTheStudentsMessage) {
  TestRun run = run_one("test{ name = 't', run = function(student, expect) student.f() end }",
                        "function f()\n  local t = nil\n  return t.twin\nend\n");
  EXPECT_EQ(run.end, RunEnd::Error);
  EXPECT_EQ(run.error, "student.lua:3: attempt to index a nil value (local 't')");
  run = run_one("test{ name = 't', run = function(student, expect) student.missing(1) end }", "");
  EXPECT_EQ(run.end, RunEnd::Error);
  EXPECT_EQ(run.error, "the submission does not define a function missing");
  run = run_one("test{ name = 't', run = function(student, expect) student.f() end }", "function f() return print end");
  EXPECT_EQ(run.end, RunEnd::Error);
  EXPECT_EQ(run.error, "f returned a value the grader cannot read: result 1: cannot pass a function");
  run = run_one("test{ name = 't', run = function(student, expect) student.f(print) end }", "function f() end");
  EXPECT_EQ(run.error, "the grader could not pass argument 1: cannot pass a function");
  // A suite may catch a student error and carry on; then only its checks decide.
  run = run_one(
      "test{ name = 't', run = function(student, expect)\n"
      "  local ok, why = pcall(student.f)\n"
      "  expect.falsy(ok, why)\n"
      "end }",
      "function f() error('mine') end");
  EXPECT_EQ(run.end, RunEnd::Completed);
  EXPECT_EQ(checks_of(run), "ok: student.lua:1: mine\n");
}

TEST(Suite, LoadFailuresAreReportedAndNothingRuns) {
  TestRun run = run_one("test{ name = 't', run = function(student, expect) expect.pass('ran') end }", "x = = 1");
  EXPECT_EQ(run.end, RunEnd::LoadError);
  EXPECT_EQ(run.error, "the submission did not load: student.lua:1: unexpected symbol near '='");
  EXPECT_TRUE(run.checks.empty());
  auto suite = suite_of("suite{ files = {'flip.lua'} }\ntest{ name = 't', run = function() end }");
  run = suite->run_test_here(0, submission_of({{"split.lua", ""}}));
  EXPECT_EQ(run.end, RunEnd::LoadError);
  EXPECT_EQ(run.error, "the submission did not load: the submission has no flip.lua");
  run = run_one("suite{ time_limit = 0.2 }\ntest{ name = 't', run = function() end }",
                "print('start')\nwhile true do end");
  EXPECT_EQ(run.end, RunEnd::Timeout);
  EXPECT_EQ(run.error, "the submission did not load: student.lua:2: time limit exceeded (0.2 s)");
  EXPECT_EQ(run.output, "start\n");
}

TEST(Suite, StudentLimitsStopTheTest) {
  TestRun run = run_one("suite{ time_limit = 0.2 }\ntest{ name = 't', run = function(student) student.f() end }",
                        "function f()\n  while true do pcall(function() while true do end end) end\nend");
  EXPECT_EQ(run.end, RunEnd::Timeout);
  EXPECT_NE(run.error.find("time limit exceeded (0.2 s)"), std::string::npos) << run.error;
  run = run_one("suite{ memory_mb = 16 }\ntest{ name = 't', run = function(student) student.f() end }",
                "function f()\n  local t = {}\n  while true do t[#t + 1] = ('x'):rep(1 << 20) .. #t end\nend");
  EXPECT_EQ(run.end, RunEnd::Memory);
  EXPECT_NE(run.error.find("memory limit exceeded (16 MB)"), std::string::npos) << run.error;
}

TEST(Suite, TheStudentApiIsRestricted) {
  // Hidden entries are functions that refuse with the words of student_api.h, naming the student's line.
  const TestRun run = run_one(
      "test{ name = 't', run = function(student, expect)\n"
      "  expect.equal(student.probe(meshedit.cube()), {'student.lua:3: meshedit.load is hidden from your code (in the "
      "window "
      "and in grading): student code cannot read or write files', 'student.lua:4: mesh:flip is hidden from your code "
      "(in "
      "the window and in grading): it is what flip_edge does, so write the pointer updates yourself', 'student.lua:5: "
      "meshedit.curve is hidden from your code (in the window and in grading): it evaluates curves for you; "
      "evaluate_step "
      "and evaluate are yours to write with vec3 arithmetic', 'table function'})\n"
      "end }",
      "function probe(m)\n"
      "  local out = {}\n"
      "  out[1] = select(2, pcall(function() return meshedit.load('x.obj') end))\n"
      "  out[2] = select(2, pcall(function() return m:flip(m:edge(0)) end))\n"
      "  out[3] = select(2, pcall(function() return meshedit.curve({{0, 0, 0}, {1, 0, 0}}) end))\n"
      "  out[4] = type(meshedit.vec3(1, 2, 3)) .. ' ' .. type(m.copy)\n"
      "  return out\n"
      "end");
  EXPECT_EQ(checks_of(run), "ok: \n");
  const TestRun allowed = run_one(
      "test{ name = 't', allow_api = {'mesh:flip'}, run = function(student, expect)\n"
      "  local m = meshedit.cube()\n"
      "  expect.equal(student.probe(m, m:edge(4)), m:edge(4))\n"
      "end }",
      "function probe(m, e) assert(not pcall(m.split, m, e)) return m:flip(e) end");
  EXPECT_EQ(allowed.end, RunEnd::Completed) << allowed.error;
  EXPECT_EQ(checks_of(allowed), "ok: \n");
}

TEST(Suite, ReferenceFunctionsReplaceTheStudentsOwn) {
  const TestRun run = run_one(
      "test{ name = 't', reference = {'flip_edge'}, run = function(student, expect)\n"
      "  local m = meshedit.cube()\n"
      "  local r = m:copy()\n"
      "  student.flip_twice(m, m:edge(4))\n"
      "  r:flip(r:edge(4)) r:flip(r:edge(4))\n"
      "  expect.same_pointers(m, r, 0, 'the reference flip ran twice')\n"
      "end }",
      "function flip_edge(mesh, e) error('my flip is broken') end\n"
      "function flip_twice(mesh, e) flip_edge(mesh, e) return flip_edge(mesh, e) end\n");
  EXPECT_EQ(run.end, RunEnd::Completed) << run.error;
  EXPECT_EQ(checks_of(run), "ok: the reference flip ran twice: same pointers as the reference\n");
}

TEST(Suite, EachTestGetsAFreshStudentState) {
  auto suite = suite_of(
      "test{ name = 'a', run = function(student, expect) expect.equal(student.bump(), 1) end }\n"
      "test{ name = 'b', run = function(student, expect) expect.equal(student.bump(), 1) end }\n");
  const Submission s =
      submission_of({{"student.lua", "count = 0\nfunction bump() count = count + 1 return count end"}});
  EXPECT_EQ(checks_of(suite->run_test_here(0, s)), "ok: \n");
  EXPECT_EQ(checks_of(suite->run_test_here(1, s)), "ok: \n");
}

TEST(Suite, ASuiteErrorIsReported) {
  const TestRun run =
      run_one("test{ name = 't', run = function(student, expect)\n  local x = nil\n  x.y = 1\nend }", "");
  EXPECT_EQ(run.end, RunEnd::Error);
  EXPECT_EQ(run.error, "suite.lua:3: attempt to index a nil value (local 'x')");
}

TEST(Suite, IncludedFilesKeepTheirOwnDefaults) {
  const auto dir = testing::scratch_dir();
  testing::write_text(dir / "part.lua",
                      "suite{ name = 'part', files = {'part.lua'}, time_limit = 2 }\n"
                      "test{ name = 'in part', run = function() end }\n");
  testing::write_text(dir / "main.lua",
                      "suite{ name = 'main', visibility = 'hidden' }\n"
                      "include('part.lua')\n"
                      "test{ name = 'in main', run = function() end }\n");
  auto suite = Suite::load(dir / "main.lua");
  EXPECT_EQ(suite->name(), "main");
  ASSERT_EQ(suite->tests().size(), 2u);
  EXPECT_EQ(suite->tests()[0].files, std::vector<std::string>{"part.lua"});
  EXPECT_EQ(suite->tests()[0].time_limit, 2.0);
  EXPECT_EQ(suite->tests()[0].visibility, "hidden");  // from the including file
  EXPECT_TRUE(suite->tests()[1].files.empty());       // part.lua's defaults stay with part.lua's tests
  EXPECT_EQ(suite->tests()[1].time_limit, 10.0);
  testing::write_text(dir / "broken.lua", "include('part.lua')\ninclude('nowhere.lua')\n");
  try {
    Suite::load(dir / "broken.lua");
    ADD_FAILURE() << "no error";
  } catch (const GradeError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.lua:2: include: cannot open "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshedit
