// your_turn on a LessonRunner and a HeadlessHost: a wrong flip_edge leaves the step waiting with compare()'s
// diagnosis, saving the right one makes the next look at the file (not before half a second of updates) run it again
// and the step go on; a runaway student loop is stopped by the student limits and said so; a student file with a
// syntax error is its file:line; bad arguments fail the step at the lesson's line; the lesson's mesh is not changed;
// each verdict keeps the exercise and the input it ran on; in the background (the window's runner) the step waits for
// the run, and Stop or leaving the step ends it.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/ids.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "exercise/exercises.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using State = LessonRunner::StepState;

// A step that runs the student's flip_edge on e2 of a 1x1 grid, then says so.
constexpr const char* kLesson = R"lua(local grid = meshedit.grid(1, 1)
step("Your turn", function()
  show(grid)
  local before = tostring(grid:edge(2).halfedge.next)
  your_turn { exercise = "flip", mesh = grid, element = "e2", hint = "Set every next pointer." }
  say(tostring(grid:edge(2).halfedge.next) == before and "the grid is as it was" or "the grid changed")
end)
)lua";

constexpr const char* kChangesNothing = "function flip_edge(mesh, e) return e end\n";

fs::path write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

// Saves `text` as the student's file with a modification time clearly after the last one.
void save(const fs::path& file, const std::string& text) {
  const auto before = fs::last_write_time(file);
  write(file, text);
  fs::last_write_time(file, before + std::chrono::seconds(2));
}

TEST(LessonYourTurn, AWrongFlipWaitsWithTheDiagnosisAndASaveRunsItAgain) {
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  const fs::path file = write(dir / "student" / "flip.lua", kChangesNothing);
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  ASSERT_TRUE(runner.load(write(dir / "lesson.lua", kLesson))) << runner.error();
  ASSERT_EQ(runner.step_state(), State::Waiting) << runner.error();
  const LessonWait& wait = runner.waiting_for();
  EXPECT_EQ(wait.kind, LessonWait::Kind::YourTurn);
  EXPECT_EQ(wait.describe(), "the student's flip.lua to give the reference's answer");
  EXPECT_EQ(wait.where, "lesson.lua:5");
  EXPECT_EQ(wait.hint, "Set every next pointer.");
  EXPECT_EQ(wait.tries, 1);
  ASSERT_EQ(runner.your_turns().size(), 1u);
  EXPECT_FALSE(runner.your_turns()[0].right);
  EXPECT_EQ(runner.your_turns()[0].input.rfind("e2 of ", 0), 0u) << runner.your_turns()[0].input;
  EXPECT_NE(wait.feedback.find("your flip_edge changed nothing"), std::string::npos) << wait.feedback;
  // The verdict keeps what both runs worked on: the grid as the lesson gave it, and e2.
  const YourTurnVerdict& first = runner.your_turns()[0];
  EXPECT_EQ(first.exercise, Exercise::FlipEdge);
  EXPECT_EQ(first.exercise_input.element, ElementRef(EdgeId(2)));
  ASSERT_TRUE(first.exercise_input.mesh);
  EXPECT_TRUE(first.exercise_input.mesh->same_as(build_halfedge_mesh(make_grid(1, 1))));
  EXPECT_EQ(first.exercise_input.describe(first.exercise), first.input);
  // The same check on that input says what the lesson said first.
  auto mine = load_student_file(file);
  const ExerciseReport report = check_exercise(*mine, first.exercise, first.exercise_input);
  EXPECT_FALSE(report.equal);
  ASSERT_FALSE(report.differences.empty());
  EXPECT_EQ(wait.feedback.substr(0, report.differences[0].size()), report.differences[0]);

  runner.update(0.25);  // the file did not change: nothing runs
  runner.update(0.25);
  EXPECT_EQ(runner.your_turns().size(), 1u);

  save(file, testing::read_text(testing::source_dir() / "tests" / "exercise" / "solutions" / "flip.lua"));
  runner.update(0.25);  // a quarter of a second: not looked at yet
  EXPECT_EQ(runner.your_turns().size(), 1u);
  EXPECT_EQ(runner.step_state(), State::Waiting);
  runner.update(0.25);  // half a second: the save is seen, the file runs again and is right
  ASSERT_EQ(runner.your_turns().size(), 2u);
  EXPECT_TRUE(runner.your_turns()[1].right);
  EXPECT_EQ(runner.your_turns()[1].feedback, "");
  // Both runs of one your_turn share its one copy of the input.
  EXPECT_EQ(runner.your_turns()[1].exercise_input.mesh, runner.your_turns()[0].exercise_input.mesh);
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  ASSERT_EQ(runner.answered().size(), 1u);
  EXPECT_EQ(runner.answered()[0].given, "your flip_edge");
  // The runs worked on copies: the lesson's grid is not flipped.
  EXPECT_EQ(runner.said(), std::vector<std::string>{"the grid is as it was"});
}

// names = {...}: a wrong verdict ends with the diagram's labels of the ids it mentions, in the order it mentions
// them, and keeps the diagnosis word for word; ids it does not mention, and ids labelled as themselves, are left out.
TEST(LessonYourTurn, DiagramNamesAreListedBesideTheIdsTheVerdictMentions) {
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  // Forgets the faces' halfedges: "f0.halfedge is h0, but h0.face is f1".
  write(dir / "student" / "flip.lua",
        testing::read_text(testing::source_dir() / "tests" / "grading" / "students" / "flip_forgets_faces.lua"));
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  ASSERT_TRUE(runner.load(write(dir / "lesson.lua", R"lua(local grid = meshedit.grid(1, 1)
step("Your turn", function()
  show(grid)
  your_turn { exercise = "flip", mesh = grid, element = "e2",
    names = { x = grid:halfedge(0), g = "f1", f0 = "f0", far = "v3" } }
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.step_state(), State::Waiting) << runner.error();
  auto mine = load_student_file(dir / "student" / "flip.lua");
  const auto grid = std::make_shared<const HalfedgeMesh>(build_halfedge_mesh(make_grid(1, 1)));
  const ExerciseReport report = check_exercise(*mine, Exercise::FlipEdge, ExerciseInput::edge(grid, EdgeId(2)));
  ASSERT_EQ(report.differences.size(), 1u);
  EXPECT_EQ(report.differences[0],
            "after your flip_edge the mesh is not valid (1 problem): f0.halfedge is h0, but "
            "h0.face is f1");
  EXPECT_EQ(runner.waiting_for().feedback,
            report.differences[0] + "\n(the diagram's labels: h0 is labelled x, f1 is labelled g)");

  // A names value that is no element is an error at the lesson's line.
  LessonRunner bad(host);
  bad.set_student_folder(dir / "student");
  ASSERT_TRUE(bad.load(write(dir / "bad.lua", R"lua(step("Your turn", function()
  your_turn { exercise = "flip", mesh = meshedit.grid(1, 1), element = "e2", names = { a = 3 } }
end)
)lua")));
  EXPECT_EQ(bad.error(), "bad.lua:2: your_turn: names.a must be an element (a handle or an id like \"h3\"), got 3");
}

TEST(LessonYourTurn, ARunawayLoopIsStoppedByTheStudentLimitsAndSaidSo) {
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  write(dir / "student" / "flip.lua", "function flip_edge(mesh, e)\n  while true do end\nend\n");
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  LuaLimits limits;
  limits.instructions = 2'000'000;
  runner.set_student_limits(limits);
  ASSERT_TRUE(runner.load(write(dir / "lesson.lua", kLesson))) << runner.error();
  ASSERT_EQ(runner.step_state(), State::Waiting) << runner.error();
  const std::string& feedback = runner.waiting_for().feedback;
  EXPECT_EQ(feedback.rfind("flip.lua:2: instruction budget exceeded", 0), 0u) << feedback;
  EXPECT_NE(feedback.find(unfinished_run_hint(Exercise::FlipEdge)), std::string::npos) << feedback;
}

// In the background (the window's runner): the step waits while the student's code runs; the first update after it
// ended records the verdict and the step goes on from your_turn; stop_student_code ends a runaway at its line, and
// leaving the step stops the run under way.
TEST(LessonYourTurn, InTheBackgroundTheStepWaitsForTheRunAndStopEndsARunaway) {
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  const fs::path file = write(dir / "student" / "flip.lua", testing::read_text(testing::source_dir() / "tests" /
                                                                               "exercise" / "solutions" / "flip.lua"));
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  runner.set_student_code_in_background(true);
  ASSERT_TRUE(runner.load(write(dir / "lesson.lua", kLesson))) << runner.error();
  EXPECT_EQ(runner.step_state(), State::Waiting) << runner.error();
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::YourTurnRunning);
  EXPECT_EQ(runner.waiting_for().describe(), "the student's flip.lua to finish running");
  EXPECT_EQ(runner.waiting_for().where, "lesson.lua:5");
  EXPECT_TRUE(runner.your_turns().empty());
  for (int i = 0; i < 5000 && runner.student_code_running() && runner.your_turns().empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    runner.update(0.001);
  }
  ASSERT_EQ(runner.your_turns().size(), 1u);
  EXPECT_TRUE(runner.your_turns()[0].right);
  EXPECT_FALSE(runner.student_code_running());
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), std::vector<std::string>{"the grid is as it was"});

  save(file, "function flip_edge(mesh, e)\n  while true do end\nend\n");
  runner.restart_step();
  ASSERT_TRUE(runner.student_code_running());
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  runner.update(0.001);
  EXPECT_TRUE(runner.student_code_running());  // still running: the loop has no end
  EXPECT_GT(runner.student_code_seconds(), 0.04);
  runner.stop_student_code();
  for (int i = 0; i < 5000 && runner.student_code_running(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    runner.update(0.001);
  }
  ASSERT_EQ(runner.your_turns().size(), 1u);
  EXPECT_FALSE(runner.your_turns()[0].right);
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::YourTurn);
  EXPECT_EQ(runner.waiting_for().feedback.rfind("flip.lua:2: stopped: you pressed Stop", 0), 0u)
      << runner.waiting_for().feedback;

  runner.restart_step();  // a run again, and leaving the step ends it at once
  ASSERT_TRUE(runner.student_code_running());
  runner.go_to(0);
  EXPECT_TRUE(runner.student_code_running());  // the step's new run
  EXPECT_TRUE(runner.your_turns().empty());
}

TEST(LessonYourTurn, AStudentSyntaxErrorIsItsFileAndLine) {
  const fs::path dir = testing::scratch_dir();
  fs::create_directories(dir / "student");
  write(dir / "student" / "flip.lua", "function flip_edge(mesh, e)\n  return e +\nend\n");
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir / "student");
  ASSERT_TRUE(runner.load(write(dir / "lesson.lua", kLesson))) << runner.error();
  ASSERT_EQ(runner.step_state(), State::Waiting) << runner.error();
  EXPECT_EQ(runner.waiting_for().feedback.rfind("flip.lua:3: ", 0), 0u) << runner.waiting_for().feedback;
}

TEST(LessonYourTurn, BadArgumentsFailTheStepAtTheLessonsLine) {
  const fs::path dir = testing::scratch_dir();
  HeadlessHost host;
  LessonRunner runner(host);
  runner.set_student_folder(dir);
  const auto fails_with = [&](const std::string& call, const std::string& message) {
    ASSERT_TRUE(runner.load(
        write(dir / "lesson.lua", "local m = meshedit.grid(1, 1)\nstep('S', function()\n  " + call + "\nend)\n")))
        << runner.error();
    EXPECT_EQ(runner.step_state(), State::Failed) << call;
    EXPECT_EQ(runner.error(), message);
  };
  fails_with("your_turn { exercise = 'flop', mesh = m, element = 'e2' }",
             "lesson.lua:3: your_turn: no exercise is called 'flop'; the exercises are curve, patch, normals, flip, "
             "split, upsample");
  fails_with("your_turn { exercise = 'flip', mesh = m, element = 'v2' }",
             "lesson.lua:3: your_turn: element must be an edge of the mesh (a handle or an id like \"e0\"), got v2");
  fails_with("your_turn { exercise = 'flip', element = 'e2' }",
             "lesson.lua:3: your_turn: the flip exercise needs mesh = a mesh, got nil");
  fails_with("your_turn { exercise = 'flip', mesh = m, edge = 'e2' }",
             "lesson.lua:3: your_turn: unknown field 'edge' (fields: exercise, mesh, element, points, t, patch, u, v, "
             "control, args, hint, names)");
  runner.set_student_folder({});
  fails_with("your_turn { exercise = 'upsample', mesh = m }",
             "lesson.lua:3: your_turn: no student folder (meshedit lesson FILE --headless --student DIR)");
}

}  // namespace
}  // namespace meshedit
